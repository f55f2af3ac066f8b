// solid NAME (crease: ..., planarity: ..., crossing_holes: ..., fix_winding: ...) { ... }: each option
// reaches hlr::SolidBuilder, and every mistake in the list is an error at the option with the list of
// options as the hint.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

const char* kOptionsHint =
    "the options are crease: degrees from 0 to 180, planarity: a fraction of the face's size above 0 "
    "and at most 0.05, crossing_holes: true or false, fix_winding: true or false";

// A 2 × 1 × 1 block whose top is a ridge 0.05 high along x = 1: the two roof faces meet at 5.7°.
std::string ridge(const std::string& options) {
  return "solid roof " + options +
         " {\n"
         "  vertex 1 = (0, 0, 0)\n  vertex 2 = (2, 0, 0)\n  vertex 3 = (2, 1, 0)\n  vertex 4 = (0, 1, 0)\n"
         "  vertex 5 = (0, 0, 1)\n  vertex 6 = (2, 0, 1)\n  vertex 7 = (2, 1, 1)\n  vertex 8 = (0, 1, 1)\n"
         "  vertex 9 = (1, 0, 1.05)\n  vertex 10 = (1, 1, 1.05)\n"
         "  face 1 4 3 2\n"
         "  face 1 2 6 9 5\n  face 3 4 8 10 7\n"
         "  face 2 3 7 6\n  face 4 1 5 8\n"
         "  face 5 9 10 8\n  face 9 6 7 10\n"
         "}\n"
         "draw roof\n";
}

std::size_t count_kind(const FrameScene& scene, EdgeKind kind) {
  if (scene.scene.objects.empty()) return 0;
  const auto& edges = scene.scene.objects[0].solid->edges;
  return static_cast<std::size_t>(
      std::count_if(edges.begin(), edges.end(), [&](const SolidEdge& e) { return e.kind == kind; }));
}

TEST(SolidOptions, CreaseMakesShallowEdgesSmooth) {
  const FrameScene sharp = test::run_ok(ridge(""));
  EXPECT_EQ(count_kind(sharp, EdgeKind::Smooth), 0U);
  EXPECT_EQ(count_kind(sharp, EdgeKind::Feature), 15U);

  const FrameScene smooth = test::run_ok(ridge("(crease: 10)"));
  ASSERT_EQ(smooth.scene.objects.size(), 1U);
  EXPECT_EQ(smooth.scene.objects[0].solid->crease_angle_deg, 10.0);
  ASSERT_EQ(count_kind(smooth, EdgeKind::Smooth), 1U);  // the ridge 9–10, and nothing else
  for (const SolidEdge& e : smooth.scene.objects[0].solid->edges) {
    if (e.kind != EdgeKind::Smooth) continue;
    const Point3 a = smooth.scene.objects[0].solid->vertices[e.v0];
    const Point3 b = smooth.scene.objects[0].solid->vertices[e.v1];
    EXPECT_EQ(a.z, 1.05);
    EXPECT_EQ(b.z, 1.05);
  }
  // Below the ridge's 5.7° the edge stays a feature; the option is an expression.
  EXPECT_EQ(count_kind(test::run_ok(ridge("(crease: 5)")), EdgeKind::Smooth), 0U);
  EXPECT_EQ(count_kind(test::run_ok("let c = 3\n" + ridge("(crease: 2 * c)")), EdgeKind::Smooth), 1U);
  EXPECT_EQ(count_kind(test::run_ok(ridge("(crease: 180)")), EdgeKind::Smooth), 15U);
  EXPECT_EQ(count_kind(test::run_ok(ridge("(crease: 0)")), EdgeKind::Smooth), 0U);
  EXPECT_EQ(count_kind(test::run_ok(ridge("()")), EdgeKind::Smooth), 0U);
}

// One unit square with vertex 3 lifted by 0.001: about 1.8e-4 of the face's size off the plane.
std::string warped(const std::string& options) {
  return "solid sheet " + options +
         " {\n"
         "  vertex 1 = (0, 0, 0)\n  vertex 2 = (1, 0, 0)\n  vertex 3 = (1, 1, 0.001)\n  vertex 4 = (0, 1, "
         "0)\n"
         "  face 1 2 3 4\n"
         "}\n"
         "draw sheet\n";
}

