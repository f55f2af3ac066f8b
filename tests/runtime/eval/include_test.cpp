// include "file.hls": relative to the including file, each file once per evaluation, cycles and missing
// files as errors at the include, and diagnostics that name the file they are in.
#include <gtest/gtest.h>

#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

TEST(Include, RelativeToTheIncludingFileAndOncePerEvaluation) {
  const test::TempDir dir("runtime-include");
  dir.write("lib/shapes.hls", "include \"more/posts.hls\"\ndef slab(w) = box(w, w, 0.5)\n");
  dir.write("lib/more/posts.hls", "def post(h) = prism(regular(6, 0.5), h)\ndraw post(1)\n");
  const auto main = dir.write("scene.hls",
                              "include \"lib/shapes.hls\"\n"
                              "include \"lib/more/posts.hls\"\n"  // already included: nothing happens
                              "draw slab(3)\n"
                              "camera c = orbit()\n");
  const auto program = Program::load(main, "scene.hls");
  ASSERT_TRUE(program->parsed());
  const FrameScene scene = program->evaluate({});
  ASSERT_EQ(scene.scene.objects.size(), 2U);
  EXPECT_EQ(scene.scene.objects[0].name, "prism");
  EXPECT_EQ(scene.scene.objects[1].name, "box");
  // Each file has its own id and name.
  EXPECT_EQ(program->sources().file(1)->name(), "lib/shapes.hls");
  EXPECT_EQ(program->sources().file(2)->name(), "lib/more/posts.hls");
}

// A one-frame run frees the trees of the script and its includes before the hidden lines: the text
// stays (messages still quote their lines), evaluating again is refused.
TEST(Include, ReleasingTheSyntaxKeepsTheText) {
  const test::TempDir dir("runtime-include-release");
  dir.write("lib.hls", "def slab(w) = box(w, w, 0.5)\n");
  const auto program = Program::load(
      dir.write("scene.hls", "include \"lib.hls\"\ndraw slab(3)\ncamera c = orbit()\n"), "scene.hls");
  const FrameScene scene = program->evaluate({});
  ASSERT_EQ(scene.scene.objects.size(), 1U);
  program->release_syntax();
  EXPECT_FALSE(program->sources().entry(0)->script.has_value());
  EXPECT_FALSE(program->sources().entry(1)->script.has_value());
  EXPECT_EQ(program->sources().file(1)->line_text(1), "def slab(w) = box(w, w, 0.5)");
  const lang::Diagnostic d{lang::Severity::Warning, scene.cameras.at(0).span, "a note on the camera", "", {}};
  EXPECT_NE(format_diagnostic(d, program->sources()).find("camera c = orbit()"), std::string::npos);
  EXPECT_THROW(program->evaluate({}), std::logic_error);
  EXPECT_EQ(scene.scene.objects[0].solid->faces.size(), 6U) << "the frame's solids outlive the tree";
}

std::string printed(const Program& program) {
  try {
    program.evaluate({});
  } catch (const EvalError& e) {
    std::string out;
    for (const auto& d : e.diagnostics) out += format_diagnostic(d, program.sources());
    return out;
  }
  return "<no error>";
}

TEST(Include, ErrorsNameTheIncludedFile) {
  const test::TempDir dir("runtime-include-errors");
  dir.write("lib/bad.hls", "def f(x) = x\nlet y = f(1, 2)\n");
  dir.write("lib/syntax.hls", "let = 3\n");
  const auto program = Program::load(dir.write("a.hls", "let a = 1\ninclude \"lib/bad.hls\"\n"), "a.hls");
  const std::string shown = printed(*program);
  EXPECT_EQ(shown.substr(0, shown.find('\n')),
            "lib/bad.hls:2:14: error: too many arguments to f(): it takes at most 1, got 2");
  const auto syntax = Program::load(dir.write("b.hls", "include \"lib/syntax.hls\"\n"), "b.hls");
  EXPECT_EQ(printed(*syntax).substr(0, 24), "lib/syntax.hls:1:5: erro");
}

TEST(Include, CallsIntoIncludedFunctionsNoteBothFiles) {
  const test::TempDir dir("runtime-include-calls");
  dir.write("lib.hls", "def inverse(x) = 1 / x\n");
  const auto program =
      Program::load(dir.write("main.hls", "include \"lib.hls\"\nlet y = inverse(0)\n"), "main.hls");
  const std::string shown = printed(*program);
  EXPECT_NE(shown.find("lib.hls:1:22: error: division by zero"), std::string::npos) << shown;
  EXPECT_NE(shown.find("main.hls:2:9: note: in the call of 'inverse' here"), std::string::npos) << shown;
}

TEST(Include, MissingFilesAndCycles) {
  const test::TempDir dir("runtime-include-cycles");
  const auto missing = Program::load(dir.write("m.hls", "include \"nope.hls\"\n"), "m.hls");
  try {
    missing->evaluate({});
    FAIL();
  } catch (const EvalError& e) {
    EXPECT_EQ(e.kind, ErrorKind::Input);  // exit 66
    EXPECT_EQ(test::line_col(e.diagnostics.front(), missing->sources()),
              "1:9: cannot read 'nope.hls': No such file or directory");
  }
  dir.write("b.hls", "include \"c.hls\"\n");
  dir.write("c.hls", "include \"b.hls\"\n");
  const auto cycle = Program::load(dir.write("a.hls", "include \"b.hls\"\n"), "a.hls");
  try {
    cycle->evaluate({});
    FAIL();
  } catch (const EvalError& e) {
    EXPECT_EQ(e.kind, ErrorKind::Script);
    EXPECT_EQ(e.diagnostics.front().message, "include cycle: a.hls → b.hls → c.hls → b.hls");
  }
}

TEST(Include, DeepChainsHitTheLimit) {
  const test::TempDir dir("runtime-include-depth");
  for (int i = 0; i < 100; ++i)
    dir.write("f" + std::to_string(i) + ".hls", "include \"f" + std::to_string(i + 1) + ".hls\"\n");
  dir.write("f100.hls", "let end = 1\n");
  const auto program = Program::load(dir.path() / "f0.hls", "f0.hls");
  try {
    program->evaluate({});
    FAIL();
  } catch (const EvalError& e) {
    EXPECT_EQ(e.diagnostics.front().message, "too many nested includes (the limit is 32)");
  }
}

}  // namespace
}  // namespace hlr::runtime
