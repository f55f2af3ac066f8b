// Runaway scripts stop at the limits of LANGUAGE_SPEC.md with a clear error at the offending span, never
// a crash, a hang or an exhausted memory.
#include <gtest/gtest.h>

#include "runtime/values/budget.hpp"
#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

TEST(Limits, CallDepth) {
  EXPECT_EQ(test::first_error("def f(n) = f(n + 1)\nlet x = f(0)"),
            "1:12: too many nested calls (the limit is 256; --limit calls=N raises it)");
  // 255 nested calls are fine.
  EXPECT_EQ(test::value("down(254)", "def down(n) {\n  if n == 0 { return 0 }\n  return down(n - 1)\n}"),
            "0");
  // Deep recursion through block functions with nested blocks and long expressions stays an error too.
  EXPECT_EQ(test::first_error(
                "def f(n) {\n  if true {\n    for i in 0..1 {\n      return 1 + (1 + (1 + f(n + 1)))\n"
                "    }\n  }\n}\nlet x = f(0)"),
            "4:28: too many nested calls (the limit is 256; --limit calls=N raises it)");
}

// Deep native recursion: every call nested in blocks and a long expression, 256 calls deep. It must end
// in the call-depth error, with the stack to spare. (AddressSanitizer's frames are ~15 times larger: at
// full depth this uses 325 MB of the 512 MB stack there, fine, but ASan reports false positives when an
// exception unwinds more than 64 MB of stack, google/sanitizers#189; so it gets a shallower script.)
#if defined(__SANITIZE_ADDRESS__)  // gcc's way of saying so
#define HLR_TEST_ASAN 1
#elif defined(__has_feature)  // clang's
#if __has_feature(address_sanitizer)
#define HLR_TEST_ASAN 1
#endif
#endif
TEST(Limits, DeepNestingStaysOnTheStack) {
#if defined(HLR_TEST_ASAN)
  const int blocks = 4, terms = 20;
#else
  const int blocks = 30, terms = 240;
#endif
  std::string script = "def f(n) {\n";
  for (int i = 0; i < blocks; ++i) script += "if true {\n";
  script += "return f(n + 1)";
  for (int i = 0; i < terms; ++i) script += " + 1";
  script += "\n";
  for (int i = 0; i < blocks; ++i) script += "}\n";
  script += "}\nlet x = f(0)\n";
  EXPECT_EQ(
      test::first_error(script),
      std::to_string(blocks + 2) + ":8: too many nested calls (the limit is 256; --limit calls=N raises it)");
}

TEST(Limits, StepsPerFrame) {
  const std::string e = test::first_error("for i in 0..9000000 {\n  let a = i\n  let b = a\n}");
  EXPECT_NE(
      e.find("too many evaluation steps in one frame (the limit is 10000000; --limit steps=N raises it)"),
      std::string::npos)
      << e;
}

TEST(Limits, ListSizes) {
  EXPECT_EQ(test::first_error("let x = 0..20000000"),
            "1:10: too many items in a list (the limit is 10000000; --limit list=N raises it): 0..20000000 "
            "has 20000000");
  EXPECT_EQ(test::first_error("let x = range(0, 1, 1e-9)"),
            "1:9: too many items in a list (the limit is 10000000; --limit list=N raises it): range() would "
            "make 1000000000");
  // A range that large is never materialised unless needed: its length is known.
  EXPECT_EQ(test::value("len(0..10000000)"), "10000000");
  EXPECT_EQ(test::first_error("let big = 0..6000000\nlet x = big + big"),
            "2:13: too many items in a list (the limit is 10000000; --limit list=N raises it)");
}

TEST(Limits, FacesPerFrameAreCheckedBeforeBuilding) {
  EXPECT_EQ(test::first_error("let s = sphere(1, slices: 100000, stacks: 100000)"),
            "1:9: too many faces built in one frame (the limit is 10000000; --limit faces=N raises it)");
  Budget budget;
  budget.charge_faces_drawn({}, 6'000'000);
  EXPECT_THROW(budget.charge_faces_drawn({}, 6'000'000), EvalError);
}

TEST(Limits, Frames) {
  EXPECT_EQ(test::first_error("animate frames 10001"),
            "1:16: too many frames (the limit is 10000): got 10001");
  EXPECT_EQ(test::first_error("animate frames 10000"), "<no error>");
}

TEST(Limits, StringsStopGrowing) {
  const std::string e = test::first_error(
      "def grow(s, n) {\n  if n == 0 { return s }\n  return grow(s + s, n - 1)\n}\nlet x = grow(\"ab\", 40)");
  EXPECT_NE(e.find("too many bytes in a string (the limit is 10000000; --limit string=N raises it)"),
            std::string::npos)
      << e;
}

// --limit NAME=N sets each limit for the run, up or down; the message names the option either way.
TEST(Limits, EachLimitIsTheRunsOwn) {
  Limits low;
  low.faces = 1000;
  low.list = 100;
  low.calls = 5;
  low.string = 8;
  low.vertices = 4;
  EXPECT_EQ(test::first_error("let s = sphere(1, 64, 32)", {}, low),
            "1:9: too many faces built in one frame (the limit is 1000; --limit faces=N raises it)");
  EXPECT_EQ(test::first_error("let x = [i for i in 0..101]", {}, low),
            "1:22: too many items in a list (the limit is 100; --limit list=N raises it): 0..101 has 101");
  EXPECT_EQ(test::first_error("def f(n) = f(n + 1)\nlet x = f(0)", {}, low),
            "1:12: too many nested calls (the limit is 5; --limit calls=N raises it)");
  EXPECT_EQ(test::first_error("let x = \"abcde\" + \"fghij\"", {}, low),
            "1:17: too many bytes in a string (the limit is 8; --limit string=N raises it)");
  EXPECT_EQ(test::first_error("draw box(1, 1, 1)", {}, low),
            "1:6: too many vertices drawn in one frame (the limit is 4; --limit vertices=N raises it)");
  Limits memory_mb;
  memory_mb.memory_mb = 1;
  const std::string memory = test::first_error("let s = sphere(1, 64, 32)", {}, memory_mb);
  EXPECT_NE(memory.find("(the limit is 1 MB; --limit memory=MB raises it)"), std::string::npos) << memory;
  Limits few_steps;
  few_steps.steps = 2000;
  const std::string steps = test::first_error("let x = [i * 2 for i in 0..5000]", {}, few_steps);
  EXPECT_NE(
      steps.find("too many evaluation steps in one frame (the limit is 2000; --limit steps=N raises it)"),
      std::string::npos)
      << steps;
  // Raised, the face limit lets through what the default refuses (the memory estimate, lowered here so
  // that nothing is built, is what stops it then).
  Limits high;
  high.faces = 20'000'000;
  high.memory_mb = 100;
  const std::string raised = test::first_error("let s = sphere(1, slices: 3000, stacks: 3500)", {}, high);
  EXPECT_NE(raised.find("the solids made would need about 10253 MB"), std::string::npos) << raised;
  EXPECT_EQ(test::first_error("let s = sphere(1, slices: 3000, stacks: 3500)").substr(0, 38),
            "1:9: too many faces built in one frame");
}

TEST(Limits, DeeplyNestedValuesPrintWithoutRecursingForever) {
  const std::string v =
      test::value("nest(200)", "def nest(n) {\n  if n == 0 { return [] }\n  return [nest(n - 1)]\n}");
  EXPECT_NE(v.find("[...]"), std::string::npos);
}

}  // namespace
}  // namespace hlr::runtime
