// Device settings: paper options and custom sizes, pens, `draw ... pen N`, `style hidden dashed pen N`,
// plotter profiles and `output ... plotter NAME` — what the evaluator puts into the FrameScene, and every
// mistake as an error at its place.
#include <gtest/gtest.h>

#include <string>

#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

std::string text_of(const std::string& script, const lang::SourceSpan& span) {
  return script.substr(span.begin, span.end - span.begin);
}

// ---- paper ----------------------------------------------------------------------------------------

TEST(DeviceSettings, PaperOptions) {
  const FrameScene plain = test::run_ok("paper A4");
  ASSERT_TRUE(plain.paper);
  EXPECT_FALSE(plain.paper->margin_mm);
  EXPECT_FALSE(plain.paper->mm_per_unit);

  const FrameScene scene = test::run_ok("let m = 5\npaper A4 landscape (margin: 2 * m, scale: 0.5)");
  ASSERT_TRUE(scene.paper);
  EXPECT_EQ(scene.paper->size, "A4");
  EXPECT_EQ(scene.paper->paper.width_mm, 297);
  EXPECT_EQ(scene.paper->paper.height_mm, 210);
  EXPECT_EQ(scene.paper->margin_mm, 10.0);
  EXPECT_EQ(scene.paper->mm_per_unit, 0.5);

  const FrameScene portrait = test::run_ok("paper A3 portrait (margin: 0)");
  EXPECT_EQ(portrait.paper->paper.width_mm, 297);
  EXPECT_EQ(portrait.paper->paper.height_mm, 420);
  EXPECT_EQ(portrait.paper->margin_mm, 0.0);
  EXPECT_FALSE(portrait.paper->mm_per_unit);
}

TEST(DeviceSettings, CustomPaper) {
  const FrameScene as_written = test::run_ok("paper custom (width: 200, height: 300, margin: 8)");
  ASSERT_TRUE(as_written.paper);
  EXPECT_EQ(as_written.paper->size, "custom");
  EXPECT_EQ(as_written.paper->paper.width_mm, 200);
  EXPECT_EQ(as_written.paper->paper.height_mm, 300);
  EXPECT_EQ(as_written.paper->margin_mm, 8.0);
  // An orientation word turns the sheet.
  const FrameScene landscape = test::run_ok("paper custom landscape (width: 200, height: 300)");
  EXPECT_EQ(landscape.paper->paper.width_mm, 300);
  EXPECT_EQ(landscape.paper->paper.height_mm, 200);
  const FrameScene portrait = test::run_ok("paper custom portrait (height: 200, width: 300)");
  EXPECT_EQ(portrait.paper->paper.width_mm, 200);
  EXPECT_EQ(portrait.paper->paper.height_mm, 300);
  const FrameScene kept = test::run_ok("paper custom portrait (width: 200, height: 300)");
  EXPECT_EQ(kept.paper->paper.width_mm, 200);
  EXPECT_EQ(kept.paper->paper.height_mm, 300);
  const FrameScene largest = test::run_ok("paper custom (width: 10000, height: 0.5)");
  EXPECT_EQ(largest.paper->paper.width_mm, 10000);
}

TEST(DeviceSettings, OutputPaperAndPlotter) {
  const std::string script = "output \"plot.hpgl\" paper A4 portrait (margin: 15) plotter \"roland-dxy\"";
  const FrameScene scene = test::run_ok(script);
  ASSERT_TRUE(scene.output);
  EXPECT_EQ(scene.output->name, "plot.hpgl");
  EXPECT_EQ(scene.output->plotter, "roland-dxy");
  ASSERT_TRUE(scene.output->plotter_span);
  EXPECT_EQ(text_of(script, *scene.output->plotter_span), "\"roland-dxy\"");
  ASSERT_TRUE(scene.paper);
  EXPECT_EQ(scene.paper->paper.width_mm, 210);
  EXPECT_EQ(scene.paper->margin_mm, 15.0);

  // Only recorded: resolving the name is the run's business, so an undeclared one is no error here.
  const FrameScene named = test::run_ok("output \"p.hpgl\" plotter mine\nplotter mine { pens: 2 }");
  EXPECT_EQ(named.output->plotter, "mine");
  EXPECT_FALSE(named.paper);
  EXPECT_EQ(test::run_ok("output \"p.hpgl\" plotter nowhere").output->plotter, "nowhere");
  EXPECT_FALSE(test::run_ok("output \"x.pdf\"").output->plotter);
  EXPECT_FALSE(test::run_ok("output \"x.pdf\"").output->plotter_span);
}

