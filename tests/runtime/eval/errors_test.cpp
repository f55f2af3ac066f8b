// Scripts that are wrong and what the evaluator says: exact line:col and message (Lua's errors.lua style),
// then the printed form with caret, hint and notes.
#include <gtest/gtest.h>

#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

struct Case {
  const char* script;
  const char* expected;  // "line:col: message"
};

// clang-format off
const Case kCases[] = {
  // names and scopes
  {"let x = y", "1:9: unknown name 'y'"},
  {"let x = 1\nlet x = 2", "2:5: 'x' is already defined in this scope"},
  {"def f() = 1\nsolid f { }", "2:7: 'f' is already defined in this scope"},
  {"let f = 3\nlet y = f(1)", "2:9: 'f' is a number, not a function"},
  // arithmetic
  {"let x = 1 / 0", "1:13: division by zero"},
  {"let a = 2\nlet x = 5 % (a - 2)", "2:14: modulo by zero"},
  {"let x = (1, 2, 3) / 0", "1:21: division by zero"},
  {"let x = 1 + \"a\"", "1:11: cannot apply '+' to a number and a string"},
  {"let x = (1, 2, 3) * (1, 2, 3)", "1:19: cannot apply '*' to a vector and a vector"},
  {"let x = 1e308 * 10", "1:15: arithmetic overflow: 1e+308 * 10 is beyond the largest number (about 1.8e308)"},
  {"let x = 1 < \"a\"", "1:11: cannot compare a number with a string using '<'"},
  {"let x = 1 == \"a\"", "1:11: cannot compare a number with a string using '=='"},
  {"let x = 1 and true", "1:9: 'and' needs bools, got a number"},
  {"let x = not 1", "1:9: 'not' needs a bool, got a number"},
  {"let x = -\"a\"", "1:9: cannot negate a string"},
  {"let x = (1, \"a\", 3)", "1:13: a vector's components must be numbers; y is a string"},
  {"let x = translate(1, 0, 0) then 2", "1:28: cannot apply 'then' to a transform and a number"},
  // non-finite results of built-ins
  {"let x = sqrt(-1)", "1:9: sqrt(-1) is not a real number"},
  {"let x = pow(10, 400)", "1:9: pow(10, 400) overflows"},
  {"let x = log(0)", "1:9: log(0) overflows"},
  {"let x = tan(90)", "1:9: tan(90) overflows"},
  {"let x = acos(2)", "1:9: acos(2) is not a real number"},
  // member and index access
  {"let x = (1, 2, 3).w", "1:19: a vector has no member 'w'"},
  {"let x = [1, 2].x", "1:16: a list has no member 'x'"},
  {"let x = [1, 2][5]", "1:16: index 5 is out of range for 2 items"},
  {"let x = [1, 2][-3]", "1:16: index -3 is out of range for 2 items"},
  {"let x = [1, 2][0.5]", "1:16: an index must be a whole number, got 0.5"},
  {"let x = 3[0]", "1:9: cannot index a number"},
  // statements
  {"if 1 { }", "1:4: 'if' needs a bool condition, got a number"},
  {"for i in 5 { }", "1:10: 'for' needs a list or a range to walk, got a number"},
  {"draw 5", "1:6: draw needs a solid, a group or a list of them, got a number"},
  {"draw [cube(1), 2]", "1:6: draw needs a solid, a group or a list of them, got a number (item [1])"},
  {"draw cube(1) at 5", "1:17: 'draw ... at' needs a transform, got a number"},
  {"camera c = 5", "1:12: 'camera c =' needs a camera, got a number"},
  {"camera c = orbit()\ncamera c = orbit()", "2:8: camera 'c' is already declared"},
  {"animate frames 0", "1:16: the frame count must be a whole number from 1 to 10000, got 0"},
  {"animate frames 2.5", "1:16: the frame count must be a whole number from 1 to 10000, got 2.5"},
  {"animate frames 10 fps 0", "1:23: fps must be positive, got 0"},
  {"animate frames 2\nanimate frames 3", "2:1: 'animate' is already set"},
  {"paper A9", "1:7: unknown paper size 'A9'"},
  {"output \"a.pdf\" paper A4\npaper A3", "2:1: 'paper' is already set"},
  {"output \"\"", "1:8: the output name is empty"},
  {"style hidden dashed\nstyle hidden off", "2:1: 'style hidden' is already set"},
  // arguments: user functions
  {"def f(a) = a\nlet x = f(1, 2)", "2:14: too many arguments to f(): it takes at most 1, got 2"},
  {"def f(a) = a\nlet x = f(b: 1)", "2:11: unknown argument 'b' to f()"},
  {"def f(a) = a\nlet x = f()", "2:9: missing argument 'a' to f()"},
  {"def f(a, b) = a\nlet x = f(1, a: 2)", "2:14: argument 'a' to f() is given twice"},
  // arguments: built-ins
  {"let x = box(1, 2, \"3\")", "1:19: bad argument 'sz' to box(): expected a number, got a string"},
  {"let x = box(1, 2)", "1:9: missing argument 'sz' to box()"},
  {"let x = box(1, 2, 3, 4)", "1:22: too many arguments to box(): it takes at most 3, got 4"},
  {"let x = cylinder(1, 2, side: 8)", "1:24: unknown argument 'side' to cylinder()"},
  {"let x = cylinder(1, 2, sides: 2)", "1:31: bad argument 'sides' to cylinder(): must be a whole number from 3 to 10000000 (got 2)"},
  {"let x = box(-1, 2, 3)", "1:13: bad argument 'sx' to box(): must be positive (got -1)"},
  {"let x = lookat(eye: (0, 0, 0), target: (0, 0, 0))", "1:40: bad argument 'target' to lookat(): must differ from the eye position"},
  {"let x = lookat(eye: (1, 0, 0), target: (0, 0, 0), fov: 190)", "1:56: bad argument 'fov' to lookat(): must be between 0 and 180 degrees (got 190)"},
  {"let x = orbit(rho: -1)", "1:20: bad argument 'rho' to orbit(): must be a positive distance (got -1)"},
  {"let x = prism([(0, 0, 0), (1, 0, 0)], 1)", "1:15: bad argument 'outline' to prism(): needs at least 3 points, got 2"},
  {"let x = prism([(0, 0, 0), (1, 0, 1), (0, 1, 0)], 1)", "1:15: bad argument 'outline' to prism(): point 1 has z = 1; outlines lie in the xy plane (z = 0)"},
  {"let x = scale(0)", "1:15: bad argument 'sx' to scale(): must not be 0: a zero scale flattens the solid"},
  {"let x = rotate(30)", "1:9: rotate(degrees) needs an axis: rotate(30, axis: (0, 0, 1)), or rotate(z: 30)"},
  {"let x = normalize((0, 0, 0))", "1:19: bad argument 'v' to normalize(): the zero vector has no direction"},
  {"let x = min()", "1:9: min() needs at least one number"},
  {"let x = range(0, 10, 0)", "1:22: bad argument 'step' to range(): must not be 0"},
  {"let x = matrix([[1, 0, 0, 0], [0, 1, 0, 0]])", "1:16: bad argument 'rows' to matrix(): must be 3 rows of 4 numbers: [[a, b, c, tx], [d, e, f, ty], [g, h, i, tz]]"},
  {"let x = desens(object: (0, 0, 0), observer: (10, 0, 0), focal: 0)", "1:64: bad argument 'focal' to desens(): must be a positive distance (got 0)"},
};
// clang-format on

