#include "core/device/formats/hpgl_device.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "core/device/page/atomic_file.hpp"
#include "core/format_number.hpp"
#include "core/geometry/clip2d.hpp"
#include "core/limits.hpp"
#include "core/tolerance.hpp"

namespace hlr {
namespace {

struct IPoint {
  long x = 0, y = 0;
  bool operator==(const IPoint&) const = default;
};

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [&](char x, char y) { return lower(x) == lower(y); });
}

std::string mm(double v) { return format_mm_for_message(v); }

// The page on one of the profile's sheets: page mm ↔ plotter units, and the integer area the pen reaches.
struct Placement {
  const HpglPaperRange* range = nullptr;
  std::string paper;  // for messages
  double page_w = 0, page_h = 0;
  double sheet_w = 0, sheet_h = 0;  // along plotter x and y
  bool rotate90 = false, rotate180 = false, y_up = true;
  double unit = 0.025, ox = 0, oy = 0;
  long ax_min = 0, ax_max = 0, ay_min = 0, ay_max = 0;  // reachable, on the sheet

  Point2 to_plotter(Point2 p) const {
    double qx = rotate90 ? p.y : p.x;  // page → sheet as seen (y down)
    double qy = rotate90 ? page_w - p.x : p.y;
    if (rotate180) {
      qx = sheet_w - qx;
      qy = sheet_h - qy;
    }
    const double sy = y_up ? sheet_h - qy : qy;  // sheet coordinates along the plotter's axes
    return {(qx - ox) / unit, (sy - oy) / unit};
  }
  Point2 to_page(Point2 u) const {
    double qx = u.x * unit + ox;
    const double sy = u.y * unit + oy;
    double qy = y_up ? sheet_h - sy : sy;
    if (rotate180) {
      qx = sheet_w - qx;
      qy = sheet_h - qy;
    }
    return rotate90 ? Point2{page_w - qy, qx} : Point2{qx, qy};
  }
  // The reachable area in page mm.
  Rect2 page_area() const {
    Rect2 r = Rect2::none();
    r.include(to_page({static_cast<double>(ax_min), static_cast<double>(ay_min)}));
    r.include(to_page({static_cast<double>(ax_max), static_cast<double>(ay_max)}));
    return r;
  }
  double min_margin() const {
    const Rect2 a = page_area();
    return std::max({0.0, a.xmin, page_w - a.xmax, a.ymin, page_h - a.ymax});
  }
};

bool same_size(double w, double h, double sw, double sh) {
  return std::fabs(w - sw) <= Tolerance::kPaperMatchMm && std::fabs(h - sh) <= Tolerance::kPaperMatchMm;
}

Placement place(const HpglProfile& profile, double page_w, double page_h, std::string_view paper) {
  check_hpgl_profile(profile);
  if (!(std::isfinite(page_w) && std::isfinite(page_h) && page_w > 0 && page_h > 0))
    throw DeviceError("HPGL: the page size must be positive, not " + mm(page_w) + " × " + mm(page_h) + " mm");
  const std::string who = "plotter '" + profile.name + "'";
  const std::string page_size = mm(page_w) + " × " + mm(page_h) + " mm";

  Placement pl;
  pl.page_w = page_w;
  pl.page_h = page_h;
  const auto accept = [&](const HpglPaperRange& r) {
    if (r.any_size()) return true;
    if (same_size(page_w, page_h, r.width_mm, r.height_mm)) return true;
    pl.rotate90 = same_size(page_h, page_w, r.width_mm, r.height_mm);  // the page turned onto the sheet
    return pl.rotate90;
  };
  bool named = false;                               // some range carries the requested paper name
  for (const HpglPaperRange& r : profile.ranges) {  // sized ranges first, then any-size ones
    if (r.any_size() || (!paper.empty() && !equal_ignoring_case(r.paper, paper))) continue;
    named = true;
    if (accept(r)) {
      pl.range = &r;
      break;
    }
  }
  for (const HpglPaperRange& r : profile.ranges) {
    if (pl.range) break;
    if (r.any_size()) pl.range = &r;
  }
  if (!pl.range && !paper.empty() && !named)
    throw DeviceError("HPGL: " + who + " has no paper '" + std::string(paper) + "'; it takes " +
                      hpgl_paper_list(profile));
  if (!pl.range && !paper.empty()) {
    HpglProfile same_name;
    for (const HpglPaperRange& r : profile.ranges)
      if (equal_ignoring_case(r.paper, paper)) same_name.ranges.push_back(r);
    throw DeviceError("HPGL: the page is " + page_size + " but " + who + " takes " +
                      hpgl_paper_list(same_name) + " (either orientation) as '" + std::string(paper) + "'");
  }
  if (!pl.range)
    throw DeviceError("HPGL: " + who + " takes no " + page_size + " page; its paper sizes are " +
                      hpgl_paper_list(profile) + " (either orientation)");

  const HpglPaperRange& r = *pl.range;
  pl.paper = r.any_size() ? page_size : r.paper;
  pl.sheet_w = r.any_size() ? page_w : (pl.rotate90 ? page_h : page_w);
  pl.sheet_h = r.any_size() ? page_h : (pl.rotate90 ? page_w : page_h);
  pl.rotate180 = profile.rotate_180;
  pl.y_up = profile.y_axis_up;
  pl.unit = profile.unit_mm;
  pl.ox = r.origin_x_mm;
  pl.oy = r.origin_y_mm;
  // The limits, and never off the sheet (clamped before the cast: the limits lie within ±32768 anyway).
  const double eps = Tolerance::kPlotterUnitSnap;
  const auto whole = [](double v) { return static_cast<long>(std::clamp(v, -1e9, 1e9)); };
  pl.ax_min = std::max(r.x_min, whole(std::ceil(-pl.ox / pl.unit - eps)));
  pl.ax_max = std::min(r.x_max, whole(std::floor((pl.sheet_w - pl.ox) / pl.unit + eps)));
  pl.ay_min = std::max(r.y_min, whole(std::ceil(-pl.oy / pl.unit - eps)));
  pl.ay_max = std::min(r.y_max, whole(std::floor((pl.sheet_h - pl.oy) / pl.unit + eps)));
  if (pl.ax_min > pl.ax_max || pl.ay_min > pl.ay_max)
    throw DeviceError("HPGL: " + who + "'s " + pl.paper + " range lies off the sheet");
  return pl;
}