struct Case {
  const char* script;
  const char* expected;  // "line:col: message"
};

// clang-format off
const Case kPaperErrors[] = {
  {"paper B17 (margin: 1)", "1:7: unknown paper size 'B17'"},
  {"paper custom", "1:7: paper custom needs width: and height: in millimetres"},
  {"paper custom (width: 100)", "1:7: paper custom needs height: in millimetres"},
  {"paper custom (height: 100, margin: 1)", "1:7: paper custom needs width: in millimetres"},
  {"paper A4 (width: 100)", "1:11: paper 'A4': option 'width' is only for 'paper custom'"},
  {"paper A4 (margin: 1, height: 100)", "1:22: paper 'A4': option 'height' is only for 'paper custom'"},
  {"paper custom (width: 0, height: 100)", "1:15: paper 'custom': option 'width' must be above 0 and at most 10000 mm (got 0)"},
  {"paper custom (width: 100, height: 10001)", "1:27: paper 'custom': option 'height' must be above 0 and at most 10000 mm (got 10001)"},
  {"paper custom (width: 100, height: -5)", "1:27: paper 'custom': option 'height' must be above 0 and at most 10000 mm (got -5)"},
  {"paper A4 (margin: -1)", "1:11: paper 'A4': option 'margin' must be 0 or more millimetres (got -1)"},
  {"paper A4 (margin: 105)", "1:11: paper 'A4': a margin of 105 mm leaves no room on 297 × 210 mm"},
  {"paper custom (width: 100, height: 40, margin: 20)", "1:39: paper 'custom': a margin of 20 mm leaves no room on 100 × 40 mm"},
  {"paper A4 (scale: 0)", "1:11: paper 'A4': option 'scale' must be above 0 millimetres per unit (got 0)"},
  {"paper A4 (scale: -2)", "1:11: paper 'A4': option 'scale' must be above 0 millimetres per unit (got -2)"},
  {"paper A4 (margins: 10)", "1:11: paper 'A4': unknown option 'margins'"},
  {"paper A4 (margin: 1, margin: 2)", "1:22: paper 'A4': option 'margin' is given twice"},
  {"paper A4 (margin: \"10\")", "1:11: paper 'A4': option 'margin' must be a number, got a string"},
  {"paper A4 (10)", "1:11: paper 'A4': each option needs a name, as in 'margin: 10'"},
  {"paper A4 (margin: x)", "1:19: unknown name 'x'"},
  {"output \"x.pdf\" paper A4 (margin: 500)", "1:26: paper 'A4': a margin of 500 mm leaves no room on 297 × 210 mm"},
  {"output \"x.pdf\" paper A4\npaper A3 (margin: 1)", "2:1: 'paper' is already set"},
  {"output \"x.hpgl\" plotter \"\"", "1:25: the plotter name is empty"},
};
// clang-format on

TEST(DeviceSettings, PaperErrors) {
  for (const Case& c : kPaperErrors) EXPECT_EQ(test::first_error(c.script), c.expected) << c.script;
}

TEST(DeviceSettings, PaperOptionHintListsTheOptions) {
  const std::string printed = test::printed_error("paper A4 (margins: 10)");
  EXPECT_NE(printed.find("hint: did you mean 'margin'? the paper options are margin:"), std::string::npos)
      << printed;
  const std::string twice = test::printed_error("paper A4 (margin: 1, margin: 2)");
  EXPECT_NE(twice.find("note: first given here"), std::string::npos) << twice;
}

// ---- pens -----------------------------------------------------------------------------------------

