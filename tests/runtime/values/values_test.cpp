// Values and operators: arithmetic, vectors, lists and ranges, strings and their formats, comparisons,
// member and index access — each checked through str() of the result.
#include <gtest/gtest.h>

#include "runtime/values/format_value.hpp"
#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

using test::value;

TEST(Values, NumbersPrintInShortestRoundTripForm) {
  EXPECT_EQ(format_number(1), "1");
  EXPECT_EQ(format_number(0.5), "0.5");
  EXPECT_EQ(format_number(1e-7), "1e-07");
  EXPECT_EQ(format_number(-0.0), "0");
  EXPECT_EQ(format_number(123456789), "123456789");
  EXPECT_EQ(format_number(100000), "100000");
  EXPECT_EQ(format_number(1e21), "1e+21");
  EXPECT_EQ(format_number(0.000001), "0.000001");
  EXPECT_EQ(format_number(-2.5e-300), "-2.5e-300");
  EXPECT_EQ(value("0.1 + 0.2"), "0.30000000000000004");
}

TEST(Values, Arithmetic) {
  EXPECT_EQ(value("1 + 2 * 3"), "7");
  EXPECT_EQ(value("(1 + 2) * 3"), "9");
  EXPECT_EQ(value("1 / 4"), "0.25");
  EXPECT_EQ(value("7 % 3"), "1");
  EXPECT_EQ(value("-1 % 3"), "2");  // floored
  EXPECT_EQ(value("7.5 % -2"), "-0.5");
  EXPECT_EQ(value("-(2 - 5)"), "3");
}

TEST(Values, VectorArithmetic) {
  EXPECT_EQ(value("(1, 2, 3) + (1, 1, 1)"), "(2, 3, 4)");
  EXPECT_EQ(value("(1, 2, 3) - (1, 1, 1)"), "(0, 1, 2)");
  EXPECT_EQ(value("(1, 2, 3) * 2"), "(2, 4, 6)");
  EXPECT_EQ(value("2 * (1, 2, 3)"), "(2, 4, 6)");
  EXPECT_EQ(value("(2, 4, 6) / 2"), "(1, 2, 3)");
  EXPECT_EQ(value("-(1, 2, 3)"), "(-1, -2, -3)");
  EXPECT_EQ(value("(1, 2, 3).y"), "2");
  EXPECT_EQ(value("(1, 2, 3)[2]"), "3");
}

TEST(Values, ListsAndRanges) {
  EXPECT_EQ(value("[1, 2] + [3]"), "[1, 2, 3]");
  EXPECT_EQ(value("0..4"), "0..4");
  EXPECT_EQ(value("[] + (0..3)"), "[0, 1, 2]");
  EXPECT_EQ(value("[] + 0..3"), "error: 2:19: cannot apply '+' to a list and a number");  // .. binds loosest
  EXPECT_EQ(value("len(0..4)"), "4");
  EXPECT_EQ(value("len(4..0)"), "0");
  EXPECT_EQ(value("(2..6)[1]"), "3");
  EXPECT_EQ(value("[1, 2, 3][-1]"), "3");
  EXPECT_EQ(value("[[1, 2], [3]][0][1]"), "2");
  EXPECT_EQ(value("range(0, 1, 0.25)"), "[0, 0.25, 0.5, 0.75]");
  EXPECT_EQ(value("range(5, 0, -2)"), "[5, 3, 1]");
  EXPECT_EQ(value("len([1, \"a\", (0, 0, 0)])"), "3");
  EXPECT_EQ(value("[1, \"a\", true]"), "[1, \"a\", true]");
}

TEST(Values, Comparisons) {
  EXPECT_EQ(value("1 < 2"), "true");
  EXPECT_EQ(value("2 <= 1"), "false");
  EXPECT_EQ(value("[1, 2] == [1, 2]"), "true");
  EXPECT_EQ(value("0..3 == [0, 1, 2]"), "true");
  EXPECT_EQ(value("(1, 2, 3) != (1, 2, 4)"), "true");
  EXPECT_EQ(value("\"a\" == \"a\""), "true");
  EXPECT_EQ(value("1 < 2 and not (2 < 1)"), "true");
  EXPECT_EQ(value("false or true"), "true");
  // Short-circuit: the right side is not evaluated.
  EXPECT_EQ(value("true or 1 / 0 == 1"), "true");
  EXPECT_EQ(value("false and 1 / 0 == 1"), "false");
}

TEST(Values, StringsAndFormats) {
  EXPECT_EQ(value("\"frame {1 + 1} of {3}\""), "frame 2 of 3");
  EXPECT_EQ(value("\"{7:03}\""), "007");
  EXPECT_EQ(value("\"{-7:03}\""), "-07");
  EXPECT_EQ(value("\"{3.14159:.2f}\""), "3.14");
  EXPECT_EQ(value("\"{3.14159:.3}\""), "3.14");
  EXPECT_EQ(value("\"[{2.5:8.2f}]\""), "[    2.50]");
  EXPECT_EQ(value("\"{255:x}\""), "ff");
  EXPECT_EQ(value("\"{42:d}\""), "42");
  EXPECT_EQ(value("\"{1234.5:e}\""), "1.234500e+03");
  EXPECT_EQ(value("\"{(1, 2, 3):.1f}\""), "(1.0, 2.0, 3.0)");
  EXPECT_EQ(value("\"[{\"ab\":4}]\""), "[ab  ]");
  EXPECT_EQ(value("\"a\" + \"b\""), "ab");
  EXPECT_EQ(value("str(1e-7)"), "1e-07");
  EXPECT_EQ(value("len(\"h\u00e9llo\")"), "5");  // code points
  EXPECT_EQ(value("\"\\{x\\}\""), "{x}");
}

TEST(Values, OtherKindsPrintReadably) {
  EXPECT_EQ(value("true"), "true");
  EXPECT_EQ(value("translate(1, 2, 3)"), "matrix([[1, 0, 0, 1], [0, 1, 0, 2], [0, 0, 1, 3]])");
  EXPECT_EQ(value("box(1, 2, 3)"), "solid box (6 faces)");
  EXPECT_EQ(value("group([box(1, 1, 1), cube(1)])"), "group of 2 solids");
  EXPECT_EQ(value("orbit()"), "camera orbit");
  EXPECT_EQ(value("sin"), "built-in sin");
  EXPECT_EQ(value("f", "def f(a, b = 2) = a"), "function f(a, b)");
}

TEST(Values, BadFormatsAreErrorsAtTheInterpolation) {
  EXPECT_EQ(value("\"{1:q}\""), "error: 2:17: bad format 'q': expected [0][width][.precision][f|e|g|d|x]");
  EXPECT_EQ(value("\"{2.5:x}\""), "error: 2:17: format 'x' needs a whole number, got 2.5");
  EXPECT_EQ(value("\"{\"s\":03}\""), "error: 2:17: format '03' needs a number, got a string");
}

}  // namespace
}  // namespace hlr::runtime