// The pieces of a polyline (plotter units) inside the box (core/geometry/clip2d.hpp).
std::vector<std::vector<Point2>> clip_polyline(const std::vector<Point2>& u, const Rect2& box) {
  std::vector<std::vector<Point2>> out;
  clip_polyline_to_rect(
      u, box, [&](Point2 p) { out.push_back({p}); }, [&](Point2 p) { out.back().push_back(p); });
  return out;
}

// Writes commands, keeping the pen position and PA/PR mode.
class Emitter {
 public:
  Emitter(bool relative, int max_pairs, bool newline)
      : relative_(relative), max_pairs_(max_pairs), nl_(newline) {}

  void command(std::string_view text) {
    out_ += text;
    out_ += ';';
    if (nl_) out_ += '\n';
  }
  void select_pen(int pen) {
    command("PU");
    command("SP" + std::to_string(pen));
  }
  void travel(IPoint to) {
    if (!known_) {  // IN leaves the plotter in PA: the first move is absolute
      pairs("PU", {to});
      known_ = true;
      at_ = to;
      if (relative_) {
        command("PR");
        in_pr_ = true;
      }
      return;
    }
    if (relative_ && to == at_) {
      command("PU");
      return;
    }
    pairs("PU", steps(to));
  }
  void draw(const std::vector<IPoint>& pts) {  // pts.front() is the current position
    if (pts.size() == 1) {  // a dot: the pen lowered where it is (hp2xx draws no zero-length move)
      command("PD");
      return;
    }
    std::vector<IPoint> all;
    for (std::size_t i = 1; i < pts.size(); ++i) {
      const std::vector<IPoint> s = steps(pts[i]);
      all.insert(all.end(), s.begin(), s.end());
    }
    pairs("PD", all);
  }
  std::string finish() {
    command("PU");
    if (in_pr_) command("PA");
    command("SP0");
    if (!nl_) out_ += '\n';
    return std::move(out_);
  }

 private:
  // The pairs that move the pen from at_ to `to` (relative: differences, split to stay within ±kHpglMaxStep).
  std::vector<IPoint> steps(IPoint to) {
    if (!relative_) {
      at_ = to;
      return {to};
    }
    const long dx = to.x - at_.x, dy = to.y - at_.y;
    const long n = std::max(1L, (std::max(std::labs(dx), std::labs(dy)) + kHpglMaxStep - 1) / kHpglMaxStep);
    std::vector<IPoint> out;
    IPoint prev = at_;
    for (long k = 1; k <= n; ++k) {
      const IPoint p{at_.x + std::lround(static_cast<double>(dx) * k / n),
                     at_.y + std::lround(static_cast<double>(dy) * k / n)};
      out.push_back({p.x - prev.x, p.y - prev.y});
      prev = p;
    }
    at_ = to;
    return out;
  }
  void pairs(std::string_view mnemonic, const std::vector<IPoint>& list) {
    for (std::size_t i = 0; i < list.size(); i += static_cast<std::size_t>(max_pairs_)) {
      std::string c(mnemonic);
      const std::size_t end = std::min(list.size(), i + static_cast<std::size_t>(max_pairs_));
      for (std::size_t j = i; j < end; ++j) {
        if (j > i) c += ',';
        c += std::to_string(list[j].x);
        c += ',';
        c += std::to_string(list[j].y);
      }
      command(c);
    }
  }

  bool relative_;
  int max_pairs_;
  bool nl_;
  std::string out_;
  bool known_ = false, in_pr_ = false;
  IPoint at_;
};

