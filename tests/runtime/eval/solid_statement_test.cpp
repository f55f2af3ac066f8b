// solid NAME { ... }: items to hlr::SolidBuilder, builder diagnostics back at the items' spans, warnings
// kept with the frame.
#include <gtest/gtest.h>

#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

const char* kTetra =
    "solid tet {\n"
    "  vertex a = (0, 0, 0)\n"
    "  vertex b = (1, 0, 0)\n"
    "  vertex c = (0, 1, 0)\n"
    "  vertex d = (0, 0, 1)\n"
    "  face a c b\n"
    "  face a b d\n"
    "  face b c d\n"
    "  face c a d\n"
    "}\n";

TEST(SolidStatement, DeclaresWithoutDrawing) {
  const FrameScene scene = test::run_ok(kTetra);
  EXPECT_TRUE(scene.scene.objects.empty());
  const FrameScene drawn = test::run_ok(std::string(kTetra) + "draw tet\ndraw tet at translate(5, 0, 0)");
  ASSERT_EQ(drawn.scene.objects.size(), 2U);
  EXPECT_EQ(drawn.scene.objects[0].name, "tet");
  EXPECT_EQ(drawn.scene.objects[1].name, "tet#2");
  EXPECT_EQ(drawn.scene.objects[0].solid->faces.size(), 4U);
  EXPECT_TRUE(drawn.scene.objects[0].solid->closed);
  EXPECT_EQ(drawn.scene.objects[1].solid->vertices[1], (Point3{6, 0, 0}));
}

TEST(SolidStatement, PositionsAreExpressionsAndIdsAreNumbersOrNames) {
  const FrameScene scene = test::run_ok(
      "let h = 2\n"
      "solid wedge {\n"
      "  vertex 1 = (0, 0, 0)\n  vertex 2 = (2, 0, 0)\n  vertex 3 = (0, 2, 0)\n"
      "  vertex top = (0, 0, h)\n"
      "  face 1 3 2\n  face 1 2 top\n  face 2 3 top\n  face 3 1 top\n"
      "  line 1 top\n"
      "}\n"
      "draw wedge");
  ASSERT_EQ(scene.scene.objects.size(), 1U);
  EXPECT_EQ(scene.scene.objects[0].solid->vertices[3], (Point3{0, 0, 2}));
}

TEST(SolidStatement, FacesWithHoles) {
  // A 4 x 4 x 1 plate with a 2 x 2 square hole through it.
  const FrameScene scene = test::run_ok(
      "solid plate {\n"
      "  vertex 1 = (0, 0, 0)\n  vertex 2 = (4, 0, 0)\n  vertex 3 = (4, 4, 0)\n  vertex 4 = (0, 4, 0)\n"
      "  vertex 5 = (0, 0, 1)\n  vertex 6 = (4, 0, 1)\n  vertex 7 = (4, 4, 1)\n  vertex 8 = (0, 4, 1)\n"
      "  vertex 11 = (1, 1, 0)\n  vertex 12 = (3, 1, 0)\n  vertex 13 = (3, 3, 0)\n  vertex 14 = (1, 3, 0)\n"
      "  vertex 15 = (1, 1, 1)\n  vertex 16 = (3, 1, 1)\n  vertex 17 = (3, 3, 1)\n  vertex 18 = (1, 3, 1)\n"
      "  face 5 6 7 8 hole 18 17 16 15\n"
      "  face 1 4 3 2 hole 11 12 13 14\n"
      "  face 1 2 6 5\n  face 2 3 7 6\n  face 3 4 8 7\n  face 4 1 5 8\n"
      "  face 11 15 16 12\n  face 12 16 17 13\n  face 13 17 18 14\n  face 14 18 15 11\n"
      "}\n"
      "draw plate");
  ASSERT_EQ(scene.scene.objects.size(), 1U);
  EXPECT_EQ(scene.scene.objects[0].solid->faces.size(), 10U);
  EXPECT_EQ(scene.scene.objects[0].solid->faces[0].rings.size(), 2U);
  EXPECT_TRUE(scene.scene.objects[0].solid->closed);
}

