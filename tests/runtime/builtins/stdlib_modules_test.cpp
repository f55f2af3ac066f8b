// Library modules written in hlrscript (stdlib/modules/, `include "std/NAME.hls"`): each module loads and
// its functions build what they promise; a missing module is an input error that says where modules live.
#include <gtest/gtest.h>

#include "tests/runtime/cli_run.hpp"
#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

TEST(StdlibModules, GearsFastenersAndBuildingsBuild) {
  const FrameScene scene = test::run_ok(
      "include \"std/gears.hls\"\ninclude \"std/fasteners.hls\"\ninclude \"std/buildings.hls\"\n"
      "draw gear(20, 2, 6, 4)\n"
      "draw gear(12, 2, 6)\n"
      "draw hex_nut(8)\n"
      "draw bolt(8, 40)\n"
      "draw house(8, 6, 4, 3)\n"
      "camera c = orbit()\n");
  ASSERT_EQ(scene.scene.objects.size(), 6U);  // two gears, the nut, the bolt (head and shank), the house
  // A gear of n teeth without a bore: top, bottom and one side face per outline edge (4 per tooth).
  const Solid& plain = *scene.scene.objects[1].solid;
  EXPECT_EQ(plain.faces.size(), 12U * 4U + 2U);
  EXPECT_TRUE(plain.closed);
  // With a key-wayed bore: 80 outline sides, 3 key-way corners + 22 arc points in the hole.
  const Solid& bored = *scene.scene.objects[0].solid;
  EXPECT_EQ(bored.faces.size(), 20U * 4U + 25U + 2U);
  // The nut: hexagon outside, 12-gon bore.
  EXPECT_EQ(scene.scene.objects[2].solid->faces.size(), 6U + 12U + 2U);
  // The house: a pentagonal gable prism.
  EXPECT_EQ(scene.scene.objects[5].solid->faces.size(), 5U + 2U);
}

TEST(StdlibModules, MissingModuleSaysWhereModulesLive) {
  const auto program = Program::from_text("test.hls", "include \"std/nope.hls\"\n");
  try {
    program->evaluate({});
    ADD_FAILURE() << "no error";
  } catch (const EvalError& e) {
    EXPECT_EQ(e.kind, ErrorKind::Input);
    ASSERT_FALSE(e.diagnostics.empty());
    EXPECT_EQ(test::line_col(e.diagnostics[0], program->sources()).substr(0, 4), "1:9:");
    EXPECT_NE(e.diagnostics[0].hint.find("the library modules: std/buildings.hls, std/fasteners.hls, "
                                         "std/gears.hls (in "),
              std::string::npos)
        << e.diagnostics[0].hint;
  }
}

// `hlrscript help NAME` knows the modules' functions: the signature as written, the module to include and
// the comment above the def; a misspelt one gets a "did you mean".
TEST(StdlibModules, HelpKnowsTheModulesFunctions) {
  const test::CliResult gear = test::run({"help", "gear"});
  EXPECT_EQ(gear.code, 0) << gear.err;
  EXPECT_EQ(gear.out.rfind("gear(teeth, m, thickness, bore = 0, key = true)   (library module std/gears.hls: "
                           "include \"std/gears.hls\" first)\n  A gear of `teeth` teeth",
                           0),
            0U)
      << gear.out;
  const test::CliResult nut = test::run({"help", "hex_nut"});
  EXPECT_NE(nut.out.find("std/fasteners.hls"), std::string::npos) << nut.out;
  const test::CliResult typo = test::run({"help", "gearz"});
  EXPECT_NE(typo.code, 0);
  EXPECT_NE(typo.err.find("did you mean 'gear'?"), std::string::npos) << typo.err;
}

}  // namespace
}  // namespace hlr::runtime
