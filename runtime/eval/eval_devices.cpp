// Device settings: paper (with its options), pens, plotter profiles, and the pen numbers of `draw ... pen
// N` and `style hidden dashed pen N`. Option lists — `(margin: 10)`, `(colour: "red")`, a plotter's `{
// unit: 0.025 }` — are checked in the manner of a solid's options: a missing name, an unknown name, a
// name given twice, a value of the wrong kind or out of range is an error at that option, with the list
// of options as the hint.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <string_view>
#include <vector>

#include "core/device/page/atomic_file.hpp"
#include "core/device/page/pen_style.hpp"
#include "core/device/page/stroke_glyphs.hpp"
#include "core/device/plotters/gcode_profile.hpp"
#include "core/device/plotters/hpgl_profile.hpp"
#include "core/format_number.hpp"
#include "core/limits.hpp"
#include "runtime/eval/eval_detail.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/eval/option_list.hpp"
#include "runtime/values/format_value.hpp"

namespace hlr::runtime {

namespace {

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

// ---- paper ------------------------------------------------------------------------------------------

std::string paper_hint() {
  return "the paper options are margin: millimetres from 0, leaving room on the page, scale: "
         "millimetres per drawing unit above 0 (instead of the camera's field of view), and fit: \"camera\" "
         "(the default: the camera's view fills the page) or \"drawing\" (what is drawn fills it), and "
         "title: the text of a sheet's title block (a script with views); 'paper custom' also takes width: "
         "and height: in millimetres, up to " +
         format_for_message(kMaxPaperSideMm);
}

std::string paper_list() {
  std::string out;
  for (const std::string_view name : paper_names()) out += (out.empty() ? "" : ", ") + std::string(name);
  return out;
}

// ---- pens -------------------------------------------------------------------------------------------

std::string pen_numbers() { return "a whole number from 1 to " + std::to_string(kMaxPen); }
std::string pen_widths() { return "above 0 and at most " + format_for_message(kMaxPenWidthMm) + " mm"; }
std::string pen_hint() {
  return "the pen options are colour: (or color:) \"#rrggbb\", \"#rgb\" or one of black, red, green, blue, "
         "cyan, magenta, yellow, orange, grey, gray, white, brown, purple; width: millimetres above 0 and at "
         "most " +
         format_for_message(kMaxPenWidthMm);
}

// ---- plotters ---------------------------------------------------------------------------------------

std::string plotter_hint() {
  return "the keys are base: a built-in profile to start from (" + hpgl_profile_list() +
         "; default generic), unit: millimetres per plotter unit (" + format_for_message(kMinPlotterUnitMm) +
         " to " + format_for_message(kMaxPlotterUnitMm) + "), pens: 1 to " + std::to_string(kMaxPen) +
         ", velocity: cm/s from " + format_for_message(kMinVelocityCmS) + " to " +
         format_for_message(kMaxVelocityCmS) +
         ", moves: \"relative\" or \"absolute\", max_pairs: coordinate pairs per PD (1 to " +
         std::to_string(kMaxPairsPerPd) +
         "), newline: true or false, pen_speed and travel_speed: mm/s above 0, lift_time: seconds from 0, "
         "info: a string (a G-code base, " +
         gcode_profile_list() + ", takes other keys)";
}

// ---- G-code plotters --------------------------------------------------------------------------------

std::string gcode_plotter_hint(GcodePenMode mode) {
  const std::string feeds =
      format_for_message(kMinGcodeFeedMmMin) + " to " + format_for_message(kMaxGcodeFeedMmMin) + " mm/min";
  const std::string pen =
      mode == GcodePenMode::Servo
          ? "up: and down: the servo's spindle S values (0 to " + format_for_message(kMaxGcodeSpindle) + ")"
          : "z_up: and z_down: the pen's Z in mm (up above down), z_feed: the pen-down Z "
            "feed (" +
                feeds + ")";
  return "the keys of a G-code plotter are base: " + gcode_profile_list() +
         " (HPGL bases take other keys), " + pen + ", feed: the drawing feed and travel: the travel feed (" +
         feeds +
         "), dwell: seconds to wait after each pen move (dwell_down: and dwell_up: for one of them; 0 to " +
         format_for_message(kMaxGcodeDwellS) + "), width: and height: the work area in mm, origin: " +
         "\"bottom-left\" or \"top-left\", pens: 1 to " + std::to_string(kMaxPen) + ", info: a string";
}

std::vector<OptionSpec> gcode_plotter_keys(GcodePenMode mode) {
  // Built by push_back: GCC 12 warns falsely (array-bounds) about vector::insert of an initializer list.
  const bool servo = mode == GcodePenMode::Servo;
  std::vector<OptionSpec> keys;
  const auto add = [&](std::string_view name, ValueKind kind) { keys.push_back({name, kind}); };
  add("base", ValueKind::String);
  add(servo ? "up" : "z_up", ValueKind::Number);
  add(servo ? "down" : "z_down", ValueKind::Number);
  if (!servo) add("z_feed", ValueKind::Number);
  for (const std::string_view name : {"feed", "travel", "dwell", "dwell_down", "dwell_up", "width", "height"})
    add(name, ValueKind::Number);
  add("origin", ValueKind::String);
  add("pens", ValueKind::Number);
  add("info", ValueKind::String);
  return keys;
}

// The G-code profile a `base:` entry names, when it names one (evaluated here only to choose the key
// list; check_options evaluates it again and reports anything wrong with it).
template <typename Eval>
std::optional<GcodeProfile> gcode_base(const std::vector<lang::Argument>& entries, Eval&& eval) {
  for (const lang::Argument& arg : entries)
    if (arg.label && arg.label->text == "base") {
      const Value v = eval(*arg.value);
      return v.is(ValueKind::String) ? gcode_profile_by_name(v.as_string()) : std::nullopt;
    }
  return std::nullopt;
}

// `plotter NAME { base: "grbl-servo", ... }`: the base's profile with the given keys applied.
GcodeProfile gcode_plotter(const std::string& name, GcodeProfile profile, const GivenOptions& given,
                           const OptionList& list, const lang::SourceSpan& name_span) {
  profile.info = "declared in the script, based on " + profile.name;  // the base's info describes the base
  profile.name = name;
  const bool servo = profile.pen_mode == GcodePenMode::Servo;
  const std::string feeds = "from " + format_for_message(kMinGcodeFeedMmMin) + " to " +
                            format_for_message(kMaxGcodeFeedMmMin) + " mm/min";
  auto feed = [&](const GivenOption& o) {
    return number_in(
        o, list, [](double x) { return x >= kMinGcodeFeedMmMin && x <= kMaxGcodeFeedMmMin; }, feeds);
  };
  auto dwell = [&](const GivenOption& o) {
    return number_in(
        o, list, [](double x) { return x >= 0 && x <= kMaxGcodeDwellS; },
        "from 0 to " + format_for_message(kMaxGcodeDwellS) + " seconds");
  };
  auto position = [&](const GivenOption& o) {
    if (servo)
      return number_in(
          o, list, [](double x) { return x >= 0 && x <= kMaxGcodeSpindle; },
          "an S value from 0 to " + format_for_message(kMaxGcodeSpindle));
    return number_in(
        o, list, [](double x) { return std::fabs(x) <= kMaxGcodeZMm; },
        "from " + format_for_message(-kMaxGcodeZMm) + " to " + format_for_message(kMaxGcodeZMm) + " mm");
  };
  const GivenOption* up = find(given, servo ? "up" : "z_up");
  const GivenOption* down = find(given, servo ? "down" : "z_down");
  if (up) profile.pen_up = position(*up);
  if (down) profile.pen_down = position(*down);
  if (const GivenOption* o = find(given, "z_feed")) profile.z_feed_mm_min = feed(*o);
  if (const GivenOption* o = find(given, "feed")) profile.draw_feed_mm_min = feed(*o);
  if (const GivenOption* o = find(given, "travel")) profile.travel_feed_mm_min = feed(*o);
  if (const GivenOption* o = find(given, "dwell"))
    profile.pen_down_dwell_s = profile.pen_up_dwell_s = dwell(*o);
  if (const GivenOption* o = find(given, "dwell_down")) profile.pen_down_dwell_s = dwell(*o);
  if (const GivenOption* o = find(given, "dwell_up")) profile.pen_up_dwell_s = dwell(*o);
  auto side_ok = [](double x) { return x > 0 && x <= kMaxPaperSideMm; };
  const std::string sides = "above 0 and at most " + format_for_message(kMaxPaperSideMm) + " mm";
  if (const GivenOption* o = find(given, "width")) profile.width_mm = number_in(*o, list, side_ok, sides);
  if (const GivenOption* o = find(given, "height")) profile.height_mm = number_in(*o, list, side_ok, sides);
  if (const GivenOption* o = find(given, "origin")) {
    const std::string& origin = o->value.as_string();
    if (origin != "bottom-left" && origin != "top-left")
      fail(o->span, list.who + "key 'origin' must be \"bottom-left\" or \"top-left\", got \"" + origin + "\"",
           list.hint);
    profile.origin = origin == "bottom-left" ? GcodeOrigin::BottomLeft : GcodeOrigin::TopLeft;
  }
  if (const GivenOption* o = find(given, "pens"))
    profile.pen_count = static_cast<int>(number_in(
        *o, list, [](double x) { return x >= 1 && x <= kMaxPen && whole(x); }, pen_numbers()));
  if (const GivenOption* o = find(given, "info")) profile.info = o->value.as_string();
  try {  // what no single key decides: up and down apart
    check_gcode_profile(profile);
  } catch (const DeviceError& e) {
    fail(down ? down->span : up ? up->span : name_span, e.what(), list.hint);
  }
  return profile;
}

}  // namespace

int Evaluator::eval_pen_number(const lang::Expr& expr, const ScopePtr& scope) {
  const double pen = eval_number(expr, scope, "the pen number");
  if (!(pen >= 1 && pen <= kMaxPen) || !whole(pen))
    fail(expr.span, "the pen number must be " + pen_numbers() + ", got " + format_for_message(pen));
  return static_cast<int>(pen);
}

void Evaluator::set_paper(const lang::PaperSpec& paper, const lang::Stmt& stmt, const ScopePtr& scope) {
  if (out_.paper) already_set(stmt.span, "paper", out_.paper->span);
  if (!paper.size) return;
  const std::string& size = paper.size->text;
  const bool custom = equal_ignoring_case(size, "custom");
  // Landscape unless the script says portrait: drawings are mostly wider than tall, and it is the
  // devices' default.
  const bool landscape = paper.orientation != lang::Orientation::Portrait;
  std::optional<Paper> found = custom ? std::optional<Paper>(Paper{}) : paper_by_name(size, landscape);
  if (!found)
    fail(paper.size->span, "unknown paper size '" + size + "'",
         "use one of " + paper_list() + ", or 'custom (width: W, height: H)' in millimetres");

  const OptionList list{"paper '" + size + "': ",
                        "option",
                        "margin: 10",
                        paper_hint(),
                        {{"margin", ValueKind::Number},
                         {"scale", ValueKind::Number},
                         {"fit", ValueKind::String},
                         {"title", ValueKind::String},
                         {"width", ValueKind::Number},
                         {"height", ValueKind::Number}}};
  const GivenOptions given =
      check_options(paper.options, list, [&](const lang::Expr& e) { return eval(e, scope); });
  PaperSetting setting;
  setting.size = size;
  setting.span = stmt.span;

  const GivenOption* width = find(given, "width");
  const GivenOption* height = find(given, "height");
  if (custom) {
    if (!width || !height) {
      const std::string missing = !width && !height ? "width: and height:" : !width ? "width:" : "height:";
      fail(paper.size->span, "paper custom needs " + missing + " in millimetres",
           "write 'paper custom (width: 300, height: 200)'; 'landscape' or 'portrait' after 'custom' "
           "turns the sheet");
    }
    auto size_ok = [](double x) { return x > 0 && x <= kMaxPaperSideMm; };
    const std::string range = "above 0 and at most " + format_for_message(kMaxPaperSideMm) + " mm";
    found->width_mm = number_in(*width, list, size_ok, range);
    found->height_mm = number_in(*height, list, size_ok, range);
    // An orientation word turns the sheet: landscape is at least as wide as high, portrait the reverse.
    if ((paper.orientation == lang::Orientation::Landscape && found->width_mm < found->height_mm) ||
        (paper.orientation == lang::Orientation::Portrait && found->width_mm > found->height_mm))
      std::swap(found->width_mm, found->height_mm);
  } else if (const GivenOption* only_custom = width ? width : height) {
    fail(only_custom->span, list.who + "option '" + only_custom->written + "' is only for 'paper custom'",
         size + " has a fixed size; for a size of your own write 'paper custom (width: 300, height: 200)'");
  }
  setting.paper = *found;

  if (const GivenOption* margin = find(given, "margin")) {
    setting.margin_mm = number_in(
        *margin, list, [](double x) { return x >= 0; }, "0 or more millimetres");
    const double shorter = std::min(found->width_mm, found->height_mm);
    if (!(2 * *setting.margin_mm < shorter))
      fail(margin->span,
           list.who + "a margin of " + format_for_message(*setting.margin_mm) + " mm leaves no room on " +
               format_for_message(found->width_mm) + " × " + format_for_message(found->height_mm) + " mm",
           "the margins on both sides must be less than the paper's shorter side (" +
               format_for_message(shorter) + " mm)");
  }
  if (const GivenOption* scale = find(given, "scale"))
    setting.mm_per_unit = number_in(
        *scale, list, [](double x) { return x > 0; }, "above 0 millimetres per unit");
  if (const GivenOption* fit = find(given, "fit")) {
    const std::optional<PageFit> chosen = page_fit_by_name(fit->value.as_string());
    if (!chosen)
      fail(
          fit->span,
          list.who + "option 'fit' must be \"camera\" or \"drawing\", got \"" + fit->value.as_string() + "\"",
          "\"camera\" frames the page by the camera's field of view (the same scale in every frame); "
          "\"drawing\" fits whatever is drawn to the page");
    setting.fit = chosen;
  }
  if (const GivenOption* title = find(given, "title")) setting.title = title->value.as_string();
  out_.paper = std::move(setting);
}

void Evaluator::exec_pen(const lang::PenStmt& pen, const lang::Stmt& stmt, const ScopePtr& scope) {
  PenSetting setting;
  setting.pen = eval_pen_number(*pen.number, scope);
  setting.span = stmt.span;
  for (const PenSetting& p : out_.pens)
    if (p.pen == setting.pen) {
      lang::Diagnostic d;
      d.span = pen.number->span;
      d.message = "pen " + std::to_string(setting.pen) + " is already set";
      d.hint = "set each pen once: one 'pen " + std::to_string(setting.pen) + " (...)' statement";
      d.notes.push_back({p.span, "it was set here"});
      throw EvalError(std::move(d));
    }
  const OptionList list{"pen " + std::to_string(setting.pen) + ": ",
                        "option",
                        "colour: \"red\"",
                        pen_hint(),
                        {{"colour", ValueKind::String, "color"}, {"width", ValueKind::Number}}};
  const GivenOptions given =
      check_options(pen.options, list, [&](const lang::Expr& e) { return eval(e, scope); });
  if (const GivenOption* colour = find(given, "colour")) {
    const std::string& text = colour->value.as_string();
    if (!parse_colour(text)) fail(colour->span, list.who + "unknown colour \"" + text + "\"", pen_hint());
    setting.colour = text;
  }
  if (const GivenOption* width = find(given, "width"))
    setting.width_mm = number_in(
        *width, list, [](double x) { return x > 0 && x <= kMaxPenWidthMm; }, pen_widths());
  out_.pens.push_back(std::move(setting));
}

void Evaluator::exec_plotter(const lang::PlotterStmt& plotter, const lang::Stmt& stmt,
                             const ScopePtr& scope) {
  const std::string& name = plotter.name.text;
  if (hpgl_profile_by_name(name) || gcode_profile_by_name(name))
    fail(plotter.name.span, "'" + name + "' is the name of a built-in plotter profile",
         "give yours another name and start from the built-in one: 'plotter my_" + name + " { base: \"" +
             name + "\", ... }'; or use it as it is: 'output \"plot." +
             (gcode_profile_by_name(name) ? "gcode" : "hpgl") + "\" plotter " + name + "'");
  for (const PlotterSetting& p : out_.plotters)
    if (p.profile.name == name) {
      lang::Diagnostic d;
      d.span = plotter.name.span;
      d.message = "plotter '" + name + "' is already declared";
      d.hint = "give each plotter its own name";
      d.notes.push_back({p.span, "the first 'plotter " + name + "' is here"});
      throw EvalError(std::move(d));
    }
  const auto evaluate = [&](const lang::Expr& e) { return eval(e, scope); };
  if (std::optional<GcodeProfile> base = gcode_base(plotter.entries, evaluate)) {
    const OptionList list{"plotter '" + name + "': ", "key", "feed: 3000", gcode_plotter_hint(base->pen_mode),
                          gcode_plotter_keys(base->pen_mode)};
    const GivenOptions given = check_options(plotter.entries, list, evaluate);
    PlotterSetting setting;
    setting.profile.name = name;
    setting.span = stmt.span;
    setting.gcode = gcode_plotter(name, std::move(*base), given, list, plotter.name.span);
    out_.plotters.push_back(std::move(setting));
    return;
  }
  const OptionList list{"plotter '" + name + "': ",
                        "key",
                        "pens: 6",
                        plotter_hint(),
                        {{"base", ValueKind::String},
                         {"unit", ValueKind::Number},
                         {"pens", ValueKind::Number},
                         {"velocity", ValueKind::Number},
                         {"moves", ValueKind::String},
                         {"max_pairs", ValueKind::Number},
                         {"newline", ValueKind::Bool},
                         {"pen_speed", ValueKind::Number},
                         {"travel_speed", ValueKind::Number},
                         {"lift_time", ValueKind::Number},
                         {"info", ValueKind::String}}};
  const GivenOptions given =
      check_options(plotter.entries, list, [&](const lang::Expr& e) { return eval(e, scope); });

  // The declared profile starts as a copy of its base.
  HpglProfile profile;
  if (const GivenOption* base = find(given, "base")) {
    const std::optional<HpglProfile> found = hpgl_profile_by_name(base->value.as_string());
    if (!found) {
      std::vector<std::string> names;
      for (const HpglProfile& p : builtin_hpgl_profiles()) names.push_back(p.name);
      for (const GcodeProfile& p : builtin_gcode_profiles()) names.push_back(p.name);
      const std::string guess = did_you_mean(base->value.as_string(), names);
      fail(base->span, list.who + "unknown base profile \"" + base->value.as_string() + "\"",
           (guess.empty() ? "" : guess + " ") + "the built-in profiles are " + hpgl_profile_list() +
               " (HPGL) and " + gcode_profile_list() + " (G-code)");
    }
    profile = *found;
  } else if (std::optional<HpglProfile> generic = hpgl_profile_by_name("generic")) {
    profile = std::move(*generic);
  }
  profile.name = name;

  auto positive = [](double x) { return x > 0; };
  if (const GivenOption* o = find(given, "unit"))
    profile.unit_mm = number_in(
        *o, list, [](double x) { return x >= kMinPlotterUnitMm && x <= kMaxPlotterUnitMm; },
        "from " + format_for_message(kMinPlotterUnitMm) + " to " + format_for_message(kMaxPlotterUnitMm) +
            " mm");
  if (const GivenOption* o = find(given, "pens"))
    profile.pen_count = static_cast<int>(number_in(
        *o, list, [](double x) { return x >= 1 && x <= kMaxPen && whole(x); }, pen_numbers()));
  if (const GivenOption* o = find(given, "velocity"))
    profile.velocity_cm_s = number_in(
        *o, list, [](double x) { return x >= kMinVelocityCmS && x <= kMaxVelocityCmS; },
        "from " + format_for_message(kMinVelocityCmS) + " to " + format_for_message(kMaxVelocityCmS) +
            " cm/s");
  if (const GivenOption* o = find(given, "moves")) {
    const std::string& moves = o->value.as_string();
    if (moves != "relative" && moves != "absolute")
      fail(o->span, list.who + "key 'moves' must be \"relative\" or \"absolute\", got \"" + moves + "\"",
           list.hint);
    profile.relative = moves == "relative";
  }
  if (const GivenOption* o = find(given, "max_pairs"))
    profile.max_pairs_per_pd = static_cast<int>(number_in(
        *o, list, [](double x) { return x >= 1 && x <= kMaxPairsPerPd && whole(x); },
        "a whole number from 1 to " + std::to_string(kMaxPairsPerPd)));
  if (const GivenOption* o = find(given, "newline")) profile.newline = o->value.as_bool();
  if (const GivenOption* o = find(given, "pen_speed"))
    profile.speeds.pen_down_mm_per_s = number_in(*o, list, positive, "above 0 mm/s");
  if (const GivenOption* o = find(given, "travel_speed"))
    profile.speeds.pen_up_mm_per_s = number_in(*o, list, positive, "above 0 mm/s");
  if (const GivenOption* o = find(given, "lift_time"))
    profile.speeds.lift_s = number_in(
        *o, list, [](double x) { return x >= 0; }, "0 or more seconds");
  if (const GivenOption* o = find(given, "info")) profile.info = o->value.as_string();
  out_.plotters.push_back({std::move(profile), stmt.span, std::nullopt});
}

// ---- labels ------------------------------------------------------------------------------------------

void Evaluator::exec_label(const lang::LabelStmt& label, const lang::Stmt& stmt, const ScopePtr& scope) {
  LabelSetting setting;
  setting.span = stmt.span;
  setting.on_page = label.on_page;
  const Value text = eval(*label.text, scope);
  try {  // any value, written as str() writes it
    setting.text = text.is(ValueKind::String) ? text.as_string() : display(text, budget_.limits().string);
  } catch (const FormatError& e) {
    fail(label.text->span, e.what());
  }
  const Value at = eval(*label.point, scope);
  if (!at.is(ValueKind::Vector))
    fail(label.point->span, "a label goes at a point, got " + kind_with_article(at.kind()),
         label.on_page ? "on the page: 'at page (20, 15)', millimetres from the top-left corner"
                       : "in the world: 'at (0, 0, 2)'; on the page: 'at page (20, 15)'");
  const Vector3 v = at.as_vector();
  setting.at = {v.x, v.y, v.z};
  if (!is_finite(setting.at)) fail(label.point->span, "the label's point must be finite");
  if (label.on_page && (v.x < 0 || v.y < 0 || v.z != 0))
    fail(label.point->span,
         "a page point is (x, y) in millimetres from the page's top-left corner, both 0 or more");
  if (label.size) {
    const Value size = eval(*label.size, scope);
    if (!size.is(ValueKind::Number) || !(size.as_number() > 0 && size.as_number() <= kMaxLabelSizeMm))
      fail(label.size->span,
           "the label's size is the height of its capitals in millimetres, above 0 and at most " +
               format_for_message(kMaxLabelSizeMm),
           "for example: size: 4");
    setting.size_mm = size.as_number();
  }
  if (label.pen) setting.pen = eval_pen_number(*label.pen->number, scope);
  // Characters the single-stroke fonts do not hold are drawn as boxes: said once per label.
  std::u32string missing;
  try {
    missing = missing_glyphs(setting.text);
  } catch (const DeviceError&) {  // no fonts: the device that draws the label says so
  }
  if (!missing.empty()) {
    lang::Diagnostic d;
    d.severity = lang::Severity::Warning;
    d.span = label.text->span;
    std::string names;
    for (const char32_t c : missing) names += (names.empty() ? "" : ", ") + describe_code_point(c);
    d.message = "the label has characters with no single-stroke letter, drawn as a box: " + names;
    d.hint = "labels draw Latin letters (with accents), digits, punctuation, ß, °, ², ³, µ and Greek";
    budget_.warn(std::move(d));
  }
  out_.labels.push_back(std::move(setting));
}

}  // namespace hlr::runtime
