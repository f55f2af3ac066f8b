// `style hidden levels N [pen P]`: what the evaluator puts into the FrameScene, and every bad number of
// levels or pen as an error at its place.
#include <gtest/gtest.h>

#include <string>

#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

TEST(HiddenLevels, TheNumberOfLevelsAndThePen) {
  const FrameScene three = test::run_ok("style hidden levels 3");
  EXPECT_EQ(three.hidden, HiddenStyle::counted(3));
  EXPECT_FALSE(three.hidden_pen);
  ASSERT_TRUE(three.hidden_span);
  const FrameScene named = test::run_ok("let n = 2\nstyle hidden levels n + 1 pen 4");
  EXPECT_EQ(named.hidden, HiddenStyle::counted(3));
  EXPECT_EQ(named.hidden_pen, 4);
  EXPECT_EQ(test::run_ok("style hidden levels (16)").hidden, HiddenStyle::counted(16));
  // The last level's pen is the last pen: 240 + 16 − 1 = 255.
  EXPECT_EQ(test::run_ok("style hidden levels 16 pen 240").hidden_pen, 240);
  EXPECT_EQ(test::run_ok("style hidden off").hidden, HiddenStyle::off());
  EXPECT_FALSE(test::run_ok("draw cube(1)").hidden);
}

TEST(HiddenLevels, LevelsIsAWordOnlyAfterStyleHidden) {
  const FrameScene scene = test::run_ok("let levels = 2\nstyle hidden levels levels\nlet dashed = levels");
  EXPECT_EQ(scene.hidden, HiddenStyle::counted(2));
}

struct Case {
  const char* script;
  const char* expected;  // line:col: message
};

// clang-format off
const Case kLevelErrors[] = {
  {"style hidden levels 0", "1:21: the number of levels must be a whole number from 1 to 16, got 0"},
  {"style hidden levels 17", "1:21: the number of levels must be a whole number from 1 to 16, got 17"},
  {"style hidden levels 2.5", "1:21: the number of levels must be a whole number from 1 to 16, got 2.5"},
  {"style hidden levels -1", "1:21: the number of levels must be a whole number from 1 to 16, got -1"},
  {"style hidden levels \"3\"", "1:21: the number of levels must be a number, got a string"},
  {"let n = [1]\nstyle hidden levels n", "2:21: the number of levels must be a number, got a list"},
  {"style hidden levels m", "1:21: unknown name 'm'"},
  {"style hidden levels 2 pen 0", "1:27: the pen number must be a whole number from 1 to 255, got 0"},
  {"style hidden levels 3 pen 254",
   "1:23: levels 1..3 from pen 254 need pens up to 256, past the last pen, 255"},
  {"style hidden levels 16 pen 241",
   "1:24: levels 1..16 from pen 241 need pens up to 256, past the last pen, 255"},
  {"style hidden levels 2\nstyle hidden dashed", "2:1: 'style hidden' is already set"},
  {"style hidden dashed\nstyle hidden levels 2", "2:1: 'style hidden' is already set"},
};
// clang-format on

TEST(HiddenLevels, Errors) {
  for (const Case& c : kLevelErrors) EXPECT_EQ(test::first_error(c.script), c.expected) << c.script;
  const std::string overflow = test::printed_error("style hidden levels 3 pen 254");
  EXPECT_NE(overflow.find("hint: level k is drawn in pen P + k - 1: start from pen 253 or lower"),
            std::string::npos)
      << overflow;
  const std::string twice = test::printed_error("style hidden levels 2\nstyle hidden levels 3");
  EXPECT_NE(twice.find("test.hls:1:1: note: it was set here"), std::string::npos) << twice;
}

}  // namespace
}  // namespace hlr::runtime