TEST(DeviceSettings, PenStatements) {
  const std::string script =
      "pen 2 (colour: \"red\", width: 0.35)\n"
      "let n = 6\n"
      "pen (n + 1) (color: \"#0F0\")\n"
      "pen 9 (width: 10)\n"
      "pen 255 ()\n";
  const FrameScene scene = test::run_ok(script);
  ASSERT_EQ(scene.pens.size(), 4U);
  EXPECT_EQ(scene.pens[0].pen, 2);
  EXPECT_EQ(scene.pens[0].colour, "red");
  EXPECT_EQ(scene.pens[0].width_mm, 0.35);
  EXPECT_EQ(text_of(script, scene.pens[0].span), "pen 2 (colour: \"red\", width: 0.35)");
  EXPECT_EQ(scene.pens[1].pen, 7);
  EXPECT_EQ(scene.pens[1].colour, "#0F0");
  EXPECT_FALSE(scene.pens[1].width_mm);
  EXPECT_EQ(scene.pens[2].pen, 9);
  EXPECT_FALSE(scene.pens[2].colour);
  EXPECT_EQ(scene.pens[2].width_mm, 10.0);
  EXPECT_EQ(scene.pens[3].pen, 255);
  for (const char* colour :
       {"black", "Grey", "gray", "white", "orange", "brown", "purple", "#abc", "#a0b1c2"}) {
    const FrameScene one = test::run_ok(std::string("pen 1 (colour: \"") + colour + "\")");
    ASSERT_EQ(one.pens.size(), 1U) << colour;
    EXPECT_EQ(one.pens[0].colour, colour);
  }
}

TEST(DeviceSettings, DrawPens) {
  const FrameScene scene = test::run_ok(
      "draw cube(1)\n"
      "draw group([cube(1), place(cube(1), translate(2, 0, 0))]) at translate(0, 3, 0) pen 3\n"
      "for i in 1..3 { draw cube(1) at translate(0, 0, 2 * i) pen i + 3 }\n"
      "let pen = 9\n"
      "draw cube(1) pen pen\n");
  ASSERT_EQ(scene.scene.objects.size(), 6U);
  EXPECT_EQ(scene.object_pens, (std::vector<int>{1, 3, 3, 4, 5, 9}));
  EXPECT_TRUE(test::run_ok("let x = 1").object_pens.empty());
  // A draw and a pen statement on the next line are two statements.
  const FrameScene two = test::run_ok("draw cube(1)\npen 2 (colour: \"blue\")");
  EXPECT_EQ(two.object_pens, (std::vector<int>{1}));
  ASSERT_EQ(two.pens.size(), 1U);
  EXPECT_EQ(two.pens[0].pen, 2);
}

TEST(DeviceSettings, HiddenPen) {
  const FrameScene dashed = test::run_ok("style hidden dashed pen 2");
  EXPECT_EQ(dashed.hidden, HiddenStyle::dashed());
  EXPECT_EQ(dashed.hidden_pen, 2);
  const FrameScene plain = test::run_ok("style hidden dashed");
  EXPECT_EQ(plain.hidden, HiddenStyle::dashed());
  EXPECT_FALSE(plain.hidden_pen);
  EXPECT_FALSE(test::run_ok("style hidden off").hidden_pen);
}

// clang-format off
const Case kPenErrors[] = {
  {"pen 0 ()", "1:5: the pen number must be a whole number from 1 to 255, got 0"},
  {"pen 256 ()", "1:5: the pen number must be a whole number from 1 to 255, got 256"},
  {"pen 1.5 ()", "1:5: the pen number must be a whole number from 1 to 255, got 1.5"},
  {"let p = \"red\"\npen p ()", "2:5: the pen number must be a number, got a string"},
  {"pen 2 ()\npen 2 (width: 1)", "2:5: pen 2 is already set"},
  {"pen 2 (colour: \"redd\")", "1:8: pen 2: unknown colour \"redd\""},
  {"pen 2 (colour: \"#12345\")", "1:8: pen 2: unknown colour \"#12345\""},
  {"pen 2 (colour: 3)", "1:8: pen 2: option 'colour' must be a string, got a number"},
  {"pen 2 (colour: \"red\", color: \"blue\")", "1:23: pen 2: option 'color' is given twice (as 'colour' before)"},
  {"pen 2 (width: 0)", "1:8: pen 2: option 'width' must be above 0 and at most 10 mm (got 0)"},
  {"pen 2 (width: 10.5)", "1:8: pen 2: option 'width' must be above 0 and at most 10 mm (got 10.5)"},
  {"pen 2 (thickness: 1)", "1:8: pen 2: unknown option 'thickness'"},
  {"pen 2 (\"red\")", "1:8: pen 2: each option needs a name, as in 'colour: \"red\"'"},
  {"draw cube(1) pen \"red\"", "1:18: the pen number must be a number, got a string"},
  {"draw cube(1) pen 0", "1:18: the pen number must be a whole number from 1 to 255, got 0"},
  {"draw cube(1) at translate(1, 0, 0) pen 2.5", "1:40: the pen number must be a whole number from 1 to 255, got 2.5"},
  {"style hidden dashed pen 300", "1:25: the pen number must be a whole number from 1 to 255, got 300"},
  {"style hidden off pen 2", "1:18: a pen goes only with 'style hidden dashed' or 'style hidden levels N'"},
};
// clang-format on

