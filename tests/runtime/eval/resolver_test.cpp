// The resolver: mistakes in code that frame 0 never runs are reported before anything runs; correct
// scripts, whatever order their functions come in, report nothing.
#include "runtime/eval/resolver.hpp"

#include <gtest/gtest.h>

#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime::test {
namespace {

// Every static error of `text`, as "line:col: message", one per line.
std::string static_errors(const std::string& text) {
  const auto program = Program::from_text("test.hls", text);
  EXPECT_TRUE(program->parsed());
  std::string out;
  for (const lang::Diagnostic& d : program->static_errors()) out += line_col(d, program->sources()) + "\n";
  return out;
}

TEST(Resolver, UnknownNameInABranchNotTaken) {
  EXPECT_EQ(static_errors("if false {\n  draw bx\n}\n"), "2:8: unknown name 'bx'\n");
}

TEST(Resolver, ReportsBeforeTheFirstFrameWhatOnlyTheLastFrameRuns) {
  const std::string text =
      "animate frames 10\n"
      "if frame == 9 {\n"
      "  draw cube(sise: 1)\n"
      "}\n";
  EXPECT_EQ(static_errors(text), "3:13: unknown argument 'sise' to cube()\n");
  // Frame 0 does not run the branch; the program still refuses to start.
  EXPECT_EQ(first_error(text), "3:13: unknown argument 'sise' to cube()");
}

TEST(Resolver, BuiltinArgumentCounts) {
  EXPECT_EQ(static_errors("def f() = box(1, 2, 3, 4)\n"),
            "1:24: too many arguments to box(): it takes at most 3, got 4\n");
  EXPECT_EQ(static_errors("if false { let c = lookat(eye: (1, 2, 3)) }\n"),
            "1:20: missing argument 'target' to lookat()\n");
  EXPECT_EQ(static_errors("if false { let i = identity(1) }\n"),
            "1:29: too many arguments to identity(): it takes no arguments, got 1\n");
  EXPECT_EQ(static_errors("if false { let s = sphere(1, r: 2) }\n"),
            "1:30: argument 'r' to sphere() is given twice\n");
}

TEST(Resolver, EveryFormOfABuiltinIsAccepted) {
  EXPECT_EQ(static_errors("let a = box(1, 2, 3)\n"
                          "let b = box(min: (0, 0, 0), max: (1, 1, 1))\n"
                          "let c = box(size: (1, 1, 1))\n"
                          "let d = translate((1, 2, 3)) then translate(1, 2, 3)\n"
                          "let e = rotate(30, axis: (0, 0, 1)) then rotate(z: 30, about: (1, 0, 0))\n"
                          "let f = min(1, 2, 3) + max([1, 2])\n"),
            "");
  // The error of the form the names point at.
  EXPECT_EQ(static_errors("let b = box(min: (0, 0, 0), mx: (1, 1, 1))\n"),
            "1:29: unknown argument 'mx' to box()\n");
}

TEST(Resolver, UserFunctionCalls) {
  const std::string def = "def g(a, b = 2) = a + b\n";
  EXPECT_EQ(static_errors(def + "let x = g(1) + g(1, 2) + g(b: 3, a: 1)\n"), "");
  EXPECT_EQ(static_errors(def + "if false { let x = g(1, 2, 3) }\n"),
            "2:28: too many arguments to g(): it takes at most 2, got 3\n");
  EXPECT_EQ(static_errors(def + "if false { let x = g(c: 1) }\n"), "2:22: unknown argument 'c' to g()\n");
}

TEST(Resolver, FunctionBodiesSeeNamesDefinedLater) {
  // Mutual recursion and helpers defined after their user run fine: the body runs when called.
  EXPECT_EQ(static_errors("def even(n) = n == 0 or odd(n - 1)\n"
                          "def odd(n) = n != 0 and even(n - 1)\n"
                          "def f() = size * 2\n"
                          "let size = 3\n"
                          "let x = f()\n"),
            "");
  // Outside functions statements run in order.
  EXPECT_EQ(static_errors("let a = b\nlet b = 1\n"), "1:9: unknown name 'b'\n");
}

TEST(Resolver, ScopesOfBlocksLoopsAndComprehensions) {
  EXPECT_EQ(static_errors("for i in 0..3 {\n"
                          "  let row = [j * i for j in 0..i if j != 1]\n"
                          "  def inner(k = i) = k + row[0]\n"
                          "}\n"
                          "solid s (crease: 30) { vertex 1 = (frame, t, time) vertex 2 = (0, 1, 0) "
                          "vertex 3 = (0, 0, 1) face 1 2 3 }\n"
                          "output \"x-{frame:03}.pdf\"\n"),
            "");
  EXPECT_EQ(
      static_errors("for i in 0..3 { let row = i }\nlet x = row\nlet y = [j for j in 0..2]\nlet z = j\n"),
      "2:9: unknown name 'row'\n4:9: unknown name 'j'\n");
  // A parameter's default sees the parameters before it, not after.
  EXPECT_EQ(static_errors("def f(a = b, b = 1) = a\n"), "1:11: unknown name 'b'\n");
}

TEST(Resolver, NamesShadowingBuiltinsAreValuesNotChecked) {
  EXPECT_EQ(static_errors("let cube = 2\nlet y = cube + 1\n"), "");
  // A call through a value: what it is is known only when it runs.
  EXPECT_EQ(static_errors("def twice(f, x) = f(f(x, 1, 2), 1, 2)\n"), "");
  EXPECT_EQ(static_errors("if false { let x = pi(2) }\n"), "1:20: 'pi' is a number, not a function\n");
}

TEST(Resolver, EachUnknownNameOnceWithAHint) {
  const auto program = Program::from_text("test.hls", "let a = sqr(2) + sqr(3)\nlet b = cylnder(1, 2)\n");
  const std::vector<lang::Diagnostic>& errors = program->static_errors();
  ASSERT_EQ(errors.size(), 2U);
  EXPECT_EQ(line_col(errors[0], program->sources()), "1:9: unknown name 'sqr'");
  EXPECT_EQ(errors[0].hint, "did you mean 'sqrt'?");
  EXPECT_EQ(line_col(errors[1], program->sources()), "2:9: unknown name 'cylnder'");
  EXPECT_EQ(errors[1].hint, "did you mean 'cylinder'?");
}

TEST(Resolver, OneLetterNamesAreHintedOnlyByCase) {
  // Every one-letter name is one edit from `t`: that is no hint. `X` for `x` is.
  auto program = Program::from_text("test.hls", "draw y\n");
  ASSERT_EQ(program->static_errors().size(), 1U);
  EXPECT_EQ(program->static_errors()[0].hint, "define it first with 'let y = ...' or 'def y(...)'");
  program = Program::from_text("test.hls", "let x = 1\ndraw X\n");
  ASSERT_EQ(program->static_errors().size(), 1U);
  EXPECT_EQ(program->static_errors()[0].hint, "did you mean 'x'?");
}

TEST(Resolver, IncludedFilesAreChecked) {
  const TempDir dir("resolver-include");
  dir.write("parts.hls", "def post(h) = box(1, 1, h)\nif false { draw bolt }\n");
  const auto main = dir.write("main.hls", "include \"parts.hls\"\ndraw post(3)\ndraw post(1, 2)\n");
  const auto program = Program::load(main, "main.hls");
  ASSERT_EQ(program->static_errors().size(), 2U);
  EXPECT_EQ(format_diagnostic(program->static_errors()[0], program->sources()).substr(0, 42),
            "parts.hls:2:17: error: unknown name 'bolt'");
  EXPECT_EQ(line_col(program->static_errors()[1], program->sources()),
            "3:14: too many arguments to post(): it takes at most 1, got 2");
}

TEST(Resolver, AMissingIncludeIsLeftToTheEvaluator) {
  EXPECT_EQ(static_errors("include \"nowhere.hls\"\ndraw cube(1)\n"), "");
  // The names it would have defined are not reported: the missing file is the mistake.
  EXPECT_EQ(static_errors("include \"nowhere.hls\"\ndraw carrier\nlet b = box(1, 2, 3, 4)\n"),
            "3:22: too many arguments to box(): it takes at most 3, got 4\n");
  EXPECT_EQ(first_error("include \"nowhere.hls\"\ndraw carrier\n").substr(0, 30),
            "1:9: cannot read 'nowhere.hls'");
}

}  // namespace
}  // namespace hlr::runtime::test
