// List comprehensions, `[EXPR for NAME in ITERABLE]` and `[... if COND]`: values, filtering, scoping
// (one scope per item, the variable never leaks), the budget, and the errors at their spans.
#include <gtest/gtest.h>

#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

using test::first_error;
using test::value;

TEST(Comprehension, MapsRangesAndLists) {
  EXPECT_EQ(value("[i * i for i in 0..6]"), "[0, 1, 4, 9, 16, 25]");
  EXPECT_EQ(value("[p.x + p.y for p in [(1, 2, 3), (4, 5, 6)]]"), "[3, 9]");
  EXPECT_EQ(value("[s + \"!\" for s in [\"a\", \"b\"]]"), "[\"a!\", \"b!\"]");
  EXPECT_EQ(value("[x for x in range(0, 1, 0.25)]"), "[0, 0.25, 0.5, 0.75]");
  EXPECT_EQ(value("[i for i in 0..0]"), "[]");
  EXPECT_EQ(value("[i for i in []]"), "[]");
  EXPECT_EQ(value("len([0 for i in 0..1000])"), "1000");
  // The result is an ordinary list: indexable, concatenable, walkable.
  EXPECT_EQ(value("[i for i in 0..4][-1] + len([1] + [i for i in 0..3])"), "7");
  EXPECT_EQ(value("sq", "let sq = [i * i for i in 0..4]\nfor v in sq {\n  let w = v\n}"), "[0, 1, 4, 9]");
}

TEST(Comprehension, Filters) {
  EXPECT_EQ(value("[i for i in 0..10 if i % 2 == 0]"), "[0, 2, 4, 6, 8]");
  EXPECT_EQ(value("[i * 10 for i in 0..10 if i > 6 and i != 8]"), "[70, 90]");
  EXPECT_EQ(value("[i for i in 0..10 if false]"), "[]");
  // The element is evaluated only for the items kept: 1 / 0 never runs.
  EXPECT_EQ(value("[1 / i for i in [0, 2, 4] if i != 0]"), "[0.5, 0.25]");
}

TEST(Comprehension, Nests) {
  EXPECT_EQ(value("[[j for j in 0..i] for i in 0..4]"), "[[], [0], [0, 1], [0, 1, 2]]");
  EXPECT_EQ(value("[[[i, j] for j in 0..3 if j != i] for i in 0..2]"),
            "[[[0, 1], [0, 2]], [[1, 0], [1, 2]]]");
  // The inner comprehension sees the outer variable; the same name in the inner one shadows it.
  EXPECT_EQ(value("[[i for i in 0..i] for i in 1..3]"), "[[0], [0, 1]]");
}

TEST(Comprehension, VariableIsLocalToTheComprehension) {
  // It does not leak out...
  EXPECT_EQ(value("[i for i in 0..3]\nlet after = i"), "error: 3:13: unknown name 'i'");
  EXPECT_EQ(value("x", "let l = [x for x in 0..3]\nlet x = 7"), "7");
  // ...and may shadow a name outside, which keeps its value.
  EXPECT_EQ(value("[i for i in 0..3] + [i]", "let i = 10"), "[0, 1, 2, 10]");
  // The iterable is evaluated outside the comprehension's scope.
  EXPECT_EQ(value("[i for i in i..3]", "let i = 1"), "[1, 2]");
  // The element sees the enclosing scope: parameters, other names.
  EXPECT_EQ(value("f(3)", "let k = 100\ndef f(n) = [k + n * i for i in 0..n]"), "[100, 103, 106]");
}

TEST(Comprehension, ClosuresCaptureTheirOwnItem) {
  const char* script =
      "def adder(k) {\n  def add(x) = x + k\n  return add\n}\n"
      "let adders = [adder(i) for i in 0..4]\n";
  EXPECT_EQ(value("[f(10) for f in adders]", script), "[10, 11, 12, 13]");
  // A function defined inside each item's scope keeps that item, not the last one.
  EXPECT_EQ(value("[g() for g in gs]",
                  "def make(i) {\n  def get() = i * i\n  return get\n}\n"
                  "let gs = [make(i) for i in 0..3]"),
            "[0, 1, 4]");
}

TEST(Comprehension, ReplacesRecursiveListBuilders) {
  const char* recursive =
      "def squares(i, n) {\n  if i == n { return [] }\n  return [i * i] + squares(i + 1, n)\n}\n";
  EXPECT_EQ(value("squares(0, 50) == [i * i for i in 0..50]", recursive), "true");
}

TEST(Comprehension, NonBoolConditionIsAnErrorAtTheCondition) {
  EXPECT_EQ(first_error("let x = [i for i in 0..3 if i]"),
            "1:29: a list comprehension's 'if' needs a bool condition, got a number");
  EXPECT_EQ(first_error("let x = [i for i in [1]\n  if \"yes\"]"),
            "2:6: a list comprehension's 'if' needs a bool condition, got a string");
  // Only reached when there are items.
  EXPECT_EQ(first_error("let x = [i for i in [] if 1]"), "<no error>");
}

TEST(Comprehension, IteratingANonListIsAnErrorAtTheIterable) {
  EXPECT_EQ(first_error("let x = [i for i in 5]"),
            "1:21: a list comprehension needs a list or a range to walk, got a number");
  EXPECT_EQ(first_error("let v = (1, 2, 3)\nlet x = [c for c in v]"),
            "2:21: a list comprehension needs a list or a range to walk, got a vector");
}

TEST(Comprehension, ErrorsInTheElementPointAtIt) {
  EXPECT_EQ(first_error("let l = [1, 2]\nlet x = [l[i] for i in 0..4]"),
            "2:12: index 2 is out of range for 2 items");
  EXPECT_EQ(first_error("let x = [y for i in 0..4]"), "1:10: unknown name 'y'");
}

TEST(Comprehension, EachItemCostsAStep) {
  // An empty body still costs one step per item: a huge filtered-out walk stops at the step limit.
  const std::string e = first_error("let x = [i for i in 0..9000000 if false]");
  EXPECT_NE(
      e.find("too many evaluation steps in one frame (the limit is 10000000; --limit steps=N raises it)"),
      std::string::npos)
      << e;
  EXPECT_EQ(first_error("let x = [0 for i in 0..3000000]"), "<no error>");
  const std::string big = first_error("let x = [0 for i in 0..6000000]");
  EXPECT_NE(big.find("too many evaluation steps"), std::string::npos) << big;
}

}  // namespace
}  // namespace hlr::runtime