TEST(DeviceSettings, PenErrors) {
  for (const Case& c : kPenErrors) EXPECT_EQ(test::first_error(c.script), c.expected) << c.script;
  const std::string twice = test::printed_error("pen 2 ()\npen 2 (width: 1)");
  EXPECT_NE(twice.find("test.hls:1:1: note: it was set here"), std::string::npos) << twice;
}

// ---- plotters -------------------------------------------------------------------------------------

TEST(DeviceSettings, PlotterProfiles) {
  const std::string script =
      "plotter mine {\n"
      "  base: \"hp7475a\"\n"
      "  pens: 4, velocity: 20\n"
      "  moves: \"absolute\"\n"
      "  max_pairs: 32\n"
      "  newline: true\n"
      "  pen_speed: 100, travel_speed: 250, lift_time: 0.2\n"
      "  info: \"my old 7475A\"\n"
      "}\n"
      "plotter plain {}\n";
  const FrameScene scene = test::run_ok(script);
  ASSERT_EQ(scene.plotters.size(), 2U);
  const HpglProfile& mine = scene.plotters[0].profile;
  const std::optional<HpglProfile> base = hpgl_profile_by_name("hp7475a");
  ASSERT_TRUE(base);
  EXPECT_EQ(mine.name, "mine");
  EXPECT_EQ(mine.unit_mm, base->unit_mm);  // copied from the base
  EXPECT_EQ(mine.ranges.size(), base->ranges.size());
  EXPECT_EQ(mine.pen_count, 4);
  EXPECT_EQ(mine.velocity_cm_s, 20.0);
  EXPECT_FALSE(mine.relative);
  EXPECT_EQ(mine.max_pairs_per_pd, 32);
  EXPECT_TRUE(mine.newline);
  EXPECT_EQ(mine.speeds.pen_down_mm_per_s, 100);
  EXPECT_EQ(mine.speeds.pen_up_mm_per_s, 250);
  EXPECT_EQ(mine.speeds.lift_s, 0.2);
  EXPECT_EQ(mine.info, "my old 7475A");
  EXPECT_EQ(text_of(script, scene.plotters[0].span).substr(0, 14), "plotter mine {");

  // Without base: a copy of "generic", renamed.
  const std::optional<HpglProfile> generic = hpgl_profile_by_name("generic");
  ASSERT_TRUE(generic);
  const HpglProfile& plain = scene.plotters[1].profile;
  EXPECT_EQ(plain.name, "plain");
  EXPECT_EQ(plain.unit_mm, generic->unit_mm);
  EXPECT_EQ(plain.pen_count, generic->pen_count);
  EXPECT_EQ(plain.relative, generic->relative);
  EXPECT_EQ(plain.info, generic->info);

  const FrameScene unit = test::run_ok("plotter fine { unit: 0.001, moves: \"relative\" }");
  EXPECT_EQ(unit.plotters[0].profile.unit_mm, 0.001);
  EXPECT_TRUE(unit.plotters[0].profile.relative);
}