TEST(EvalErrors, LineColumnAndMessage) {
  for (const Case& c : kCases) EXPECT_EQ(test::first_error(c.script), c.expected) << c.script;
}

TEST(EvalErrors, PrintedWithCaretHintAndSignature) {
  EXPECT_EQ(test::printed_error("draw box(1, 2)\n"),
            "test.hls:1:6: error: missing argument 'sz' to box()\n"
            "   1 | draw box(1, 2)\n"
            "     |      ^~~~~~~~~\n"
            "hint: box(sx, sy, sz) | box(min: p, max: q) | box(size: v, center: p)\n");
  EXPECT_EQ(test::printed_error("let x = boxx(1, 2, 3)\n"),
            "test.hls:1:9: error: unknown name 'boxx'\n"
            "   1 | let x = boxx(1, 2, 3)\n"
            "     |         ^~~~\n"
            "hint: did you mean 'box'?\n");
}

TEST(EvalErrors, ErrorsInsideFunctionsNoteTheCalls) {
  EXPECT_EQ(test::printed_error("def f(x) = 1 / x\ndef g(y) = f(y - 1)\nlet z = g(1)\n"),
            "test.hls:1:16: error: division by zero\n"
            "   1 | def f(x) = 1 / x\n"
            "     |                ^\n"
            "hint: the divisor evaluates to 0\n"
            "test.hls:2:12: note: in the call of 'f' here\n"
            "   2 | def g(y) = f(y - 1)\n"
            "     |            ^~~~~~~~\n"
            "test.hls:3:9: note: in the call of 'g' here\n"
            "   3 | let z = g(1)\n"
            "     |         ^~~~\n");
}

TEST(EvalErrors, RedefinitionPointsAtTheFirstDefinition) {
  const std::string printed = test::printed_error("let width = 1\nlet width = 2\n");
  EXPECT_NE(printed.find("test.hls:2:5: error: 'width' is already defined in this scope"), std::string::npos);
  EXPECT_NE(printed.find("test.hls:1:5: note: 'width' was defined here"), std::string::npos);
}

TEST(EvalErrors, SyntaxErrorsStopBeforeEvaluation) {
  EXPECT_EQ(test::first_error("let x = 1 +\n"), "1:12: expected an operand after the operator");
}

}  // namespace
}  // namespace hlr::runtime