TEST(SolidStatement, BuilderErrorsPointAtTheirItems) {
  const std::string unknown =
      test::first_error("solid s {\n  vertex 1 = (0, 0, 0)\n  vertex 2 = (1, 0, 0)\n  face 1 2 9\n}");
  EXPECT_EQ(unknown.substr(0, 23), "4:3: solid 's': face 1 ") << unknown;
  EXPECT_NE(unknown.find("'9'"), std::string::npos) << unknown;
  const std::string dup = test::first_error("solid s {\n  vertex 1 = (0, 0, 0)\n  vertex 1 = (1, 0, 0)\n}");
  EXPECT_EQ(dup.substr(0, 17), "3:3: solid 's': v") << dup;
  const std::string warped = test::first_error(
      "solid s {\n  vertex 1 = (0, 0, 0)\n  vertex 2 = (1, 0, 0)\n  vertex 3 = (1, 1, 0.5)\n"
      "  vertex 4 = (0, 1, 0)\n  face 1 2 3 4\n}");
  EXPECT_EQ(warped.substr(0, 4), "6:3:") << warped;
  EXPECT_NE(warped.find("planar"), std::string::npos) << warped;
  EXPECT_EQ(test::first_error("solid s {\n  vertex 1 = 5\n}"),
            "2:14: vertex 1 needs a position vector, got a number");
}

TEST(SolidStatement, AllBuilderErrorsAreReportedTogether) {
  const auto program = Program::from_text(
      "test.hls", "solid s {\n  vertex 1 = (0, 0, 0)\n  vertex 2 = (1, 0, 0)\n  face 1 2 8\n  face 2 1 9\n}");
  try {
    program->evaluate({});
    FAIL() << "no error";
  } catch (const EvalError& e) {
    ASSERT_GE(e.diagnostics.size(), 2U);
    EXPECT_EQ(test::line_col(e.diagnostics[0], program->sources()).substr(0, 2), "4:");
    EXPECT_EQ(test::line_col(e.diagnostics[1], program->sources()).substr(0, 2), "5:");
  }
}

TEST(SolidStatement, WarningsDoNotFail) {
  // Face 2 is wound against its neighbours: reversed, with a warning at its item.
  const std::string script =
      std::string(kTetra).replace(std::string(kTetra).find("face a b d"), 10, "face a d b");
  const FrameScene scene = test::run_ok(script + "draw tet");
  ASSERT_EQ(scene.scene.objects.size(), 1U);
  ASSERT_EQ(scene.warnings.size(), 1U);
  EXPECT_EQ(scene.warnings[0].severity, lang::Severity::Warning);
  EXPECT_EQ(test::line_col(scene.warnings[0], script).substr(0, 23), "7:3: solid 'tet': face ");
}

TEST(SolidStatement, ThesisStyleLoopsWithBridges) {
  // One loop walks the outer square, bridges 1 → 5 into the hole, walks it and bridges back: the
  // doubled edge 1–5 is a line on the face, not a boundary.
  const FrameScene scene = test::run_ok(
      "solid plate {\n"
      "  vertex 1 = (0, 0, 0)\n  vertex 2 = (4, 0, 0)\n  vertex 3 = (4, 4, 0)\n  vertex 4 = (0, 4, 0)\n"
      "  vertex 5 = (1, 1, 0)\n  vertex 6 = (3, 1, 0)\n  vertex 7 = (3, 3, 0)\n  vertex 8 = (1, 3, 0)\n"
      "  face 1 2 3 4 1 5 8 7 6 5\n"
      "}\n"
      "draw plate");
  ASSERT_EQ(scene.scene.objects.size(), 1U);
  ASSERT_EQ(scene.scene.objects[0].solid->faces.size(), 1U);
  EXPECT_EQ(scene.scene.objects[0].solid->faces[0].rings.size(), 2U);
}

}  // namespace
}  // namespace hlr::runtime
