// The evaluator's semantics: let, lexical scopes, closures, recursion, named and default parameters,
// block functions with return, if/else, for over ranges and lists, functions as values, frame globals.
#include <gtest/gtest.h>

#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

using test::value;

TEST(Evaluator, LetAndBlocksAreLexicallyScoped) {
  EXPECT_EQ(value("x", "let x = 1\nif true { let x = 2 }"), "1");
  EXPECT_EQ(value("g()", "let x = 1\ndef f() = x\ndef g() {\n  let x = 2\n  return f()\n}"), "1");
  EXPECT_EQ(value("y", "let x = 2\nlet y = x * x"), "4");
}

TEST(Evaluator, ClosuresKeepTheirDefiningScope) {
  const char* make =
      "def make(k) {\n  def add(x) = x + k\n  return add\n}\nlet add2 = make(2)\nlet add5 = make(5)";
  EXPECT_EQ(value("add2(3)", make), "5");
  EXPECT_EQ(value("add5(3)", make), "8");
  EXPECT_EQ(value("add2(add5(0))", make), "7");
}

TEST(Evaluator, ClosuresInLoopsCaptureTheirIteration) {
  // Each iteration has its own scope, so `i` inside the closure is that iteration's.
  const char* script =
      "def pick(n) {\n"
      "  for i in 0..10 {\n"
      "    def get() = i\n"
      "    if i == n { return get }\n"
      "  }\n"
      "}\n";
  EXPECT_EQ(value("pick(3)()", script), "3");
  EXPECT_EQ(value("pick(7)()", script), "7");
}

TEST(Evaluator, Recursion) {
  const char* fact = "def fact(n) {\n  if n <= 1 { return 1 }\n  return n * fact(n - 1)\n}";
  EXPECT_EQ(value("fact(10)", fact), "3628800");
  const char* squares =
      "def squares(i, n) {\n  if i >= n { return [] }\n  return [i * i] + squares(i + 1, n)\n}";
  EXPECT_EQ(value("squares(0, 5)", squares), "[0, 1, 4, 9, 16]");
  // Mutual recursion: names are looked up when called, so a later def is visible.
  const char* parity =
      "def even(n) {\n  if n == 0 { return true }\n  return odd(n - 1)\n}\n"
      "def odd(n) {\n  if n == 0 { return false }\n  return even(n - 1)\n}";
  EXPECT_EQ(value("even(10)", parity), "true");
  EXPECT_EQ(value("odd(7)", parity), "true");
}

TEST(Evaluator, NamedAndDefaultParameters) {
  const char* f = "def f(a, b = a * 2, c = 10) = a + b + c";
  EXPECT_EQ(value("f(1)", f), "13");
  EXPECT_EQ(value("f(1, 5)", f), "16");
  EXPECT_EQ(value("f(b: 1, a: 2)", f), "13");
  EXPECT_EQ(value("f(1, c: 0)", f), "3");
  EXPECT_EQ(value("f(1, 2, 3)", f), "6");
}

TEST(Evaluator, BlockFunctionsReturn) {
  EXPECT_EQ(value("f(5)", "def f(x) {\n  let y = x + 1\n  return y * 2\n}"), "12");
  EXPECT_EQ(value("f()", "def f() {\n  return\n}"), "none");
  EXPECT_EQ(value("f()", "def f() {\n  let unused = 1\n}"), "none");
  // return leaves nested loops and ifs at once
  EXPECT_EQ(
      value("first_over(10)",
            "def first_over(n) {\n  for i in 0..100 {\n    if i * i > n { return i }\n  }\n  return -1\n}"),
      "4");
}

TEST(Evaluator, IfElseChains) {
  const char* sign =
      "def sign(x) {\n  if x < 0 { return -1 } else if x == 0 { return 0 } else { return 1 }\n}";
  EXPECT_EQ(value("[sign(-3), sign(0), sign(2)]", sign), "[-1, 0, 1]");
}

TEST(Evaluator, ForWalksRangesAndLists) {
  const char* sum =
      "def sum(xs, i = 0) {\n  if i >= len(xs) { return 0 }\n  return xs[i] + sum(xs, i + 1)\n}\n"
      "def count_to(n) {\n  for i in 0..n {\n    if i == n - 1 { return i }\n  }\n}";
  EXPECT_EQ(value("sum([1, 2, 3, 4])", sum), "10");
  EXPECT_EQ(value("count_to(5)", sum), "4");
  const FrameScene scene = test::run_ok("for p in [(0, 0, 0), (5, 0, 0)] { draw cube(1) at translate(p) }");
  ASSERT_EQ(scene.scene.objects.size(), 2U);
  EXPECT_EQ(scene.scene.objects[1].solid->vertices[0].x, 4.5);
}

TEST(Evaluator, FunctionsAreValues) {
  const char* twice = "def twice(f, x) = f(f(x))\ndef inc(x) = x + 1";
  EXPECT_EQ(value("twice(inc, 1)", twice), "3");
  EXPECT_EQ(value("twice(sqrt, 16)", twice), "2");
  EXPECT_EQ(value("[inc, sqrt][1](9)", twice), "3");
}

TEST(Evaluator, ScriptsMayShadowBuiltins) {
  EXPECT_EQ(value("box(3)", "def box(a) = a * 2"), "6");
  EXPECT_EQ(value("pi", "let pi = 3"), "3");
  EXPECT_EQ(value("round(pi * 1000)"), "3142");
}

TEST(Evaluator, FrameGlobals) {
  const FrameTime time{3, 0.75, 0.125};
  const FrameScene scene = test::run_ok("output \"f{frame}-t{t}-s{time}.pdf\"", time);
  ASSERT_TRUE(scene.output);
  EXPECT_EQ(scene.output->name, "f3-t0.75-s0.125.pdf");
  EXPECT_TRUE(scene.output->interpolated);
  // A script may define its own t inside its top level (a scope below the frame globals).
  EXPECT_EQ(value("t", "let t = 5"), "5");
}

TEST(Evaluator, ClosureCyclesAreReleased) {
  // A def stores the function in the scope its closure points to; the evaluator must break that cycle
  // (LeakSanitizer checks this test under HLR_SANITIZE).
  EXPECT_EQ(value("f(3)", "def f(n) {\n  def g(m) = m + n\n  return g(1)\n}"), "4");
}

}  // namespace
}  // namespace hlr::runtime
