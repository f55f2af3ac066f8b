// --levels N: hidden lines by occlusion level from the command line — the range, its exclusion with
// --hidden, the usage text, overriding the script's style while keeping its hidden pen, and a last
// level's pen past the last pen reported at the script's style statement.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/runtime/cli_run.hpp"
#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

using test::run;

const char* kCube =
    "draw cube(1)\n"
    "camera main = lookat(eye: (4, -5, 3), target: (0.5, 0.5, 0.5))\n";

TEST(LevelsOption, BadValuesAreUsageErrorsNamingTheRange) {
  for (const char* bad : {"0", "17", "2.5", "-1", "x", "", "3x", "100000000000"}) {
    const test::CliResult r = run({"a.hls", "--levels", bad});
    EXPECT_EQ(r.code, 64) << bad;
    EXPECT_NE(r.err.find("--levels " + std::string(bad) + ": expected a whole number from 1 to 16"),
              std::string::npos)
        << r.err;
  }
}

TEST(LevelsOption, ExcludesHidden) {
  for (const char* hidden : {"off", "dashed"}) {
    const test::CliResult r = run({"a.hls", "--levels", "2", "--hidden", hidden});
    EXPECT_EQ(r.code, 64);
    EXPECT_NE(r.err.find("--hidden and --levels exclude each other"), std::string::npos) << r.err;
  }
}

TEST(LevelsOption, InTheUsageText) {
  const test::CliResult help = run({"--help"});
  EXPECT_NE(help.out.find("--levels N"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("[--hidden off|dashed | --levels N]"), std::string::npos) << help.out;
}

TEST(LevelsOption, OverridesTheScriptsStyleAndListsLevelsInJson) {
  const test::TempDir dir("runtime-levels-option");
  const std::string script = dir.write("scene.hls", std::string("style hidden off\n") + kCube).string();
  const std::filesystem::path json = dir.path() / "out.json";
  for (const char* n : {"1", "16"}) {
    const test::CliResult r = run({script, "-o", json.string(), "--levels", n});
    ASSERT_EQ(r.code, 0) << r.err;
    const nlohmann::json frame = nlohmann::json::parse(test::read_text(json))["frames"][0];
    // The levels' members are there (whatever the engine finds hidden): the script's `off` is overridden.
    EXPECT_TRUE(frame.contains("hidden_stroke_levels")) << n;
    EXPECT_EQ(frame["hidden_stroke_levels"].size(), frame["hidden_strokes"].size());
    for (const nlohmann::json& s : frame["segments"])
      if (s["hidden"].get<bool>()) {
        EXPECT_GE(s["level"].get<int>(), 1);
        EXPECT_LE(s["level"].get<int>(), std::stoi(n));
      }
  }
  // --hidden dashed: no levels.
  ASSERT_EQ(run({script, "-o", json.string(), "--hidden", "dashed"}).code, 0);
  EXPECT_FALSE(nlohmann::json::parse(test::read_text(json))["frames"][0].contains("hidden_stroke_levels"));
}

TEST(LevelsOption, KeepsTheScriptsHiddenPenWhoseLastLevelMustExist) {
  const test::TempDir dir("runtime-levels-pen");
  const std::string script =
      dir.write("scene.hls", std::string("style hidden dashed pen 250\n") + kCube).string();
  EXPECT_EQ(run({"check", script, "--levels", "6"}).code, 0);  // pens 250..255
  const std::filesystem::path out = dir.path() / "out.svg";
  const test::CliResult r = run({script, "-o", out.string(), "--levels", "7"});
  EXPECT_EQ(r.code, 65);
  EXPECT_NE(r.err.find("scene.hls:1:1: error: --levels 7 from this hidden pen 250 needs pens up to 256"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(run({"check", script, "--levels", "7"}).code, 65);
}

}  // namespace
}  // namespace hlr::runtime
