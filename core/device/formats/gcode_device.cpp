#include "core/device/formats/gcode_device.hpp"

#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "core/device/page/atomic_file.hpp"
#include "core/format_number.hpp"
#include "core/geometry/clip2d.hpp"
#include "core/tolerance.hpp"

namespace hlr {
namespace {

std::string mm(double v) { return format_mm_for_message(v); }

// A coordinate: three decimals, and 0.000 for anything that rounds to zero (GRBL reads -0.000 fine, but
// a file that differs by a sign nobody can see is harder to compare).
// std::to_chars rounds as printf's "%.3f" does, a tenth of the time.
std::string fixed3(double v) {
  char buf[48];
  const auto [end, error] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 3);
  std::string s = error == std::errc() ? std::string(buf, end) : std::string("nan");
  if (s == "-0.000") s = "0.000";
  return s;
}

// A setting (S, Z, F, P): up to three decimals, trailing zeros dropped ("30", "0.15").
std::string value(double v) {
  std::string s = fixed3(v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

// Comment text: GRBL ends a comment at the first ')' and has no nesting; senders expect ASCII lines.
std::string comment(std::string_view text) {
  std::string s = "(";
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    s += c == '(' ? '[' : c == ')' ? ']' : (u < 0x20 || u >= 0x7f) ? '?' : c;
  }
  return s + ")\n";
}

// The page on the machine: page mm ↔ machine mm.
struct Placement {
  double page_w = 0, page_h = 0;
  bool y_up = true;
  Point2 to_machine(Point2 p) const { return {p.x, y_up ? page_h - p.y : p.y}; }
  Point2 to_page(Point2 m) const { return {m.x, y_up ? page_h - m.y : m.y}; }
};

Placement place(const GcodeProfile& profile, double w, double h) {
  check_gcode_profile(profile);
  if (!(std::isfinite(w) && std::isfinite(h) && w > 0 && h > 0))
    throw DeviceError("G-code: the page size must be positive, not " + mm(w) + " × " + mm(h) + " mm");
  constexpr double kSlack = Tolerance::kWorkAreaSlackMm;
  const double aw = profile.width_mm, ah = profile.height_mm;
  if (w > aw + kSlack || h > ah + kSlack) {
    std::string message = "G-code: the page is " + mm(w) + " × " + mm(h) + " mm but plotter '" +
                          profile.name + "' draws within a " + mm(aw) + " × " + mm(ah) + " mm work area";
    if (h <= aw + kSlack && w <= ah + kSlack)
      message += "; the page fits turned: use --" + std::string(w > h ? "portrait" : "landscape") +
                 " (or 'paper ... " + (w > h ? "portrait" : "landscape") + "')";
    else
      message += "; use a smaller paper (--paper), or declare the plotter's area (width:, height:)";
    throw DeviceError(message);
  }
  return {w, h, profile.origin == GcodeOrigin::BottomLeft};
}

std::string duration(double s) {
  const long total = std::lround(s);
  if (total < 60) return value(std::round(s * 10) / 10) + " s";
  const long h = total / 3600, m = total / 60 % 60, sec = total % 60;
  return (h ? std::to_string(h) + " h " : "") + std::to_string(m) + " min " + std::to_string(sec) + " s";
}

// Writes the program's body and keeps what the time estimate needs.
class Program {
 public:
  explicit Program(const GcodeProfile& p) : p_(p) {}

  void pen_up() {
    if (p_.pen_mode == GcodePenMode::Servo)
      line("M3 S" + value(p_.pen_up));
    else
      line("G0 Z" + value(p_.pen_up));
    dwell(p_.pen_up_dwell_s);
  }
  void pen_down() {
    if (p_.pen_mode == GcodePenMode::Servo)
      line("M3 S" + value(p_.pen_down));
    else
      line("G1 Z" + value(p_.pen_down) + " F" + value(p_.z_feed_mm_min));
    dwell(p_.pen_down_dwell_s);
  }
  void change_pen(int pen) {
    out_ += comment("change to pen " + std::to_string(pen) + ", then resume");
    line("M0");
    ++changes_;
  }
  // One piece of a stroke, in machine mm, already as it is printed.
  void stroke(const std::vector<Point2>& pts) {
    travel_mm_ += std::hypot(pts.front().x - at_.x, pts.front().y - at_.y);
    line("G0 X" + fixed3(pts.front().x) + " Y" + fixed3(pts.front().y));
    pen_down();
    for (std::size_t i = 1; i < pts.size(); ++i) {
      draw_mm_ += std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
      line("G1 X" + fixed3(pts[i].x) + " Y" + fixed3(pts[i].y) +
           (i == 1 ? " F" + value(p_.draw_feed_mm_min) : ""));
    }
    pen_up();
    at_ = pts.back();
    ++lifts_;
  }
  void finish() {
    travel_mm_ += std::hypot(at_.x, at_.y);
    line("G0 X0.000 Y0.000");
    // M2 also stops the spindle (GRBL's M5): a servo build's PWM drops to S0, which lifts the pen further
    // when up is below down, and would drop it otherwise; then the program just ends.
    if (p_.pen_mode == GcodePenMode::Servo && p_.pen_up > p_.pen_down)
      line("(end; no M2, which would turn the servo to S0 and lower the pen)");
    else
      line("M2");
  }

  const std::string& text() const { return out_; }
  double draw_mm() const { return draw_mm_; }
  double travel_mm() const { return travel_mm_; }
  int lifts() const { return lifts_; }
  int changes() const { return changes_; }

 private:
  void line(const std::string& text) {
    out_ += text;
    out_ += '\n';
  }
  void dwell(double s) {
    if (s > 0) line("G4 P" + value(s));
  }

  const GcodeProfile& p_;
  std::string out_;
  Point2 at_{0, 0};
  double draw_mm_ = 0, travel_mm_ = 0;
  int lifts_ = 0, changes_ = 0;
};

// The point as it will be printed, read back: what the machine moves to.
Point2 printed(Point2 m) { return {std::stod(fixed3(m.x)), std::stod(fixed3(m.y))}; }

}  // namespace

std::string to_gcode(const PlotPage& page, const GcodeProfile& profile, const GcodeOptions& options) {
  const Placement pl = place(profile, page.width_mm, page.height_mm);
  const Rect2 box{0, 0, pl.page_w, pl.page_h};  // machine mm: the page
  constexpr double kReachSlack = Tolerance::kPrintedReachMm;

  Program body(profile);
  body.pen_up();
  int pen = 1;  // the program starts with pen 1 in the holder
  for (std::size_t i = 0; i < page.strokes.size(); ++i) {
    const PlotStroke& stroke = page.strokes[i];
    const std::string which = "G-code: stroke " + std::to_string(i + 1);
    if (stroke.pen < 1 || stroke.pen > profile.pen_count)
      throw DeviceError(which + " uses pen " + std::to_string(stroke.pen) + " but plotter '" + profile.name +
                        "' has pens 1–" + std::to_string(profile.pen_count) +
                        "; assign the drawing's pens (and the hidden layer's) within that range, or "
                        "declare more with pens:");
    std::vector<Point2> m;
    m.reserve(stroke.points.size());
    for (const Point2& p : stroke.points) {
      if (!(std::isfinite(p.x) && std::isfinite(p.y)))
        throw DeviceError(which + " has a point that is not finite");
      m.push_back(pl.to_machine(p));
    }
    std::vector<std::vector<Point2>> pieces;
    if (options.clip) {
      clip_polyline_to_rect(
          m, box, [&](Point2 q) { pieces.push_back({q}); }, [&](Point2 q) { pieces.back().push_back(q); });
    } else {
      for (std::size_t k = 0; k < m.size(); ++k) {
        const Point2 q = m[k];
        if (q.x >= -kReachSlack && q.x <= box.xmax + kReachSlack && q.y >= -kReachSlack &&
            q.y <= box.ymax + kReachSlack)
          continue;
        throw DeviceError(which + " reaches (" + mm(stroke.points[k].x) + ", " + mm(stroke.points[k].y) +
                          ") mm on the page, off the " + mm(pl.page_w) + " × " + mm(pl.page_h) +
                          " mm page plotter '" + profile.name +
                          "' draws on. Fit the drawing to the page (no fixed scale), use a smaller "
                          "scale or a bigger paper, or cut it with --clip");
      }
      pieces.push_back(std::move(m));
    }
    for (const std::vector<Point2>& piece : pieces) {
      std::vector<Point2> pts;
      for (const Point2& q : piece) {
        const Point2 s = printed(q);
        if (pts.empty() || !(pts.back().x == s.x && pts.back().y == s.y)) pts.push_back(s);
      }
      if (pts.empty()) continue;
      if (stroke.pen != pen) {
        body.change_pen(stroke.pen);
        pen = stroke.pen;
      }
      body.stroke(pts);
    }
  }
  body.finish();

  const PlotterSpeeds speeds = gcode_speeds(profile);
  const double seconds = body.draw_mm() / speeds.pen_down_mm_per_s +
                         body.travel_mm() / speeds.pen_up_mm_per_s + body.lifts() * speeds.lift_s +
                         profile.pen_up_dwell_s;
  std::string out;
  out += comment("hlrscript G-code for plotter '" + profile.name + "': " + profile.info);
  out += comment("page " + mm(pl.page_w) + " x " + mm(pl.page_h) + " mm, its corner at the work area's " +
                 gcode_origin_name(profile.origin) + " origin; machine y " + (pl.y_up ? "up" : "down") +
                 "; units mm");
  out += comment("start with pen 1 in the holder; pen changes, each an M0 pause: " +
                 std::to_string(body.changes()));
  out += comment("estimated plotting time " + duration(seconds) + ": drawing " + mm(body.draw_mm()) +
                 " mm at " + value(profile.draw_feed_mm_min) + " mm/min, travel " + mm(body.travel_mm()) +
                 " mm at " + value(profile.travel_feed_mm_min) + " mm/min, pen lifts " +
                 std::to_string(body.lifts()) + (body.changes() ? ", pen changes not counted" : ""));
  out += "G21\nG90\n";
  out += body.text();
  return out;
}

Point2 gcode_home_on_page(const GcodeProfile& profile, double page_width_mm, double page_height_mm) {
  return place(profile, page_width_mm, page_height_mm).to_page({0, 0});
}

}  // namespace hlr
