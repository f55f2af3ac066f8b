#include "core/device/page/page_layout.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/device/page/atomic_file.hpp"
#include "core/format_number.hpp"

namespace hlr {
namespace {

struct NamedPaper {
  std::string_view name;
  double short_mm, long_mm;
};

// ISO 216 A series; US sizes from their inch dimensions (8.5×11, 8.5×14, 11×17 in, exactly 25.4 mm/in).
constexpr std::array<NamedPaper, 10> kPapers{{
    {"A0", 841, 1189},
    {"A1", 594, 841},
    {"A2", 420, 594},
    {"A3", 297, 420},
    {"A4", 210, 297},
    {"A5", 148, 210},
    {"A6", 105, 148},
    {"Letter", 215.9, 279.4},
    {"Legal", 215.9, 355.6},
    {"Tabloid", 279.4, 431.8},
}};

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  // ASCII only: paper names are ASCII, and std::tolower's locale dependence would make matching vary.
  const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [&](char x, char y) { return lower(x) == lower(y); });
}

bool finite(Point2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// digits [ "." digits ] at the front of `text`, consumed. Too many digits for a double reads as infinity,
// so check_page_spec() reports the size rather than the spelling.
std::optional<double> take_decimal(std::string_view& text) {
  std::size_t end = 0;
  while (end < text.size() && is_digit(text[end])) ++end;
  if (end == 0) return std::nullopt;
  if (end < text.size() && text[end] == '.') {
    std::size_t frac = end + 1;
    while (frac < text.size() && is_digit(text[frac])) ++frac;
    if (frac == end + 1) return std::nullopt;
    end = frac;
  }
  double value = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + end, value, std::chars_format::fixed);
  if (ec == std::errc::result_out_of_range)
    value = std::numeric_limits<double>::infinity();
  else if (ec != std::errc{} || ptr != text.data() + end)
    return std::nullopt;
  text.remove_prefix(end);
  return value;
}

std::string mm(double v) { return format_for_message(v); }

}  // namespace

std::optional<Paper> paper_by_name(std::string_view name, bool landscape) {
  for (const NamedPaper& p : kPapers) {
    if (!equal_ignoring_case(name, p.name)) continue;
    return landscape ? Paper{p.long_mm, p.short_mm} : Paper{p.short_mm, p.long_mm};
  }
  return std::nullopt;
}

std::optional<Paper> parse_paper(std::string_view text, bool landscape) {
  if (auto named = paper_by_name(text, landscape)) return named;
  const std::optional<double> w = take_decimal(text);
  if (!w || text.empty() || (text.front() != 'x' && text.front() != 'X')) return std::nullopt;
  text.remove_prefix(1);
  const std::optional<double> h = take_decimal(text);
  if (!h || !(text.empty() || equal_ignoring_case(text, "mm"))) return std::nullopt;
  Paper p{*w, *h};
  if (landscape ? p.width_mm < p.height_mm : p.width_mm > p.height_mm) std::swap(p.width_mm, p.height_mm);
  return p;
}

const std::vector<std::string_view>& paper_names() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> v;
    for (const NamedPaper& p : kPapers) v.push_back(p.name);
    return v;
  }();
  return names;
}

std::optional<PageFit> page_fit_by_name(std::string_view name) {
  if (name == "camera") return PageFit::Camera;
  if (name == "drawing") return PageFit::Drawing;
  return std::nullopt;
}

Rect2 camera_window(double half_extent, const PageSpec& spec) {
  check_page_spec(spec);
  const double room_w = spec.paper.width_mm - 2 * spec.margin_mm;
  const double room_h = spec.paper.height_mm - 2 * spec.margin_mm;
  double half_w = 0, half_h = 0;
  if (spec.mm_per_unit) {
    half_w = 0.5 * room_w / *spec.mm_per_unit;
    half_h = 0.5 * room_h / *spec.mm_per_unit;
  } else {
    const double shorter = std::min(room_w, room_h);
    half_w = half_extent * room_w / shorter;
    half_h = half_extent * room_h / shorter;
  }
  return Rect2{-half_w, -half_h, half_w, half_h};
}

std::optional<Rect2> picture_frame(const Camera& camera, const PageSpec& spec) {
  if (camera.frame) return camera.frame;
  if (spec.fit == PageFit::Drawing) return std::nullopt;
  return camera_window(camera.window_half, spec);
}

Camera framed_camera(Camera camera, const PageSpec& spec) {
  camera.frame = picture_frame(camera, spec);
  return camera;
}

Rect2 drawing_extent(const std::optional<Rect2>& frame, const std::vector<VisibleSegment>& segments) {
  if (frame) return *frame;
  Rect2 r = Rect2::none();
  for (const VisibleSegment& s : segments) {
    // The engine drops non-finite pieces; skipping them here keeps one bad point from shrinking the rest.
    if (finite(s.s0)) r.include(s.s0);
    if (finite(s.s1)) r.include(s.s1);
  }
  return r;
}

void check_page_spec(const PageSpec& spec) {
  const double w = spec.paper.width_mm, h = spec.paper.height_mm, m = spec.margin_mm;
  if (!(std::isfinite(w) && std::isfinite(h) && w > 0 && h > 0))
    throw DeviceError("paper size must be finite and positive, got " + mm(w) + " x " + mm(h) + " mm");
  if (w > kMaxPaperSideMm || h > kMaxPaperSideMm)
    throw DeviceError("paper size " + mm(w) + " x " + mm(h) + " mm is too large: each side must be at most " +
                      mm(kMaxPaperSideMm) + " mm (10 m)");
  if (!(std::isfinite(m) && m >= 0 && w - 2 * m > 0 && h - 2 * m > 0))
    throw DeviceError("margin of " + mm(m) + " mm leaves no room on a " + mm(w) + " x " + mm(h) +
                      " mm page; use a margin from 0 to under half the shorter side");
  if (spec.mm_per_unit && !(std::isfinite(*spec.mm_per_unit) && *spec.mm_per_unit > 0))
    throw DeviceError("the drawing scale must be finite and positive, got " + mm(*spec.mm_per_unit) +
                      " mm per unit");
}

PageLayout fit_rect_to_page(const Rect2& extent, const PageSpec& spec) {
  check_page_spec(spec);
  const double w = spec.paper.width_mm, h = spec.paper.height_mm;
  const double room_w = w - 2 * spec.margin_mm, room_h = h - 2 * spec.margin_mm;

  PageLayout layout;
  layout.page_width_mm = w;
  layout.page_height_mm = h;
  if (spec.mm_per_unit) layout.scale = *spec.mm_per_unit;
  if (extent.empty() || !std::isfinite(extent.xmin) || !std::isfinite(extent.xmax) ||
      !std::isfinite(extent.ymin) || !std::isfinite(extent.ymax))
    return layout;  // nothing to fit: the picture origin at the centre, scale 1 unless given
  layout.picture_centre = {0.5 * extent.xmin + 0.5 * extent.xmax, 0.5 * extent.ymin + 0.5 * extent.ymax};
  if (spec.mm_per_unit) return layout;

  // A zero side puts no limit on the scale; a single point has no size to fit and keeps scale 1.
  constexpr double kUnlimited = std::numeric_limits<double>::infinity();
  const double ew = extent.width(), eh = extent.height();
  const double sx = ew > 0 ? room_w / ew : kUnlimited, sy = eh > 0 ? room_h / eh : kUnlimited;
  const double scale = std::min(sx, sy);
  layout.scale = scale < kUnlimited ? scale : 1;
  return layout;
}

}  // namespace hlr
