// Broken scripts and what the parser says about them: exact line:col and message (Lua's
// testes/errors.lua style), the printed form, and recovery to report several errors per file.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lang/parser.hpp"

namespace hlr::lang {
namespace {

// "line:col: message" of every diagnostic.
std::vector<std::string> errors(const std::string& text) {
  const ParseResult result = parse(text, "bad.hls");
  std::vector<std::string> out;
  for (const auto& d : result.diagnostics) {
    const SourcePos at = result.source->position(d.span.begin);
    out.push_back(std::to_string(at.line) + ":" + std::to_string(at.column) + ": " + d.message);
  }
  EXPECT_EQ(result.ok(), out.empty());
  return out;
}

std::string first_error(const std::string& text) {
  const auto all = errors(text);
  return all.empty() ? "<no error>" : all.front();
}

struct Case {
  const char* script;
  const char* expected;  // "line:col: message"
};

// clang-format off
const Case kCases[] = {
  // braces and brackets
  {"solid a {\n  vertex 1 = (0, 0, 0)\n  face 1 2 3\n",
   "3:13: expected 'vertex', 'face', 'line' or '}' in the solid (to close '{' at line 1)"},
  {"for i in 0..4 {\n  draw x\n", "2:9: expected a statement or '}' (to close '{' at line 1)"},
  {"def f(x) {\n  return x\n", "2:11: expected a statement or '}' (to close '{' at line 1)"},
  {"draw f(1, 2\n", "1:12: expected ',' or ')' in the argument list (to close '(' at line 1)"},
  {"let v = (1, 2, 3\n", "1:17: expected ')' after the third component: a vector has exactly three components (to close '(' at line 1)"},
  {"let x = (1 + 2\n", "1:15: expected ')' or ',' (to close '(' at line 1)"},
  {"let l = [1, 2\nlet y = 3\n", "1:14: expected ',' or ']' in the list (to close '[' at line 1)"},
  {"let e = l[0\n", "1:12: expected ']' after the index (to close '[' at line 1)"},
  {"def f(a, b\ndraw f(1)", "1:11: expected a parameter name, ',' or ')' in the parameter list (to close '(' at line 1)"},
  {"}\n", "1:1: unexpected '}' with no '{' open"},
  // solids
  {"solid a {\n  face\n}\n", "2:7: expected vertex ids after 'face', as in 'face 1 2 3'"},
  {"solid a {\n  vertex 1 (0, 0, 0)\n}\n", "2:12: expected '=' after the vertex id, as in 'vertex 1 = (0, 0, 0)'"},
  {"solid a {\n  vertex = (0, 0, 0)\n}\n", "2:10: expected a vertex id (a whole number or a name) after 'vertex', as in 'vertex 1 = (0, 0, 0)'"},
  {"solid a {\n  vertex 1 =\n}\n", "2:13: expected the vertex position after '=', as in 'vertex 1 = (0, 0, 0)'"},
  {"solid a {\n  face 1 2 3 hole\n}\n", "2:18: expected vertex ids after 'hole', as in 'face 1 2 3 4 hole 5 6 7'"},
  {"solid a {\n  line 1\n}\n", "2:9: expected a second vertex id: a line joins two vertices, as in 'line 1 2'"},
  {"solid { }", "1:7: expected a name after 'solid', as in 'solid box { ... }'"},
  {"solid a vertex 1 = (0, 0, 0)", "1:9: expected '{' after the solid's name"},
  {"solid a {\n  vertex 1 = (0, 0, 0) draw a\n}\n", "2:24: expected 'vertex', 'face', 'line' or '}' in the solid (to close '{' at line 1)"},
  {"vertex 1 = (0, 0, 0)", "1:1: 'vertex' belongs inside a solid"},
  // solid options
  {"solid a (crease: 30 {\n}\n", "1:21: expected ',' or ')' in the solid's options (to close '(' at line 1)"},
  {"solid a (crease: 30\n  vertex 1 = (0, 0, 0)\n}\n", "1:20: expected ',' or ')' in the solid's options (to close '(' at line 1)"},
  {"solid a (crease 30) {}", "1:17: expected ',' or ')' in the solid's options (to close '(' at line 1)"},
  {"solid a (crease: 30,) {}", "1:21: expected an option after ',' in the solid's options, as in '(crease: 30, planarity: 0.003)'"},
  {"solid a (crease:) {}", "1:17: expected a value after the argument name and ':', as in 'fov: 40'"},
  {"solid a (crease: 30) vertex 1 = (0, 0, 0)", "1:22: expected '{' after the solid's name"},
  // numbers, strings, characters
  {"let x = 1.2.3", "1:12: malformed number: a number has at most one decimal point"},
  {"let x = 2x", "1:10: malformed number: a letter follows the digits"},
  {"let x = 1e", "1:11: expected digits after the exponent 'e' of the number, as in '1.5e-3'"},
  {"let s = \"abc\nlet t = 1", "1:13: unterminated string: add '\"' before the end of the line"},
  {"output \"frame-{frame:03.pdf\"", "1:28: expected '}' to end the '{...}' in the string, as in \"frame-{frame:03}.pdf\" (to close '{' at line 1)"},
  {"let s = \"a\\qb\"", "1:12: unknown escape in the string"},
  {"let s = \"{}\"", "1:11: expected an expression inside '{...}' in the string"},
  {"draw a @ b", "1:8: unexpected character '@'"},
  {"let x = 3;", "1:10: unexpected character ';'"},
  {"let s = 'abc'", "1:9: unexpected character '''"},
  {"let é = 1", "1:5: unexpected character 'é'"},
  {"let x = 1e999", "1:9: number out of range: numbers must lie within about 1e308"},
  // let, def, names
  {"let = 3", "1:5: expected a name after 'let', as in 'let x = 1'"},
  {"let for = 1", "1:5: 'for' is a reserved word and cannot be used as a name"},
  {"let x 3", "1:7: expected '=' after the name, as in 'let x = 1'"},
  {"let x =\ndraw x", "1:8: expected a value after '=', as in 'let x = 1'"},
  {"def f(a,) = 1", "1:9: expected a parameter name after ','"},
  {"def f = 1", "1:7: expected '(' and the parameters after the function name, as in 'def f(x) = x * 2'"},
  {"def f(x)\ndraw f(1)", "1:9: expected '= expression' or a '{ ... }' body after the parameters"},
  {"def f(if) = 1", "1:7: 'if' is a reserved word and cannot be used as a name"},
  {"def f(a = 1, b) = a", "1:14: parameter 'b' needs a default value, as 'a' before it has one"},
  {"def f(a, a) = a", "1:10: parameter 'a' appears twice in 'f'"},
  {"x = 3", "1:1: expected a statement, found 'x'"},
  {"else { }", "1:1: 'else' without an 'if' before it"},
  {"return 1", "1:1: 'return' outside a function body"},
  // control flow
  {"for i 0..4 {}", "1:7: expected 'in' after the loop variable, as in 'for i in 0..4 { ... }'"},
  {"for 0..4 {}", "1:5: expected the loop variable after 'for', as in 'for i in 0..4 { ... }'"},
  {"for i in 0..4 draw x", "1:15: expected '{' to start the loop body"},
  {"for i in { }", "1:10: expected a range or list after 'in', as in 'for i in 0..4 { ... }'"},
  {"if x > 1 draw a", "1:10: expected '{' after the condition"},
  {"if { draw a }", "1:4: expected a condition after 'if'"},
  {"if a { } else draw b", "1:15: expected '{' or 'if' after 'else'"},
  // draw, camera, animate, output, style, include
  {"draw", "1:5: expected what to draw after 'draw', as in 'draw box'"},
  {"draw x at", "1:10: expected a transform after 'at', as in 'draw box at translate(1, 0, 0)'"},
  {"draw x at rotate(z: 30) then", "1:29: expected a transform after 'then', as in 'rotate(z: 30) then scale(2)'"},
  {"camera c lookat(eye: (1, 1, 1))", "1:10: expected '=' after the camera name, as in 'camera main = lookat(...)'"},
  {"camera = orbit(theta: 45)", "1:8: expected a camera name after 'camera', as in 'camera main = lookat(...)'"},
  {"camera c = lookat(eye: )", "1:24: expected a value after the argument name and ':', as in 'fov: 40'"},
  {"camera c = lookat(fov: 40, 1)", "1:28: positional argument after the named argument 'fov'"},
  {"camera c = orbit(d: 1, d: 2)", "1:24: argument 'd' is given twice"},
  {"animate 48", "1:9: expected 'frames' after 'animate', as in 'animate frames 48 fps 12'"},
  {"animate frames\ndraw x", "1:15: expected the number of frames after 'frames', as in 'animate frames 48'"},
  {"animate frames 48 fps", "1:22: expected frames per second after 'fps', as in 'animate frames 48 fps 12'"},
  {"output landing.pdf", "1:8: expected a quoted file name after 'output', as in 'output \"frame-{frame:03}.pdf\"'"},
  {"paper 210", "1:7: expected a paper size after 'paper', as in 'paper A4'"},
  {"style hidden dotted", "1:14: expected 'dashed', 'off' or 'levels N' after 'style hidden'"},
  {"style dashed", "1:7: expected 'hidden' after 'style', as in 'style hidden dashed'"},
  {"include parts.hls", "1:9: expected a quoted file name after 'include', as in 'include \"parts.hls\"'"},
  // paper options, pens, plotters
  {"paper A4 (margin: 10\ndraw x", "1:21: expected ',' or ')' in the paper's options (to close '(' at line 1)"},
  {"paper A4 (margin: 10,)", "1:22: expected an option after ',' in the paper's options, as in '(margin: 10, scale: 0.5)'"},
  {"output \"x.hpgl\" plotter", "1:24: expected a plotter name after 'plotter', as in 'plotter hp7475a' or 'plotter \"roland-dxy\"'"},
  {"output \"x.hpgl\" plotter \"p{n}\"", "1:25: the plotter name must be a plain string, without '{...}'"},
  {"pen 2\ndraw x", "1:6: expected '(' and the pen's options after the pen number, as in 'pen 2 (colour: \"red\", width: 0.35)'"},
  {"pen (colour: \"red\")", "1:5: expected the pen number after 'pen', as in 'pen 2 (colour: \"red\", width: 0.35)'"},
  {"draw x pen\n", "1:11: expected a pen number after 'pen', as in 'draw box pen 2'"},
  {"style hidden off pen 2", "1:18: a pen goes only with 'style hidden dashed' or 'style hidden levels N'"},
  {"style hidden levels pen 2", "1:21: expected how many occlusion levels to draw after 'levels', as in 'style hidden levels 3'"},
  {"style hidden levels\ndraw x", "1:20: expected how many occlusion levels to draw after 'levels', as in 'style hidden levels 3'"},
  {"plotter { pens: 2 }", "1:9: expected a name after 'plotter', as in 'plotter mine { base: \"hp7475a\", pens: 6 }'"},
  {"plotter then { pens: 2 }", "1:9: 'then' is a reserved word and cannot be used as a name"},
  {"plotter p { pens 6 }", "1:13: expected 'key: value' or '}' in the plotter (to close '{' at line 1)"},
  {"plotter p {\n  pens: 6,\n}", "2:11: expected 'key: value' after ',' in the plotter, as in 'pens: 6'"},
  {"include \"part-{n}.hls\"", "1:9: the file name after 'include' must be a plain string, without '{...}'"},
  // expressions
  {"let x = 1 +", "1:12: expected an operand after the operator"},
  {"let x = (1, 2 3)", "1:15: expected ')' or ',' and a third component after the vector's second component (to close '(' at line 1)"},
  {"let x = (1, 2, 3, 4)", "1:17: expected ')' after the third component: a vector has exactly three components (to close '(' at line 1)"},
  {"let x = [1, 2,]", "1:15: expected a list element after ','"},
  {"let x = f(1,)", "1:13: expected an argument after ','"},
  {"let x = v.", "1:11: expected a member name after '.', as in 'v.x'"},
  {"let x = a < b < c", "1:15: comparisons do not chain"},
  {"let x = 0..1..2", "1:13: a range has one '..': write 'a..b'"},
  {"let x = not", "1:12: expected an operand after 'not'"},
  {"let x = a and", "1:14: expected an operand after 'and'"},
  {"let x = -", "1:10: expected an operand after '-'"},
  {"let x = l[]", "1:11: expected an index after '[', as in 'l[0]'"},
  // list comprehensions
  {"let x = [i for in l]", "1:16: 'in' is a reserved word and cannot be used as a name"},
  {"let x = [i for]", "1:15: expected the comprehension's variable after 'for', as in '[i * i for i in 0..10]'"},
  {"let x = [i for i of 0..4]", "1:18: expected 'in' after the comprehension's variable, as in '[i * i for i in 0..10]'"},
  {"let x = [i for i in ]", "1:21: expected a range or list after 'in', as in '[i * i for i in 0..10]'"},
  {"let x = [i for i in l if ]", "1:26: expected a condition after 'if', as in '[i for i in 0..10 if i % 2 == 0]'"},
  {"let x = [i for i in l,\n  2]", "1:22: expected ']' to end the comprehension (to close '[' at line 1)"},
  {"let x = [i for i in l\nlet y = 2\n", "1:22: expected ']' to end the comprehension (to close '[' at line 1)"},
  {"let x = [i\n  for j in m for k in n]", "2:14: expected ']' to end the comprehension (to close '[' at line 1)"},
};
// clang-format on

TEST(Diagnostics, BrokenSnippets) {
  EXPECT_GE(std::size(kCases), 40U);
  for (const Case& c : kCases) EXPECT_EQ(first_error(c.script), c.expected) << "script:\n" << c.script;
}

TEST(Diagnostics, PrintedForm) {
  const ParseResult result = parse("solid a {\n  vertex 1 (0, 0, 0)\n}\n", "scene.hls");
  ASSERT_EQ(result.diagnostics.size(), 1U);
  EXPECT_EQ(format(result.diagnostics[0], *result.source),
            "scene.hls:2:12: error: expected '=' after the vertex id, as in 'vertex 1 = (0, 0, 0)'\n"
            "   2 |   vertex 1 (0, 0, 0)\n"
            "     |            ^\n");
}

TEST(Diagnostics, PrintedFormWithHintUnderlineAndTabs) {
  const ParseResult result = parse("\tlet for = 1\n", "t.hls");
  ASSERT_EQ(result.diagnostics.size(), 1U);
  EXPECT_EQ(format(result.diagnostics[0], *result.source),
            "t.hls:1:6: error: 'for' is a reserved word and cannot be used as a name\n"
            "   1 | \tlet for = 1\n"
            "     | \t    ^~~\n"
            "hint: expected a name after 'let', as in 'let x = 1'\n");
}

TEST(Diagnostics, CaretCountsCodePoints) {
  const ParseResult result = parse("let s = \"héllo\" @\n", "u.hls");
  ASSERT_EQ(result.diagnostics.size(), 1U);
  EXPECT_EQ(result.source->position(result.diagnostics[0].span.begin).column, 17U);
  const std::string text = format(result.diagnostics[0], *result.source);
  EXPECT_NE(text.find("     |                 ^\n"), std::string::npos) << text;
}

// A UTF-8 byte-order mark, as some editors save it, is not part of the script: it parses, and a message
// on the first line counts columns from the first visible character.
TEST(Diagnostics, AByteOrderMarkIsSkipped) {
  EXPECT_TRUE(parse("\xEF\xBB\xBFlet a = 1\n", "bom.hls").ok());
  const ParseResult result = parse("\xEF\xBB\xBFlet s = 1 @\n", "bom.hls");
  ASSERT_EQ(result.diagnostics.size(), 1U);
  EXPECT_EQ(result.source->position(result.diagnostics[0].span.begin).column, 11U);
  const std::string text = format(result.diagnostics[0], *result.source);
  EXPECT_NE(text.find("   1 | let s = 1 @\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("\xEF\xBB\xBF"), std::string::npos) << text;
}

// The code points of `text` (UTF-8), one string each.
std::vector<std::string> code_points(const std::string& text) {
  std::vector<std::string> out;
  for (const char c : text) {
    if ((static_cast<unsigned char>(c) & 0xC0U) == 0x80U && !out.empty()) {
      out.back() += c;
    } else {
      out.emplace_back(1, c);
    }
  }
  return out;
}

// The printed quote and the code point its caret stands under, for a one-line script with one error.
struct Quote {
  std::string quoted;  // the quoted line, gutter removed
  std::string under_caret;
  std::size_t underline = 0;  // '~' after the caret
};
Quote quote_of(const std::string& text) {
  const ParseResult result = parse(text, "long.hls");
  EXPECT_EQ(result.diagnostics.size(), 1U);
  if (result.diagnostics.empty()) return {};
  const std::string printed = format(result.diagnostics[0], *result.source);
  const std::size_t first = printed.find('\n');
  const std::size_t second = printed.find('\n', first + 1);
  const std::size_t third = printed.find('\n', second + 1);
  const std::string gutter = "   1 | ";
  Quote q;
  q.quoted = printed.substr(first + 1 + gutter.size(), second - first - 1 - gutter.size());
  const auto caret_line =
      code_points(printed.substr(second + 1 + gutter.size(), third - second - 1 - gutter.size()));
  const auto quoted = code_points(q.quoted);
  for (std::size_t i = 0; i < caret_line.size(); ++i) {
    if (caret_line[i] != "^") continue;
    q.under_caret = i < quoted.size() ? quoted[i] : "<end>";
    q.underline = caret_line.size() - i - 1;
  }
  return q;
}

TEST(Diagnostics, LongLineIsQuotedAroundTheCaret) {
  std::string list = "let x = [";
  for (int i = 0; i < 3000; ++i) list += "1, ";
  Quote q = quote_of(list + "@, " + list.substr(9) + "1]\n");
  EXPECT_EQ(q.under_caret, "@");
  EXPECT_EQ(code_points(q.quoted).size(), 162U);
  EXPECT_EQ(q.quoted.substr(0, 3), "\u2026");                 // cut before
  EXPECT_EQ(q.quoted.substr(q.quoted.size() - 3), "\u2026");  // and after
  // The end of the line is quoted whole, cut before.
  q = quote_of(list + "@]\n");
  EXPECT_EQ(q.under_caret, "@");
  EXPECT_EQ(q.quoted.substr(0, 3), "\u2026");
  EXPECT_EQ(q.quoted.substr(q.quoted.size() - 3), " @]");
  EXPECT_EQ(code_points(q.quoted).size(), 161U);
  // The start of the line is quoted whole, cut after.
  q = quote_of("let x = [@, " + list.substr(9) + "]\n");
  EXPECT_EQ(q.under_caret, "@");
  EXPECT_EQ(q.quoted.substr(0, 10), "let x = [@");
  EXPECT_EQ(code_points(q.quoted).size(), 161U);
  // Multi-byte characters count one column each, cut or not.
  q = quote_of("let s = \"" + [] {
    std::string e;
    for (int i = 0; i < 500; ++i) e += "\u00e9";
    return e;
  }() + "\" @\n");
  EXPECT_EQ(q.under_caret, "@");
  EXPECT_LE(code_points(q.quoted).size(), 162U);
  // Tabs and the underline as on a short line.
  q = quote_of("\tlet for = 1" + std::string(400, ' ') + "\n");
  EXPECT_EQ(q.under_caret, "f");
  EXPECT_EQ(q.underline, 2U);
}

TEST(Diagnostics, ScriptTooLargeIsRefused) {
  ParseOptions options;
  options.max_bytes = 16;
  const ParseResult result = parse("let x = 1\nlet y = 2\n", "big.hls", 0, options);
  ASSERT_EQ(result.diagnostics.size(), 1U);
  EXPECT_FALSE(result.ok());
  EXPECT_EQ(result.diagnostics[0].message,
            "script is too large: 20 bytes, and a script holds at most 16 bytes");
  EXPECT_EQ(result.source->position(result.diagnostics[0].span.begin).line, 1U);
  EXPECT_TRUE(parse("let x = 1\n", "small.hls", 0, options).ok());
}

TEST(Diagnostics, UnclosedBraceSaysWhereItOpened) {
  const ParseResult result = parse("let a = 1\nfor i in 0..3 {\n  draw x\n", "u.hls");
  ASSERT_EQ(result.diagnostics.size(), 1U);
  const Diagnostic& d = result.diagnostics[0];
  EXPECT_EQ(d.message, "expected a statement or '}' (to close '{' at line 2)");
  ASSERT_EQ(d.notes.size(), 1U);
  EXPECT_EQ(result.source->position(d.notes[0].span.begin).line, 2U);
  EXPECT_EQ(result.source->position(d.notes[0].span.begin).column, 15U);
  EXPECT_NE(format(d, *result.source).find("u.hls:2:15: note: '{' opened here\n"), std::string::npos);
}

TEST(Diagnostics, ErrorInSolidDoesNotHideLaterErrors) {
  EXPECT_EQ(errors("solid a {\n  vertex 1 (0, 0, 0)\n  face 1 2 3\n}\nlet = 3\ndraw\n"),
            (std::vector<std::string>{
                "2:12: expected '=' after the vertex id, as in 'vertex 1 = (0, 0, 0)'",
                "5:5: expected a name after 'let', as in 'let x = 1'",
                "6:5: expected what to draw after 'draw', as in 'draw box'",
            }));
}

TEST(Diagnostics, RecoversAfterMissingBraceOfSolid) {
  EXPECT_EQ(errors("solid a {\n  vertex 1 = (0, 0, 0)\n\ncamera c lookat()\n"),
            (std::vector<std::string>{
                "2:23: expected 'vertex', 'face', 'line' or '}' in the solid (to close '{' at line 1)",
                "4:10: expected '=' after the camera name, as in 'camera main = lookat(...)'",
            }));
}

TEST(Diagnostics, UnclosedSolidOptions) {
  const ParseResult result =
      parse("solid hull (planarity: 0.003, crossing_holes: true {\n  vertex 1 = (0, 0, 0)\n}\n", "s.hls");
  ASSERT_EQ(result.diagnostics.size(), 1U);
  EXPECT_EQ(format(result.diagnostics[0], *result.source),
            "s.hls:1:52: error: expected ',' or ')' in the solid's options (to close '(' at line 1)\n"
            "   1 | solid hull (planarity: 0.003, crossing_holes: true {\n"
            "     |                                                    ^\n"
            "hint: options are 'name: value' pairs separated by ',', as in 'solid hull (crease: 30, "
            "planarity: 0.003) { ... }'\n"
            "s.hls:1:12: note: '(' opened here\n"
            "   1 | solid hull (planarity: 0.003, crossing_holes: true {\n"
            "     |            ^\n");
}

TEST(Diagnostics, RecoversAfterBrokenSolidOptions) {
  // The solid's body is skipped as a whole; the next statement is parsed.
  EXPECT_EQ(errors("solid a (crease: 30 {\n  vertex 1 = (0, 0, 0)\n}\nlet = 3\n"),
            (std::vector<std::string>{
                "1:21: expected ',' or ')' in the solid's options (to close '(' at line 1)",
                "4:5: expected a name after 'let', as in 'let x = 1'",
            }));
  EXPECT_EQ(
      errors("solid a (crease: 30,) {\n}\nsolid b (x: 1 y: 2) {\n}\n"),
      (std::vector<std::string>{
          "1:21: expected an option after ',' in the solid's options, as in '(crease: 30, planarity: 0.003)'",
          "3:15: expected ',' or ')' in the solid's options (to close '(' at line 3)",
      }));
}

TEST(Diagnostics, RecoversInsideOneLineBlocks) {
  // After an error inside a statement the parser skips to the next statement keyword that starts a
  // line or follows a '}' closing the broken statement: 'x = 1' and '}' are skipped here.
  EXPECT_EQ(errors("for i in 0..4 { draw } draw @\nx = 1\n}\nlet y = 2\nlet = 1\n"),
            (std::vector<std::string>{
                "1:22: expected what to draw after 'draw', as in 'draw box'",
                "1:29: unexpected character '@'",
                "5:5: expected a name after 'let', as in 'let x = 1'",
            }));
}

TEST(Diagnostics, RecoversLineByLineBetweenStatements) {
  EXPECT_EQ(errors("x = 1\n}\nelse { }\nface 1 2 3\nlet = 1\n"),
            (std::vector<std::string>{
                "1:1: expected a statement, found 'x'",
                "2:1: unexpected '}' with no '{' open",
                "3:1: 'else' without an 'if' before it",
                "4:1: 'face' belongs inside a solid",
                "5:5: expected a name after 'let', as in 'let x = 1'",
            }));
}

TEST(Diagnostics, StaticChecksComeWithSyntaxErrorsInSourceOrder) {
  EXPECT_EQ(errors("return 1\nlet = 2\n"), (std::vector<std::string>{
                                               "1:1: 'return' outside a function body",
                                               "2:5: expected a name after 'let', as in 'let x = 1'",
                                           }));
}

TEST(Diagnostics, StopsAfterTooManyErrors) {
  std::string text;
  for (int i = 0; i < 50; ++i) text += "let = 1\n";
  const auto all = errors(text);
  ASSERT_EQ(all.size(), kMaxErrors + 1);
  EXPECT_EQ(all.back(), "20:5: too many errors (the limit is 20); stopping here");
}

TEST(Diagnostics, DeepNestingIsAnErrorNotACrash) {
  EXPECT_EQ(first_error("let x = " + std::string(10000, '(') + "1" + std::string(10000, ')')),
            "1:73: too many nested brackets, blocks or prefix operators (the limit is 64)");
  EXPECT_EQ(first_error("let x = " + std::string(100000, '-') + "1"),
            "1:74: too many nested brackets, blocks or prefix operators (the limit is 64)");
  std::string chain = "let x = 1";
  for (int i = 0; i < 5000; ++i) chain += " + 1";
  EXPECT_EQ(first_error(chain), "1:9: expression too deep: more than 256 nested operations");
  std::string elses = "if a {}";
  for (int i = 0; i < 5000; ++i) elses += " else if a {}";
  EXPECT_EQ(first_error(elses).substr(0, 20), "1:838: too many nest");
  // Right at the limit still parses.
  EXPECT_TRUE(parse("let x = " + std::string(63, '[') + "1" + std::string(63, ']'), "ok.hls").ok());
}

}  // namespace
}  // namespace hlr::lang