std::string velocity_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

}  // namespace

std::string to_hpgl(const PlotPage& page, const HpglProfile& profile, const HpglOptions& options) {
  const Placement pl = place(profile, page.width_mm, page.height_mm, options.paper);
  const bool relative = options.relative.value_or(profile.relative);
  const int max_pairs = options.max_pairs_per_pd.value_or(profile.max_pairs_per_pd);
  if (max_pairs < 1) throw DeviceError("HPGL: at least one coordinate pair per PD is needed");
  std::optional<double> velocity = profile.velocity_cm_s;
  if (options.velocity_cm_s) {
    const double v = *options.velocity_cm_s;
    if (!(v == 0 || (v >= kMinVelocityCmS && v <= kMaxVelocityCmS)))
      throw DeviceError("HPGL: the velocity must be " + format_for_message(kMinVelocityCmS) + "…" +
                        format_for_message(kMaxVelocityCmS) + " cm/s, or 0 for the plotter's own");
    velocity = v > 0 ? options.velocity_cm_s : std::nullopt;
  }

  Emitter out(relative, max_pairs, options.newline.value_or(profile.newline));
  out.command("IN");
  if (velocity) out.command("VS" + velocity_text(*velocity));

  const Rect2 box{static_cast<double>(pl.ax_min), static_cast<double>(pl.ay_min),
                  static_cast<double>(pl.ax_max), static_cast<double>(pl.ay_max)};
  int pen = 0;
  for (std::size_t i = 0; i < page.strokes.size(); ++i) {
    const PlotStroke& stroke = page.strokes[i];
    const std::string which = "HPGL: stroke " + std::to_string(i + 1);
    if (stroke.pen < 1 || stroke.pen > profile.pen_count)
      throw DeviceError(which + " uses pen " + std::to_string(stroke.pen) + " but plotter '" + profile.name +
                        "' has pens 1–" + std::to_string(profile.pen_count) +
                        "; assign the drawing's pens (and the hidden layer's) within that range");
    std::vector<Point2> u;
    u.reserve(stroke.points.size());
    for (const Point2& p : stroke.points) {
      if (!(std::isfinite(p.x) && std::isfinite(p.y)))
        throw DeviceError(which + " has a point that is not finite");
      u.push_back(pl.to_plotter(p));
    }
    std::vector<std::vector<Point2>> pieces;
    if (options.clip) {
      pieces = clip_polyline(u, box);
    } else {
      for (std::size_t k = 0; k < u.size(); ++k) {
        const double sx = std::floor(u[k].x + 0.5), sy = std::floor(u[k].y + 0.5);
        if (sx >= box.xmin && sx <= box.xmax && sy >= box.ymin && sy <= box.ymax) continue;
        const Rect2 a = pl.page_area();
        const std::string point = "(" + mm(stroke.points[k].x) + ", " + mm(stroke.points[k].y) + ") mm";
        const std::string area = "x " + mm(a.xmin) + "–" + mm(a.xmax) + " mm, y " + mm(a.ymin) + "–" +
                                 mm(a.ymax) + " mm from the page's top-left corner";
        const std::string margin = mm(std::ceil(pl.min_margin() * 10) / 10);
        throw DeviceError(which + " reaches " + point + " on the page, outside what plotter '" +
                          profile.name + "' can draw on " + pl.paper + " paper: " + area +
                          ". Fit the drawing to the page (no fixed scale) with a margin of at least " +
                          margin + " mm, use a smaller scale or a bigger paper, or cut it with --clip");
      }
      pieces.push_back(std::move(u));
    }
    for (const std::vector<Point2>& piece : pieces) {
      std::vector<IPoint> snapped;
      for (const Point2& q : piece) {
        const IPoint s{static_cast<long>(std::floor(q.x + 0.5)), static_cast<long>(std::floor(q.y + 0.5))};
        if (snapped.empty() || !(snapped.back() == s)) snapped.push_back(s);
      }
      if (snapped.empty()) continue;
      if (stroke.pen != pen) {
        out.select_pen(stroke.pen);
        pen = stroke.pen;
      }
      out.travel(snapped.front());
      out.draw(snapped);
    }
  }
  return out.finish();
}

void write_hpgl(const std::filesystem::path& target, const PlotPage& page, const HpglProfile& profile,
                const HpglOptions& options) {
  const std::string text = to_hpgl(page, profile, options);  // every check before the file exists
  write_atomically(target, [&](const std::filesystem::path& temp) {
    std::ofstream out(temp, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw DeviceError("write failed");
  });
}

double hpgl_min_margin_mm(const HpglProfile& profile, double page_width_mm, double page_height_mm,
                          std::string_view paper) {
  return place(profile, page_width_mm, page_height_mm, paper).min_margin();
}

Point2 hpgl_home_on_page(const HpglProfile& profile, double page_width_mm, double page_height_mm,
                         std::string_view paper) {
  return place(profile, page_width_mm, page_height_mm, paper).to_page({0, 0});
}

}  // namespace hlr
