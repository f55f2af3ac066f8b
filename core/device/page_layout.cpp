#include "core/device/page_layout.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "core/device/atomic_file.hpp"

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

}  // namespace

std::optional<Paper> paper_by_name(std::string_view name, bool landscape) {
  for (const NamedPaper& p : kPapers) {
    if (!equal_ignoring_case(name, p.name)) continue;
    return landscape ? Paper{p.long_mm, p.short_mm} : Paper{p.short_mm, p.long_mm};
  }
  return std::nullopt;
}

const std::vector<std::string_view>& paper_names() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> v;
    for (const NamedPaper& p : kPapers) v.push_back(p.name);
    return v;
  }();
  return names;
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
    throw DeviceError("paper size must be finite and positive, got " + std::to_string(w) + " x " +
                      std::to_string(h) + " mm");
  if (!(std::isfinite(m) && m >= 0 && w - 2 * m > 0 && h - 2 * m > 0))
    throw DeviceError("margin of " + std::to_string(m) + " mm leaves no room on a " + std::to_string(w) +
                      " x " + std::to_string(h) +
                      " mm page; use a margin from 0 to under half the shorter side");
}

PageLayout fit_rect_to_page(const Rect2& extent, const PageSpec& spec) {
  check_page_spec(spec);
  const double w = spec.paper.width_mm, h = spec.paper.height_mm;
  const double room_w = w - 2 * spec.margin_mm, room_h = h - 2 * spec.margin_mm;

  PageLayout layout;
  layout.page_width_mm = w;
  layout.page_height_mm = h;
  if (extent.empty() || !std::isfinite(extent.xmin) || !std::isfinite(extent.xmax) ||
      !std::isfinite(extent.ymin) || !std::isfinite(extent.ymax))
    return layout;  // nothing to fit: scale 1 about the picture origin

  // A zero side puts no limit on the scale; a single point has no size to fit and keeps scale 1.
  constexpr double kUnlimited = std::numeric_limits<double>::infinity();
  const double ew = extent.width(), eh = extent.height();
  const double sx = ew > 0 ? room_w / ew : kUnlimited, sy = eh > 0 ? room_h / eh : kUnlimited;
  const double scale = std::min(sx, sy);
  layout.scale = scale < kUnlimited ? scale : 1;
  layout.picture_centre = {0.5 * extent.xmin + 0.5 * extent.xmax, 0.5 * extent.ymin + 0.5 * extent.ymax};
  return layout;
}

}  // namespace hlr