TEST(SolidOptions, PlanarityLetsASlightlyWarpedFaceThrough) {
  const std::string strict = test::first_error(warped(""));
  const std::string deviation = "6:3: solid 'sheet': face 1 is not planar: vertex ";
  ASSERT_EQ(strict.substr(0, deviation.size()), deviation) << strict;
  EXPECT_NE(strict.find("(tolerance 1e-06 × face size); split it into planar faces"), std::string::npos)
      << strict;

  const FrameScene relaxed = test::run_ok(warped("(planarity: 0.003)"));
  ASSERT_EQ(relaxed.scene.objects.size(), 1U);
  EXPECT_EQ(relaxed.scene.objects[0].solid->faces.size(), 1U);
  ASSERT_EQ(relaxed.warnings.size(), 1U);
  // Asked for by the script's own option: a note (printed with --verbose), not a warning.
  EXPECT_EQ(relaxed.warnings[0].severity, lang::Severity::Note);
  const std::string warning = test::line_col(relaxed.warnings[0], warped("(planarity: 0.003)"));
  EXPECT_EQ(warning.substr(0, deviation.size()), deviation) << warning;
  EXPECT_NE(warning.find("accepted by the planarity tolerance 0.003"), std::string::npos) << warning;

  // Too tight still: the same deviation message, with the tolerance asked for.
  const std::string tight = test::first_error(warped("(planarity: 1e-5)"));
  const std::string same = strict.substr(0, strict.find(" (tolerance"));
  EXPECT_EQ(tight.substr(0, same.size()), same) << tight;
  EXPECT_NE(tight.find("(tolerance 1e-05 × face size)"), std::string::npos) << tight;
  EXPECT_EQ(test::run_ok(warped("(planarity: 0.05)")).scene.objects.size(), 1U);
}

// A 4 × 4 sheet with a hole that pokes out past its right edge.
std::string crossing(const std::string& options) {
  return "solid plate " + options +
         " {\n"
         "  vertex 1 = (0, 0, 0)\n  vertex 2 = (4, 0, 0)\n  vertex 3 = (4, 4, 0)\n  vertex 4 = (0, 4, 0)\n"
         "  vertex 5 = (1, 1, 0)\n  vertex 6 = (5, 1, 0)\n  vertex 7 = (5, 3, 0)\n  vertex 8 = (1, 3, 0)\n"
         "  face 1 2 3 4 hole 8 7 6 5\n"
         "}\n"
         "draw plate\n";
}

TEST(SolidOptions, CrossingHolesAcceptsAHoleOutsideItsFace) {
  const std::string refused = test::first_error(crossing(""));
  EXPECT_EQ(refused.substr(0, 37), "10:3: solid 'plate': hole 1 of face 1") << refused;
  EXPECT_NE(refused.find("a hole must lie within the outer ring"), std::string::npos) << refused;
  EXPECT_EQ(test::first_error(crossing("(crossing_holes: false)")), refused);

  const FrameScene kept = test::run_ok(crossing("(crossing_holes: true)"));
  ASSERT_EQ(kept.scene.objects.size(), 1U);
  EXPECT_EQ(kept.scene.objects[0].solid->faces[0].rings.size(), 2U);
  ASSERT_EQ(kept.warnings.size(), 1U);
  const std::string warning = test::line_col(kept.warnings[0], crossing("(crossing_holes: true)"));
  EXPECT_EQ(warning.substr(0, 37), "10:3: solid 'plate': hole 1 of face 1") << warning;
  EXPECT_NE(warning.find("the face is the even-odd region of its rings"), std::string::npos) << warning;
}

const char* kTetraFlipped =
    "  vertex a = (0, 0, 0)\n  vertex b = (1, 0, 0)\n  vertex c = (0, 1, 0)\n  vertex d = (0, 0, 1)\n"
    "  face a c b\n  face a d b\n  face b c d\n  face c a d\n"
    "}\n"
    "draw tet\n";

TEST(SolidOptions, FixWindingFalseMakesAWrongWindingAnError) {
  const std::string script = std::string("solid tet {\n") + kTetraFlipped;
  const FrameScene fixed = test::run_ok(script);
  ASSERT_EQ(fixed.warnings.size(), 1U);
  EXPECT_EQ(test::line_col(fixed.warnings[0], script).substr(0, 31), "7:3: solid 'tet': face 2 was wo");
  EXPECT_EQ(test::run_ok(std::string("solid tet (fix_winding: true) {\n") + kTetraFlipped).warnings.size(),
            1U);

  const std::string error =
      test::first_error(std::string("solid tet (fix_winding: false) {\n") + kTetraFlipped);
  EXPECT_EQ(error,
            "7:3: solid 'tet': face 2 is wound clockwise seen from outside, unlike its neighbours; list its "
            "vertices in the opposite order");
}

