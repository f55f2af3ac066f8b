// The grammar alone, rule by rule (PEGTL's rule_*.cpp style): rows of input -> success, local
// failure (the rule does not match, the caller may try something else) or global failure (a must<>
// raised, with its message). No actions run here.
#include "lang/grammar.hpp"

#include <gtest/gtest.h>

#include <string>
#include <tao/pegtl/contrib/analyze.hpp>

#include "lang/parse_control.hpp"

namespace hlr::lang {
namespace {

namespace g = grammar;
namespace pegtl = tao::pegtl;

enum class Outcome { Success, Local, Global };

struct Row {
  const char* input;
  Outcome outcome;
  const char* message = "";  // start of the message, for Global rows
};

template <typename Rule>
std::pair<Outcome, std::string> match_whole(const std::string& input) {
  detail::ParseState state;
  pegtl::memory_input in(input, "row");
  try {
    const bool ok = pegtl::parse<pegtl::seq<Rule, pegtl::eof>, pegtl::nothing, detail::control>(in, state);
    return {ok ? Outcome::Success : Outcome::Local, ""};
  } catch (const detail::SyntaxError& e) {
    return {Outcome::Global, e.message};
  }
}

template <typename Rule>
void check_rows(std::initializer_list<Row> rows) {
  for (const Row& row : rows) {
    const auto [outcome, message] = match_whole<Rule>(row.input);
    EXPECT_EQ(outcome, row.outcome) << "input: " << row.input << "\nmessage: " << message;
    if (row.outcome == Outcome::Global) {
      EXPECT_EQ(message.rfind(row.message, 0), 0U) << "input: " << row.input << "\nmessage: " << message;
    }
  }
}

constexpr Outcome S = Outcome::Success;
constexpr Outcome L = Outcome::Local;
constexpr Outcome G = Outcome::Global;

TEST(Grammar, AnalyzeFindsNoProblems) {
  EXPECT_EQ(pegtl::analyze<g::script>(-1), 0U);
  EXPECT_EQ(pegtl::analyze<g::expression>(-1), 0U);
}

TEST(Grammar, Padding) {
  check_rows<g::sp>({{"", S}, {"  \t\n", S}, {"# note\n  # more", S}, {"#", S}, {"x", L}});
}

TEST(Grammar, Keywords) {
  check_rows<g::key_for>({{"for", S}, {"format", L}, {"for_", L}, {"fo", L}});
  check_rows<g::name>(
      {{"x", S}, {"_a1", S}, {"format", S}, {"for", L}, {"then", L}, {"1x", L}, {"vertex", S}});
}

TEST(Grammar, Numbers) {
  check_rows<g::number>({{"0", S},
                         {"48", S},
                         {"112.5", S},
                         {"1e3", S},
                         {"1.5E-2", S},
                         {"2e+10", S},
                         {".5", L},
                         {"1.2.3", G, "malformed number: a number has at most one decimal point"},
                         {"2x", G, "malformed number: a letter follows the digits"},
                         {"1e", G, "expected digits after the exponent"},
                         {"1.", L}});
}

TEST(Grammar, Strings) {
  check_rows<g::string_lit>({{"\"\"", S},
                             {"\"bunny.off\"", S},
                             {"\"landing-{frame:03}.pdf\"", S},
                             {"\"{a + b}\"", S},
                             {"\"a\\\"b\\\\c\\n\\{\"", S},
                             {"\"é ü\"", S},
                             {"\"abc", G, "unterminated string"},
                             {"\"abc\ndef\"", G, "unterminated string"},
                             {"\"\\q\"", G, "unknown escape"},
                             {"\"{}\"", G, "expected an expression inside '{...}'"},
                             {"\"{x\"", G, "expected '}' to end the '{...}'"},
                             {"x", L}});
}

TEST(Grammar, ParensAndVectors) {
  check_rows<g::paren_expr>({{"(1)", S},
                             {"( 1 + 2 )", S},
                             {"(0, 10, 0)", S},
                             {"(1914, 151, 112.5)", S},
                             {"(-x, y * 2, f(z))", S},
                             {"()", G, "expected an expression after '('"},
                             {"(1", G, "expected ')' or ','"},
                             {"(1, 2)", S},
                             {"(1, 2 3)", G, "expected ')' or ',' and a third component"},
                             {"(1, 2, 3, 4)", G, "expected ')' after the third component"},
                             {"(1,)", G, "expected the second component"},
                             {"(1, 2,)", G, "expected the third component"}});
}

TEST(Grammar, Lists) {
  check_rows<g::list_lit>({{"[]", S},
                           {"[1]", S},
                           {"[1, (0, 0, 0), [2]]", S},
                           {"[1,]", G, "expected a list element after ','"},
                           {"[1 2]", G, "expected ',' or ']'"},
                           {"[1", G, "expected ',' or ']'"}});
}

TEST(Grammar, ListComprehensions) {
  check_rows<g::list_lit>({{"[i * i for i in 0..10]", S},
                           {"[i for i in 0..10 if i % 2 == 0]", S},
                           {"[ p.x for p in ps if p.y > 0 ]", S},
                           {"[[j for j in 0..i] for i in 0..4]", S},
                           {"[f(x) for x in [1, 2] if not done(x)]", S},
                           {"[x\nfor x # note\nin l]", S},
                           {"[x for]", G, "expected the comprehension's variable after 'for'"},
                           {"[x for 1 in l]", G, "expected the comprehension's variable after 'for'"},
                           {"[x for x l]", G, "expected 'in' after the comprehension's variable"},
                           {"[x for x in]", G, "expected a range or list after 'in'"},
                           {"[x for x in l if]", G, "expected a condition after 'if'"},
                           {"[x for x in l", G, "expected ']' to end the comprehension"},
                           {"[x for x in l, 2]", G, "expected ']' to end the comprehension"},
                           {"[x for x in l if a if b]", G, "expected ']' to end the comprehension"},
                           {"[x for x in l for y in m]", G, "expected ']' to end the comprehension"},
                           {"[1, x for x in l]", G, "expected ',' or ']'"},
                           {"[for x in l]", G, "expected ',' or ']'"}});
  // `for`, `in` and `if` stay reserved: never names, so never the start of an item.
  check_rows<g::name>({{"for", L}, {"in", L}, {"if", L}, {"format", S}, {"index", S}, {"iffy", S}});
}

TEST(Grammar, Postfix) {
  check_rows<g::postfix_expr>({{"f()", S},
                               {"f(1, 2)", S},
                               {"lookat(eye: (30, 20, 15), fov: 40)", S},
                               {"rotate(z: 30)", S},
                               {"v.x", S},
                               {"l[0]", S},
                               {"a.b[1](2).c", S},
                               {"f(1,)", G, "expected an argument after ','"},
                               {"f(1", G, "expected ',' or ')'"},
                               {"f(eye: )", G, "expected a value after the argument name"},
                               {"v.", G, "expected a member name after '.'"},
                               {"v.1", G, "expected a member name"},
                               {"l[]", G, "expected an index after '['"},
                               {"l[0", G, "expected ']' after the index"}});
}

TEST(Grammar, ExpressionLevels) {
  check_rows<g::expression>({{"1 + 2 * 3", S},
                             {"-x", S},
                             {"- - x", S},
                             {"2*i", S},
                             {"0..4", S},
                             {"0 .. n - 1", S},
                             {"a == b", S},
                             {"a <= b and not c or d", S},
                             {"rotate(z: 30) then scale(2)", S},
                             {"true", S},
                             {"1 +", G, "expected an operand after the operator"},
                             {"1 *", G, "expected an operand after the operator"},
                             {"-", G, "expected an operand after '-'"},
                             {"not", G, "expected an operand after 'not'"},
                             {"a and", G, "expected an operand after 'and'"},
                             {"a or", G, "expected an operand after 'or'"},
                             {"a then", G, "expected a transform after 'then'"},
                             {"0..", G, "expected the end of the range"},
                             {"0..1..2", G, "a range has one '..'"},
                             {"a <", G, "expected an operand after the comparison"},
                             {"a < b < c", G, "comparisons do not chain"},
                             {"then", L},
                             {"@", L}});
}

TEST(Grammar, SolidItems) {
  check_rows<g::vertex_decl>({{"vertex 1 = (0, 10, 0)", S},
                              {"vertex top = (0, 10, h)", S},
                              {"vertex 1 (0, 0, 0)", G, "expected '=' after the vertex id"},
                              {"vertex = (0, 0, 0)", G, "expected a vertex id"},
                              {"vertex 1 =", G, "expected the vertex position"},
                              {"vertex 1 == (0,0,0)", G, "expected '=' after the vertex id"}});
  check_rows<g::face_decl>({{"face 1 top 3 4", S},
                            {"face 5 6 7 8 hole 9 10 11", S},
                            {"face 1 2 3 4 hole 5 6 7 hole 8 9 10", S},
                            {"face", G, "expected vertex ids after 'face'"},
                            {"face 1 2 hole", G, "expected vertex ids after 'hole'"}});
  check_rows<g::line_decl>({{"line 12 13", S},
                            {"line a b", S},
                            {"line", G, "expected two vertex ids after 'line'"},
                            {"line 12", G, "expected a second vertex id"}});
}

TEST(Grammar, SolidStatement) {
  check_rows<g::solid_stmt>({{"solid a {}", S},
                             {"solid lblock {\n vertex 1 = (0,10,0)\n face 1 2 3\n line 1 2\n}", S},
                             {"solid {}", G, "expected a name after 'solid'"},
                             {"solid a", G, "expected '{' after the solid's name"},
                             {"solid a { vertex 1 = (0,0,0)", G, "expected 'vertex', 'face', 'line' or '}'"},
                             {"solid a { draw x }", G, "expected 'vertex', 'face', 'line' or '}'"}});
}

TEST(Grammar, SolidOptions) {
  check_rows<g::solid_stmt>(
      {{"solid a (crease: 30) {}", S},
       {"solid a(crease:30){}", S},
       {"solid a (crease: 30, planarity: 0.003,\n crossing_holes: true, fix_winding: false) {}", S},
       {"solid a () {}", S},
       {"solid a (30) {}", S},  // parses: the runtime says options need names
       {"solid a (crease: 2 * c) {}", S},
       {"solid a (crease: 30 {}", G, "expected ',' or ')' in the solid's options"},
       {"solid a (crease 30) {}", G, "expected ',' or ')' in the solid's options"},
       {"solid a (crease: 30,) {}", G, "expected an option after ',' in the solid's options"},
       {"solid a (crease:) {}", G, "expected a value after the argument name and ':'"},
       {"solid a (crease: 30)", G, "expected '{' after the solid's name"},
       {"solid a (crease: 30) vertex 1 = (0, 0, 0)", G, "expected '{' after the solid's name"}});
  check_rows<g::solid_options>(
      {{"(crease: 30)", S}, {"()", S}, {"crease: 30", L}, {"(", G, "expected ',' or ')'"}});
}

TEST(Grammar, Statements) {
  check_rows<g::statement>({
      {"let m = import(\"bunny.off\")", S},
      {"let = 3", G, "expected a name after 'let'"},
      {"let x 3", G, "expected '=' after the name"},
      {"let x =", G, "expected a value after '='"},
      {"def post(h) = prism(regular(6, 0.5), h)", S},
      {"def f(a, b = 2) { let c = a * b return c }", S},
      {"def f() = 1", S},
      {"def (a) = 1", G, "expected a function name"},
      {"def f = 1", G, "expected '(' and the parameters"},
      {"def f(a,) = 1", G, "expected a parameter name after ','"},
      {"def f(a b) = 1", G, "expected a parameter name, ',' or ')'"},
      {"def f(a)", G, "expected '= expression' or a '{ ... }' body"},
      {"def f(a) =", G, "expected the function's expression"},
      {"def f(a = ) = 1", G, "expected a default value"},
      {"for i in 0..4 { draw post(1 + i) at translate(2*i, 0, 0) }", S},
      {"for i in [1, 2] {}", S},
      {"for in 0..4 {}", G, "expected the loop variable"},
      {"for i 0..4 {}", G, "expected 'in' after the loop variable"},
      {"for i in {}", G, "expected a range or list after 'in'"},
      {"for i in 0..4", G, "expected '{' to start the loop body"},
      {"for i in 0..4 { draw x", G, "expected a statement or '}'"},
      {"if a { } else { }", S},
      {"if a { } else if b { }", S},
      {"if { }", G, "expected a condition after 'if'"},
      {"if a", G, "expected '{' after the condition"},
      {"if a {} else", G, "expected '{' or 'if' after 'else'"},
      {"draw lblock", S},
      {"draw m at rotate(z: 30) then scale(2)", S},
      {"draw", G, "expected what to draw after 'draw'"},
      {"draw x at", G, "expected a transform after 'at'"},
      {"camera main = lookat(eye: (30, 20, 15), target: (0, 0, 0), up: (0, 0, 1), fov: 40)", S},
      {"camera = orbit()", G, "expected a camera name"},
      {"camera c lookat()", G, "expected '=' after the camera name"},
      {"camera c =", G, "expected a camera after '='"},
      {"animate frames 48 fps 12", S},
      {"animate frames 48", S},
      {"animate 48", G, "expected 'frames' after 'animate'"},
      {"animate frames", G, "expected the number of frames"},
      {"animate frames 48 fps", G, "expected frames per second"},
      {"output \"landing-{frame:03}.pdf\" paper A4 landscape", S},
      {"output \"x.svg\" portrait", S},
      {"output x.pdf", G, "expected a quoted file name after 'output'"},
      {"output \"x.pdf\" paper", G, "expected a paper size"},
      {"paper A4", S},
      {"paper letter landscape", S},
      {"paper", G, "expected a paper size"},
      {"style hidden dashed", S},
      {"style hidden off", S},
      {"style dashed", G, "expected 'hidden' after 'style'"},
      {"style hidden dotted", G, "expected 'dashed', 'off' or 'levels N'"},
      {"include \"parts.hls\"", S},
      {"include parts", G, "expected a quoted file name after 'include'"},
      {"return", S},
      {"return x + 1", S},
      {"x = 1", L},
      {"vertex 1 = (0, 0, 0)", L},
  });
}

TEST(Grammar, PaperOptions) {
  check_rows<g::paper_stmt>(
      {{"paper A4 (margin: 10)", S},
       {"paper A4 landscape (margin: 10, scale: 0.5)", S},
       {"paper custom (width: 300, height: 200)", S},
       {"paper custom portrait (width: 300, height: 200, margin: 5)", S},
       {"paper A4 ()", S},
       {"paper A4 (10)", S},  // parses: the runtime says options need names
       {"paper A4 (margin: 10", G, "expected ',' or ')' in the paper's options"},
       {"paper A4 (margin 10)", G, "expected ',' or ')' in the paper's options"},
       {"paper A4 (margin: 10,)", G, "expected an option after ',' in the paper's options"},
       {"paper A4 (margin:)", G, "expected a value after the argument name and ':'"}});
  check_rows<g::paper_options>({{"(margin: 1)", S}, {"margin: 1", L}, {"(", G, "expected ',' or ')'"}});
}

TEST(Grammar, OutputPaperAndPlotter) {
  check_rows<g::output_stmt>(
      {{"output \"x.pdf\" paper A4 landscape (margin: 10)", S},
       {"output \"x.pdf\" paper custom (width: 100, height: 80)", S},
       {"output \"x.hpgl\" plotter hp7475a", S},
       {"output \"x.hpgl\" paper A4 plotter \"roland-dxy\"", S},
       {"output \"x.hpgl\" paper A3 portrait (scale: 2) plotter mine", S},
       {"output \"x.hpgl\" landscape plotter mine", S},
       {"output \"x.hpgl\" plotter", G, "expected a plotter name after 'plotter'"},
       {"output \"x.hpgl\" plotter 7", G, "expected a plotter name after 'plotter'"},
       {"output \"x.pdf\" paper A4 (margin: 1", G, "expected ',' or ')' in the paper's"},
       // `plotter NAME {` starts a plotter statement, not the output's clause
       {"output \"x.hpgl\" plotter mine {}", L}});
}

TEST(Grammar, Pens) {
  check_rows<g::pen_stmt>({{"pen 2 (colour: \"red\", width: 0.35)", S},
                           {"pen 2(color: \"#f00\")", S},
                           {"pen 2 ()", S},
                           {"pen n (width: 0.5)", S},
                           {"pen (i + 1) (width: 0.5)", S},
                           {"pen 2", G, "expected '(' and the pen's options after the pen number"},
                           {"pen \"red\" (width: 1)", G, "expected the pen number after 'pen'"},
                           {"pen (colour: \"red\")", G, "expected the pen number after 'pen'"},
                           {"pen -1 (width: 1)", G, "expected the pen number after 'pen'"},
                           {"pen 2 (width: 1", G, "expected ',' or ')' in the pen's options"},
                           {"pen 2 (width: 1,)", G, "expected an option after ',' in the pen's options"},
                           {"pen", G, "expected the pen number after 'pen'"}});
  check_rows<g::draw_stmt>({{"draw x pen 2", S},
                            {"draw x at t pen n + 1", S},
                            {"draw x pen f(i)", S},
                            {"draw pen", S},  // a name here
                            {"draw x pen", G, "expected a pen number after 'pen', as in 'draw box pen 2'"},
                            {"draw x pen 2 (colour: \"red\")", L},  // a draw, then a pen statement
                            {"draw x pen 2 ()", L}});
  check_rows<g::style_stmt>(
      {{"style hidden dashed pen 2", S},
       {"style hidden off pen 2", S},  // parses: the syntax check reports it
       {"style hidden dashed pen", G, "expected a pen number after 'pen'"},
       {"style hidden levels 3", S},
       {"style hidden levels n pen 2", S},
       {"style hidden levels (k + 1) pen p", S},
       {"style hidden levels -1", S},  // parses: the evaluator says the range
       {"style hidden levels", G, "expected how many occlusion levels to draw after 'levels'"},
       {"style hidden levels pen 2", G, "expected how many occlusion levels"},
       {"style hidden levelsx", G, "expected 'dashed', 'off' or 'levels N'"}});
}

TEST(Grammar, Plotters) {
  check_rows<g::plotter_stmt>(
      {{"plotter mine { base: \"hp7475a\", pens: 6 }", S},
       {"plotter mine {\n  base: \"hp7475a\"\n  unit: 0.025  # comment\n  velocity: 2 * 20\n}", S},
       {"plotter mine { base: \"hp7475a\" pens: 6, newline: true }", S},
       {"plotter mine {}", S},
       {"plotter { }", G, "expected a name after 'plotter'"},
       {"plotter mine", G, "expected '{' after the plotter's name"},
       {"plotter mine { pens 6 }", G, "expected 'key: value' or '}' in the plotter"},
       {"plotter mine { pens: }", G, "expected a value after the key and ':'"},
       {"plotter mine { pens: 6, }", G, "expected 'key: value' after ',' in the plotter"},
       {"plotter mine { pens: 6", G, "expected 'key: value' or '}' in the plotter"}});
}

TEST(Grammar, DeviceWordsAreContextual) {
  check_rows<g::script>({{"draw a\npen 2 (colour: \"red\")", S},
                         {"draw a pen 2\npen 3 (width: 1)", S},
                         {"draw a at t\npen (k) ()", S},
                         {"style hidden dashed\npen 1 (width: 0.2)", S},
                         {"style hidden levels 2\npen 1 (width: 0.2)", S},
                         {"let levels = 2 style hidden levels levels", S},
                         {"output \"x.hpgl\"\nplotter mine { pens: 2 }", S},
                         {"output \"x.hpgl\" plotter mine\nplotter mine { pens: 2 }", S},
                         {"let pen = 1 let plotter = 2 draw x pen pen + plotter", S},
                         {"let x = pen", S}});
}

TEST(Grammar, Script) {
  check_rows<g::script>({{"", S},
                         {"  # only a comment\n", S},
                         {"let a = 1 let b = 2", S},
                         {"let a = 1\n\ndraw a", S},
                         {"draw a\n@", G, "expected a statement"}});
}

}  // namespace
}  // namespace hlr::lang