// clang-format off
const Case kPlotterErrors[] = {
  {"plotter hp7475a {}", "1:9: 'hp7475a' is the name of a built-in plotter profile"},
  {"plotter HP7475A {}", "1:9: 'HP7475A' is the name of a built-in plotter profile"},
  {"plotter generic { pens: 2 }", "1:9: 'generic' is the name of a built-in plotter profile"},
  {"plotter m {}\nplotter m { pens: 2 }", "2:9: plotter 'm' is already declared"},
  {"plotter m { speed: 3 }", "1:13: plotter 'm': unknown key 'speed'"},
  {"plotter m { pens: 2, pens: 3 }", "1:22: plotter 'm': key 'pens' is given twice"},
  {"plotter m { base: \"hp7474a\" }", "1:13: plotter 'm': unknown base profile \"hp7474a\""},
  {"plotter m { base: hp7475a }", "1:19: unknown name 'hp7475a'"},
  {"plotter m { base: 7475 }", "1:13: plotter 'm': key 'base' must be a string, got a number"},
  {"plotter m { unit: 0 }", "1:13: plotter 'm': key 'unit' must be from 0.001 to 1 mm (got 0)"},
  {"plotter m { unit: 2 }", "1:13: plotter 'm': key 'unit' must be from 0.001 to 1 mm (got 2)"},
  {"plotter m { pens: 0 }", "1:13: plotter 'm': key 'pens' must be a whole number from 1 to 255 (got 0)"},
  {"plotter m { pens: 2.5 }", "1:13: plotter 'm': key 'pens' must be a whole number from 1 to 255 (got 2.5)"},
  {"plotter m { velocity: 0 }", "1:13: plotter 'm': key 'velocity' must be from 0.01 to 1000 cm/s (got 0)"},
  {"plotter m { velocity: 1001 }", "1:13: plotter 'm': key 'velocity' must be from 0.01 to 1000 cm/s (got 1001)"},
  {"plotter m { moves: \"rel\" }", "1:13: plotter 'm': key 'moves' must be \"relative\" or \"absolute\", got \"rel\""},
  {"plotter m { max_pairs: 0 }", "1:13: plotter 'm': key 'max_pairs' must be a whole number from 1 to 10000 (got 0)"},
  {"plotter m { max_pairs: 10001 }", "1:13: plotter 'm': key 'max_pairs' must be a whole number from 1 to 10000 (got 10001)"},
  {"plotter m { newline: 1 }", "1:13: plotter 'm': key 'newline' must be true or false, got a number"},
  {"plotter m { pen_speed: 0 }", "1:13: plotter 'm': key 'pen_speed' must be above 0 mm/s (got 0)"},
  {"plotter m { travel_speed: -1 }", "1:13: plotter 'm': key 'travel_speed' must be above 0 mm/s (got -1)"},
  {"plotter m { lift_time: -0.1 }", "1:13: plotter 'm': key 'lift_time' must be 0 or more seconds (got -0.1)"},
  {"plotter m { info: 3 }", "1:13: plotter 'm': key 'info' must be a string, got a number"},
};
// clang-format on

TEST(DeviceSettings, PlotterErrors) {
  for (const Case& c : kPlotterErrors) EXPECT_EQ(test::first_error(c.script), c.expected) << c.script;
  const std::string builtin = test::printed_error("plotter hp7475a {}");
  EXPECT_NE(builtin.find("base: \"hp7475a\""), std::string::npos) << builtin;
  const std::string base = test::printed_error("plotter m { base: \"hp7474a\" }");
  EXPECT_NE(base.find("did you mean 'hp7475a'?"), std::string::npos) << base;
  const std::string twice = test::printed_error("plotter m {}\nplotter m {}");
  EXPECT_NE(twice.find("test.hls:1:1: note: the first 'plotter m' is here"), std::string::npos) << twice;
}

TEST(DeviceSettings, EveryFrameEvaluatesTheSettingsAgain) {
  const std::string script =
      "animate frames 3\n"
      "pen 1 (width: 0.1 + frame / 10)\n"
      "plotter p { pens: frame + 1 }\n"
      "draw cube(1) pen frame + 1\n";
  for (int frame = 0; frame < 3; ++frame) {
    const FrameScene scene = test::run_ok(script, frame_time(frame, 3, 24));
    ASSERT_EQ(scene.pens.size(), 1U);
    EXPECT_DOUBLE_EQ(*scene.pens[0].width_mm, 0.1 + frame / 10.0);
    ASSERT_EQ(scene.plotters.size(), 1U);
    EXPECT_EQ(scene.plotters[0].profile.pen_count, frame + 1);
    EXPECT_EQ(scene.object_pens, (std::vector<int>{frame + 1}));
  }
}

}  // namespace
}  // namespace hlr::runtime