TEST(SolidOptions, AllOptionsTogether) {
  const FrameScene scene = test::run_ok(
      ridge("(crease: 10, planarity: 0.01,\n            crossing_holes: true, fix_winding: false)"));
  ASSERT_EQ(scene.scene.objects.size(), 1U);
  EXPECT_EQ(count_kind(scene, EdgeKind::Smooth), 1U);
  EXPECT_TRUE(scene.warnings.empty());
}

// "line:col: message" and the hint of the first error.
std::pair<std::string, std::string> error_and_hint(const std::string& text) {
  const auto program = Program::from_text("test.hls", text);
  try {
    program->evaluate({});
  } catch (const EvalError& e) {
    if (!e.diagnostics.empty())
      return {test::line_col(e.diagnostics.front(), program->sources()), e.diagnostics.front().hint};
    return {e.what(), ""};
  }
  return {"<no error>", ""};
}

TEST(SolidOptions, MistakesAreErrorsAtTheOption) {
  struct Case {
    const char* options;
    const char* expected;
  };
  const Case cases[] = {
      {"(creese: 30)", "1:13: solid 'roof': unknown option 'creese'"},
      {"(smooth: 30)", "1:13: solid 'roof': unknown option 'smooth'"},
      {"(crease: 10, crease: 20)", "1:25: solid 'roof': option 'crease' is given twice"},
      {"(30)", "1:13: solid 'roof': an option needs a name, as in 'crease: 30'"},
      {"(crease: 10, true)", "1:25: solid 'roof': an option needs a name, as in 'crease: 30'"},
      {"(crease: true)", "1:13: solid 'roof': option 'crease' must be a number, got a bool"},
      {"(crease: (1, 2, 3))", "1:13: solid 'roof': option 'crease' must be a number, got a vector"},
      {"(planarity: \"0.003\")", "1:13: solid 'roof': option 'planarity' must be a number, got a string"},
      {"(crossing_holes: 1)",
       "1:13: solid 'roof': option 'crossing_holes' must be true or false, got a number"},
      {"(fix_winding: [true])", "1:13: solid 'roof': option 'fix_winding' must be true or false, got a list"},
      {"(crease: 181)", "1:13: solid 'roof': option 'crease' must be from 0 to 180 degrees (got 181)"},
      {"(crease: -1)", "1:13: solid 'roof': option 'crease' must be from 0 to 180 degrees (got -1)"},
      {"(crease: 0 / 0)", "1:25: division by zero"},
      {"(planarity: 0)", "1:13: solid 'roof': option 'planarity' must be above 0 and at most 0.05 (got 0)"},
      {"(planarity: -0.001)",
       "1:13: solid 'roof': option 'planarity' must be above 0 and at most 0.05 (got -0.001)"},
      {"(planarity: 0.06)",
       "1:13: solid 'roof': option 'planarity' must be above 0 and at most 0.05 (got 0.06)"},
      {"(crease: nope)", "1:21: unknown name 'nope'"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.options);
    const auto [error, hint] = error_and_hint(ridge(c.options));
    EXPECT_EQ(error, c.expected);
    if (error.find("solid 'roof'") == std::string::npos) continue;
    if (error.find("'creese'") != std::string::npos) {
      EXPECT_EQ(hint, std::string("did you mean 'crease'? ") + kOptionsHint);
    } else {
      EXPECT_EQ(hint, kOptionsHint);
    }
  }
}

TEST(SolidOptions, ErrorsComeBeforeTheBodyAndWithoutDrawing) {
  // The options are checked first: the broken face below is never reached.
  EXPECT_EQ(test::first_error("solid s (crease: 200) {\n  face 1 2 3\n}\n"),
            "1:10: solid 's': option 'crease' must be from 0 to 180 degrees (got 200)");
  const std::string printed = test::printed_error("solid s (planarity: 1) {}\n");
  EXPECT_NE(
      printed.find("test.hls:1:10: error: solid 's': option 'planarity' must be above 0 and at most 0.05"),
      std::string::npos)
      << printed;
  EXPECT_NE(printed.find("^" + std::string(11, '~') + "\n"), std::string::npos)
      << printed;  // the whole option
  EXPECT_NE(printed.find(std::string("hint: ") + kOptionsHint), std::string::npos) << printed;
}

}  // namespace
}  // namespace hlr::runtime
