// The timeline built-ins from scripts: track() at the frame drawn or at `time:`, easing and spline names
// with their errors, spline(), follow(), and `frames` bound in every frame — frame 0 included.
#include <gtest/gtest.h>

#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime::test {
namespace {

// str() of the top-level `x` after evaluating `text` at `time`.
std::string x_at(const std::string& text, FrameTime time = {}) {
  const auto program = Program::from_text("test.hls", text);
  std::string shown;
  try {
    program->evaluate(time, [&](const Evaluator& e) { shown = display(*e.global("x"), 1000); });
  } catch (const EvalError& e) {
    return "error: " + line_col(e.diagnostics.front(), program->sources());
  }
  return shown;
}

TEST(Animation, TrackAtTheFrameDrawnOrAtAGivenTime) {
  const std::string track = "let x = track([[0, 0], [10, 100], [20, 0, \"step\"], [30, 50]]";
  EXPECT_EQ(x_at(track + ")\n", frame_time(5, 31, 24)), "50");
  EXPECT_EQ(x_at(track + ")\n", frame_time(25, 31, 24)), "0");  // the step holds key 2's value
  EXPECT_EQ(x_at(track + ")\n", frame_time(30, 31, 24)), "50");
  EXPECT_EQ(x_at(track + ", time: 2.5)\n"), "25");
  EXPECT_EQ(x_at(track + ", time: 15, ease: \"in_quad\")\n"), "75");  // 100 − 100 · 0.5²
  EXPECT_EQ(x_at("let x = track([[0, (0, 0, 0)], [4, (4, 8, 0)]], time: 1)\n"), "(1, 2, 0)");
  EXPECT_EQ(x_at("let x = track([[0, 0], [1, 1], [2, 0]], time: 0.5, spline: \"natural\")\n"), "0.6875");
  EXPECT_EQ(x_at("let x = ease(\"in_cubic\", 0.5)\n"), "0.125");
  EXPECT_EQ(x_at("let x = spline([(0, 0), (10, 0), (10, 10)], 0.75, kind: \"linear\")\n"), "(10, 5, 0)");
}

TEST(Animation, MistakesAreErrorsAtTheArgument) {
  EXPECT_EQ(x_at("let x = track([[0, 0], [1, 1]], time: 0, ease: \"in_out_cubc\")\n").substr(0, 111),
            "error: 1:48: bad argument 'ease' to track(): unknown easing \"in_out_cubc\"; did you mean "
            "'in_out_cubic'? "
            "(one of");
  EXPECT_EQ(
      x_at("let x = track([[0, 0], [1, (1, 1, 1)]], time: 0)\n"),
      "error: 1:15: bad argument 'keys' to track(): key 1's value is a vector; a track's values are all "
      "numbers");
  EXPECT_EQ(x_at("let x = track([[0, 0], [0, 1]], time: 0)\n"),
            "error: 1:15: bad argument 'keys' to track(): key 1 must come after key 0: key times increase");
  EXPECT_EQ(
      x_at("let x = track([[0, 0, 1, 2]], time: 0)\n"),
      "error: 1:15: bad argument 'keys' to track(): key 0 has 4 items; a key is [time, value] or [time, "
      "value, \"easing\"]");
  EXPECT_EQ(x_at("let x = spline([(0, 0, 0)], 0.5, kind: \"bezier\")\n"),
            "error: 1:40: bad argument 'kind' to spline(): unknown spline \"bezier\" (linear, catmull_rom or "
            "natural)");
  EXPECT_EQ(x_at("camera c = follow([(1, 1, 1), (1, 1, 1)], 0.5)\nlet x = 1\n"),
            "error: 1:19: bad argument 'path' to follow(): does not move at t = 0.5");
}

TEST(Animation, FollowIsACamera) {
  const FrameScene scene =
      run_ok("camera c = follow([(0, 0, 10), (100, 0, 10), (200, 50, 10)], 0.5, bank: 15)\n");
  ASSERT_EQ(scene.cameras.size(), 1U);
  EXPECT_EQ(scene.cameras[0].camera.kind, "follow");
}

TEST(Animation, FramesIsTheSequenceLengthInEveryFrame) {
  const auto program = Program::from_text("test.hls", "animate frames 48 fps 12\nlet x = frames - 1\n");
  std::string shown;
  program->evaluate_first_frame([&](const Evaluator& e) { shown = display(*e.global("x"), 100); });
  EXPECT_EQ(shown, "47");
  EXPECT_EQ(x_at("animate frames 48 fps 12\nlet x = frames - 1\n", frame_time(30, 48, 12)), "47");
}

}  // namespace
}  // namespace hlr::runtime::test
