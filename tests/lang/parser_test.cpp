// Every line of DESIGN.md's sketch parses into the expected AST: node kinds, names, numbers, spans.
#include "lang/parser.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

namespace hlr::lang {
namespace {

Script parse_ok(const std::string& text) {
  ParseResult result = parse(text, "test.hls");
  std::string shown;
  for (const auto& d : result.diagnostics) shown += format(d, *result.source);
  EXPECT_TRUE(result.ok()) << shown;
  return result.ok() ? std::move(*result.script) : Script{};
}

// The S-expression of a one-statement script.
std::string ast(const std::string& text) {
  const Script script = parse_ok(text);
  return script.statements.size() == 1 ? dump(script.statements[0]) : "<" + dump(script) + ">";
}

std::string span_text(const std::string& text, const SourceSpan& span) {
  return text.substr(span.begin, span.end - span.begin);
}

// Line and column of a span's offset: spans hold offsets, the file knows its lines.
SourcePos at(const std::string& text, std::uint32_t offset) {
  return SourceFile(0, "test.hls", text).position(offset);
}

const char* kSketch = R"(# comments with '#'
solid lblock {                     # a solid: vertices and faces; declaring does not draw
  vertex 1 = (0, 10, 0)            # vertex ids: integers or identifiers
  vertex top = (0, 10, 5)
  face 1 top 3 4                   # counter-clockwise seen from outside
  face 5 6 7 8 hole 9 10 11        # a face with a hole
  line 12 13                       # a marking line on the surface (drawn, hides nothing)
}
let m = import("bunny.off")        # OFF / OBJ / STL meshes
def post(h) = prism(regular(6, 0.5), h)
for i in 0..4 { draw post(1 + i) at translate(2*i, 0, 0) }
draw lblock
draw m at rotate(z: 30) then scale(2)
camera main = lookat(eye: (30, 20, 15), target: (0, 0, 0), up: (0, 0, 1), fov: 40)
camera albers = orbit(theta: 45, phi: 60, rho: 425, d: 1549)            # Albers' viewpoint
camera cockpit = desens(object: (126, 0, 0), attitude: (0, 0, 0),       # Desens' 12 degrees
                        observer: (1914, 151, 112.5), heading: (10, 0, 0),
                        focal: 1.5, scale: 0.5)
animate frames 48 fps 12           # whole script is evaluated per frame with frame, t (0..1), time
output "landing-{frame:03}.pdf" paper A4 landscape
style hidden dashed                # optional hidden-line layer (dashed in PDF, second pen on HPGL)
)";

TEST(Parser, DesignSketchAsAWhole) {
  const Script script = parse_ok(kSketch);
  EXPECT_EQ(
      dump(script),
      "(solid lblock (vertex 1 (vec 0 10 0)) (vertex top (vec 0 10 5)) (face 1 top 3 4) "
      "(face 5 6 7 8 (hole 9 10 11)) (line 12 13))\n"
      "(let m (call import \"bunny.off\"))\n"
      "(def post (h) (call prism (call regular 6 0.5) h))\n"
      "(for i (.. 0 4) (block (draw (call post (+ 1 i)) at (call translate (* 2 i) 0 0))))\n"
      "(draw lblock)\n"
      "(draw m at (then (call rotate z:30) (call scale 2)))\n"
      "(camera main (call lookat eye:(vec 30 20 15) target:(vec 0 0 0) up:(vec 0 0 1) fov:40))\n"
      "(camera albers (call orbit theta:45 phi:60 rho:425 d:1549))\n"
      "(camera cockpit (call desens object:(vec 126 0 0) attitude:(vec 0 0 0) observer:(vec 1914 151 112.5) "
      "heading:(vec 10 0 0) focal:1.5 scale:0.5))\n"
      "(animate 48 fps 12)\n"
      "(output (str \"landing-\" (fmt frame \"03\") \".pdf\") A4 landscape)\n"
      "(style hidden dashed)\n");
  ASSERT_EQ(script.statements.size(), 12U);
  // Statement spans: from the keyword to the end of the statement, comments excluded.
  const std::string text = kSketch;
  EXPECT_EQ(span_text(text, script.statements[1].span), "let m = import(\"bunny.off\")");
  EXPECT_EQ(at(text, script.statements[0].span.begin).line, 2U);
  EXPECT_EQ(at(text, script.statements[0].span.end).line, 8U);
  EXPECT_EQ(at(text, script.statements[8].span.begin).line, 16U);  // camera cockpit, over three lines
  EXPECT_EQ(at(text, script.statements[8].span.end).line, 18U);
  EXPECT_EQ(span_text(text, script.statements[11].span), "style hidden dashed");
}

// A vertex position of three plain numbers on one line takes the literal path; anything more is an
// expression. Either way the tree reads the same: the literal path is only a shortcut.
TEST(Parser, LiteralVertexPositionsAreTheExpressionsTheyLookLike) {
  // Whether the position took the literal path (and then has no expression), and its numbers.
  struct Read {
    bool literal = false, has_expression = false;
    std::array<double, 3> xyz{};
  };
  const auto vertex = [](const std::string& position) {
    const Script script = parse_ok("solid s {\n  vertex a = " + position + "\n  face a a a\n}\n");
    const SolidBody& body = std::get<SolidStmt>(script.statements.at(0).node).body;
    const SolidBody::Vertex& v = body.vertices().at(0);
    const bool literal = v.position == SolidBody::kLiteral;
    return Read{literal, body.position_count() > 0, literal ? v.at : std::array<double, 3>{}};
  };
  const auto dump_of = [](const std::string& position) {
    return dump(parse_ok("solid s {\n  vertex a = " + position + "\n  face a a a\n}\n").statements.at(0));
  };
  for (const char* literal : {"(1, 2, 3)", "(-1.5, 0.25e2, -0)", "(1,2,3)", "(  7 ,\t8 , 9  )",
                              "(1e-3, -2E+2, 3.0)", "(1, 2, 3)  # a comment"}) {
    const Read v = vertex(literal);
    EXPECT_TRUE(v.literal) << literal;
    EXPECT_FALSE(v.has_expression) << literal;
    // Broken across lines, the same position is an expression; its tree prints the same.
    std::string split = literal;
    split.insert(split.find(',') + 1, "\n");
    EXPECT_FALSE(vertex(split).literal) << split;
    EXPECT_EQ(dump_of(literal), dump_of(split)) << literal;
  }
  EXPECT_EQ(vertex("(-1.5, 0.25e2, -0)").xyz[1], 25.0);
  EXPECT_TRUE(std::signbit(vertex("(-1.5, 0.25e2, -0)").xyz[2]));
  for (const char* expression : {"(1, 2, 3) + (0, 0, 1)", "(x, 2, 3)", "(- 1, 2, 3)", "(1, 2, 3) then 4",
                                 "(1, 2, 3 + 1)", "((1), 2, 3)"}) {
    const std::string text = "let x = 1\nsolid s {\n  vertex a = " + std::string(expression) + "\n}\n";
    const ParseResult r = parse(text, "t.hls", 0);
    if (!r.script) continue;  // an error (then 4) is the expression grammar's
    const SolidBody& body = std::get<SolidStmt>(r.script->statements.at(1).node).body;
    EXPECT_NE(body.vertices().at(0).position, SolidBody::kLiteral) << expression;
    EXPECT_EQ(body.position_count(), 1U) << expression;
  }
  // A malformed number is the same error either way.
  const ParseResult bad = parse("solid s {\n  vertex a = (1.2.3, 0, 0)\n}\n", "t.hls", 0);
  ASSERT_FALSE(bad.diagnostics.empty());
  EXPECT_NE(bad.diagnostics[0].message.find("at most one decimal point"), std::string::npos);
  const ParseResult huge = parse("solid s {\n  vertex a = (1e999, 0, 0)\n}\n", "t.hls", 0);
  ASSERT_FALSE(huge.diagnostics.empty());
  EXPECT_NE(huge.diagnostics[0].message.find("number out of range"), std::string::npos);
}

TEST(Parser, SolidNodes) {
  const std::string text =
      "solid lblock {\n  vertex 1 = (0, 10, 0)\n  vertex top = (0, 10, 5)\n"
      "  face 1 top 3 4\n  face 5 6 7 8 hole 9 10 11\n  line 12 13\n}\n";
  const Script script = parse_ok(text);
  const auto& solid = std::get<SolidStmt>(script.statements.at(0).node);
  EXPECT_EQ(solid.name.text, "lblock");
  EXPECT_EQ(span_text(text, solid.name.span), "lblock");
  const SolidBody& body = solid.body;
  ASSERT_EQ(body.items().size(), 5U);
  const auto item_text = [&](std::size_t k) {
    return text.substr(body.items()[k].begin, body.items()[k].end - body.items()[k].begin);
  };
  EXPECT_EQ(item_text(0), "vertex 1 = (0, 10, 0)");
  EXPECT_EQ(item_text(3), "face 5 6 7 8 hole 9 10 11");
  EXPECT_EQ(item_text(4), "line 12 13");
  ASSERT_EQ(body.vertices().size(), 2U);
  const auto id = [&](std::uint32_t k) { return std::string(body.id(k)); };
  EXPECT_EQ(id(body.vertices()[0].id), "1");
  // Three plain numbers are read straight into the declaration.
  EXPECT_EQ(body.vertices()[0].position, SolidBody::kLiteral);
  EXPECT_EQ(body.vertices()[0].at, (std::array<double, 3>{0, 10, 0}));
  EXPECT_EQ(id(body.vertices()[1].id), "top");
  ASSERT_EQ(body.face_count(), 2U);
  ASSERT_EQ(body.ring_count(0), 1U);
  ASSERT_EQ(body.ring(0, 0).size(), 4U);
  EXPECT_EQ(id(body.ring(0, 0)[1]), "top");
  EXPECT_EQ(body.ring(0, 0)[0], body.vertices()[0].id);  // one id, interned once
  ASSERT_EQ(body.ring_count(1), 2U);
  EXPECT_EQ(body.ring(1, 1).size(), 3U);
  EXPECT_EQ(id(body.ring(1, 1)[2]), "11");
  ASSERT_EQ(body.lines().size(), 1U);
  EXPECT_EQ(id(body.lines()[0][0]), "12");
  EXPECT_EQ(id(body.lines()[0][1]), "13");
  // A number is its value: "007" and "7" are one vertex.
  const Script zeros = parse_ok("solid s {\n  vertex 007 = (0, 0, 0)\n  line 7 0007\n}\n");
  const SolidBody& zb = std::get<SolidStmt>(zeros.statements.at(0).node).body;
  ASSERT_EQ(zb.id_count(), 1U);
  EXPECT_EQ(zb.id(0), "7");
}

TEST(Parser, SolidOptions) {
  const std::string text =
      "solid carrier (planarity: 0.003, crossing_holes: true) {\n  vertex 1 = (0, 0, 0)\n  face 1 2 3\n}\n";
  EXPECT_EQ(ast(text),
            "(solid carrier (options planarity:0.003 crossing_holes:true) (vertex 1 (vec 0 0 0)) "
            "(face 1 2 3))");
  const Script script = parse_ok(text);
  const auto& solid = std::get<SolidStmt>(script.statements.at(0).node);
  EXPECT_EQ(solid.name.text, "carrier");
  ASSERT_EQ(solid.options.size(), 2U);
  ASSERT_EQ(solid.body.items().size(), 2U);
  EXPECT_EQ(solid.options[0].label->text, "planarity");
  EXPECT_EQ(span_text(text, solid.options[0].span), "planarity: 0.003");
  EXPECT_EQ(span_text(text, solid.options[0].label->span), "planarity");
  EXPECT_EQ(span_text(text, solid.options[0].value->span), "0.003");
  EXPECT_EQ(at(text, solid.options[1].span.begin).column, 34U);
  EXPECT_TRUE(std::get<BoolLit>(solid.options[1].value->node).value);
  EXPECT_EQ(span_text(text, script.statements[0].span), text.substr(0, text.size() - 1));

  // Expressions, positional values (the runtime rejects them), an empty list, no list, over lines.
  EXPECT_EQ(ast("solid s (crease: 2 * c, 30) {}"), "(solid s (options crease:(* 2 c) 30))");
  EXPECT_EQ(ast("solid s () {}"), "(solid s)");
  EXPECT_EQ(ast("solid s {}"), "(solid s)");
  EXPECT_EQ(ast("solid s(\n  crease: 30,   # degrees\n  fix_winding: false\n){ face 1 2 3 }"),
            "(solid s (options crease:30 fix_winding:false) (face 1 2 3))");
  EXPECT_TRUE(std::get<SolidStmt>(parse_ok("solid s {}").statements.at(0).node).options.empty());
}

TEST(Parser, CallsWithNamedArguments) {
  const std::string text =
      "camera main = lookat(eye: (30, 20, 15), target: (0, 0, 0), up: (0, 0, 1), fov: 40)";
  const Script script = parse_ok(text);
  const auto& cam = std::get<CameraStmt>(script.statements.at(0).node);
  EXPECT_EQ(cam.name.text, "main");
  const auto& call = std::get<CallExpr>(cam.value->node);
  EXPECT_EQ(std::get<NameRef>(call.callee->node).name, "lookat");
  ASSERT_EQ(call.args.size(), 4U);
  EXPECT_EQ(call.args[0].label->text, "eye");
  EXPECT_EQ(span_text(text, call.args[0].span), "eye: (30, 20, 15)");
  EXPECT_EQ(span_text(text, call.args[0].label->span), "eye");
  EXPECT_EQ(call.args[3].label->text, "fov");
  EXPECT_TRUE(std::get<NumberLit>(call.args[3].value->node).integer);
  EXPECT_EQ(span_text(text, cam.value->span), text.substr(14));
}

// (x, y) is the point (x, y, 0): a vector whose third component is a 0 spanning the literal.
TEST(Parser, TwoComponentVectorIsAPointOfTheXyPlane) {
  EXPECT_EQ(ast("let p = (1, 2 + a)"), "(let p (vec 1 (+ 2 a) 0))");
  const std::string text = "let p = (3, 4)";
  const Script script = parse_ok(text);
  const auto& vec = std::get<VectorLit>(std::get<LetStmt>(script.statements.at(0).node).value->node);
  EXPECT_EQ(std::get<NumberLit>(vec.components[2]->node).value, 0);
  EXPECT_EQ(span_text(text, vec.components[2]->span), "(3, 4)");
}

TEST(Parser, OneLineForLoop) {
  const std::string text = "for i in 0..4 { draw post(1 + i) at translate(2*i, 0, 0) }";
  const Script script = parse_ok(text);
  const auto& loop = std::get<ForStmt>(script.statements.at(0).node);
  EXPECT_EQ(loop.variable.text, "i");
  EXPECT_EQ(std::get<BinaryExpr>(loop.iterable->node).op, BinaryOp::Range);
  ASSERT_EQ(loop.body.statements.size(), 1U);
  const auto& draw = std::get<DrawStmt>(loop.body.statements[0].node);
  ASSERT_TRUE(draw.transform);
  EXPECT_EQ(at(text, draw.transform->span.begin).column, 37U);
  EXPECT_EQ(at(text, loop.body.span.begin).column, 15U);
}

TEST(Parser, Precedence) {
  EXPECT_EQ(ast("let x = 1 + 2 * 3 - 4 / 5 % 6"), "(let x (- (+ 1 (* 2 3)) (% (/ 4 5) 6)))");
  EXPECT_EQ(ast("let x = -a * -b"), "(let x (* (- a) (- b)))");
  EXPECT_EQ(ast("let x = 0..n - 1"), "(let x (.. 0 (- n 1)))");
  EXPECT_EQ(ast("let x = -2..2"), "(let x (.. (- 2) 2))");
  EXPECT_EQ(ast("let x = a + 1 < b * 2"), "(let x (< (+ a 1) (* b 2)))");
  EXPECT_EQ(ast("let x = not a == b"), "(let x (not (== a b)))");
  EXPECT_EQ(ast("let x = a or b and c"), "(let x (or a (and b c)))");
  EXPECT_EQ(ast("let x = a and b or c"), "(let x (or (and a b) c))");
  EXPECT_EQ(ast("let x = a or b then c"), "(let x (then (or a b) c))");
  EXPECT_EQ(ast("let x = rotate(z: 30) then scale(2) then translate(1, 0, 0)"),
            "(let x (then (then (call rotate z:30) (call scale 2)) (call translate 1 0 0)))");
  EXPECT_EQ(ast("let x = (1 + 2) * 3"), "(let x (* (+ 1 2) 3))");
  EXPECT_EQ(ast("let x = -v.x"), "(let x (- (. v x)))");
  EXPECT_EQ(ast("let x = l[0].y(2)[1]"), "(let x (index (call (. (index l 0) y) 2) 1))");
  EXPECT_EQ(ast("let x = a != b"), "(let x (!= a b))");
  EXPECT_EQ(ast("let x = a >= b"), "(let x (>= a b))");
}

TEST(Parser, ListComprehensions) {
  EXPECT_EQ(ast("let x = [i * i for i in 0..10]"), "(let x (comp (* i i) for i in (.. 0 10)))");
  EXPECT_EQ(ast("let x = [i for i in l if i % 2 == 0 and i > 2]"),
            "(let x (comp i for i in l if (and (== (% i 2) 0) (> i 2))))");
  EXPECT_EQ(ast("let x = [[j for j in 0..i] for i in 0..4]"),
            "(let x (comp (comp j for j in (.. 0 i)) for i in (.. 0 4)))");
  EXPECT_EQ(ast("let x = [a then b for a in l]"), "(let x (comp (then a b) for a in l))");
  EXPECT_EQ(ast("let x = [f(p).x for p in ps][0]"), "(let x (index (comp (. (call f p) x) for p in ps) 0))");
  // A one-item list and an empty one are still lists.
  EXPECT_EQ(ast("let x = [[i]]"), "(let x (list (list i)))");

  const std::string text = "let squares = [ i * i for i in 0..n if i != 3 ]";
  const Script script = parse_ok(text);
  const Expr& e = *std::get<LetStmt>(script.statements.at(0).node).value;
  const auto& comp = std::get<ListComprehension>(e.node);
  EXPECT_EQ(span_text(text, e.span), "[ i * i for i in 0..n if i != 3 ]");
  EXPECT_EQ(span_text(text, comp.element->span), "i * i");
  EXPECT_EQ(comp.variable->text, "i");
  EXPECT_EQ(at(text, comp.variable->span.begin).column, 27U);
  EXPECT_EQ(span_text(text, comp.variable->span), "i");
  EXPECT_EQ(span_text(text, comp.iterable->span), "0..n");
  ASSERT_TRUE(comp.condition);
  EXPECT_EQ(span_text(text, comp.condition->span), "i != 3");
  EXPECT_EQ(at(text, comp.condition->span.begin).column, 40U);
  EXPECT_EQ(e.height, 3U);  // comp > != > i
  EXPECT_FALSE(std::get<ListComprehension>(
                   std::get<LetStmt>(parse_ok("let y = [k for k in l]").statements.at(0).node).value->node)
                   .condition);
}

TEST(Parser, Literals) {
  EXPECT_EQ(ast("let x = [1, 2.5, 1e3, 1.5E-2, true, false, \"s\", (1, 2, 3), []]"),
            "(let x (list 1 2.5 1000 0.015 true false \"s\" (vec 1 2 3) (list)))");
  EXPECT_EQ(ast("let s = \"a\\\"b\\\\c\\{d\\}\""), "(let s \"a\\\"b\\\\c{d}\")");
  EXPECT_EQ(ast("let s = \"{n} items, {x * 2:.2f}\""),
            "(let s (str (fmt n) \" items, \" (fmt (* x 2) \".2f\")))");
  EXPECT_EQ(ast("let s = \"\""), "(let s \"\")");
  const Script script = parse_ok("let n = 48\nlet d = 48.0\n");
  EXPECT_TRUE(std::get<NumberLit>(std::get<LetStmt>(script.statements[0].node).value->node).integer);
  EXPECT_FALSE(std::get<NumberLit>(std::get<LetStmt>(script.statements[1].node).value->node).integer);
}

TEST(Parser, Definitions) {
  EXPECT_EQ(ast("def post(h) = prism(regular(6, 0.5), h)"),
            "(def post (h) (call prism (call regular 6 0.5) h))");
  EXPECT_EQ(ast("def f(a, n = 6) = a * n"), "(def f (a n=6) (* a n))");
  EXPECT_EQ(ast("def g() = 1"), "(def g () 1)");
  EXPECT_EQ(ast("def step(i) {\n  let h = i * 0.2\n  return box(1, 1, h)\n}"),
            "(def step (i) (block (let h (* i 0.2)) (return (call box 1 1 h))))");
  EXPECT_EQ(ast("def nothing() { return }"), "(def nothing () (block (return)))");
  const std::string text = "def f(a, n = 6) = a * n";
  const Script script = parse_ok(text);
  const auto& def = std::get<DefStmt>(script.statements[0].node);
  EXPECT_FALSE(def.body);
  ASSERT_EQ(def.params.size(), 2U);
  EXPECT_FALSE(def.params[0].default_value);
  EXPECT_TRUE(def.params[1].default_value);
  EXPECT_EQ(at(text, def.params[1].name.span.begin).column, 10U);
}

TEST(Parser, ControlFlow) {
  EXPECT_EQ(ast("if a > 1 { draw x } else { draw y }"), "(if (> a 1) (block (draw x)) (block (draw y)))");
  EXPECT_EQ(ast("if a { draw x } else if b { draw y }"),
            "(if a (block (draw x)) (block (if b (block (draw y)))))");
  EXPECT_EQ(ast("for p in [a, b] { for i in 0..2 { draw p at translate(i, 0, 0) } }"),
            "(for p (list a b) (block (for i (.. 0 2) (block (draw p at (call translate i 0 0))))))");
}

TEST(Parser, Settings) {
  EXPECT_EQ(ast("animate frames 48"), "(animate 48)");
  EXPECT_EQ(ast("animate frames n * 2 fps 24"), "(animate (* n 2) fps 24)");
  EXPECT_EQ(ast("output \"scene.svg\""), "(output \"scene.svg\")");
  EXPECT_EQ(ast("output \"a.pdf\" portrait"), "(output \"a.pdf\" portrait)");
  EXPECT_EQ(ast("paper A3 landscape"), "(paper A3 landscape)");
  EXPECT_EQ(ast("style hidden off"), "(style hidden off)");
  EXPECT_EQ(ast("include \"parts.hls\""), "(include \"parts.hls\")");
  const Script script = parse_ok("output \"x.pdf\" paper A4 landscape");
  const auto& out = std::get<OutputStmt>(script.statements[0].node);
  EXPECT_EQ(out.paper.size->text, "A4");
  EXPECT_EQ(out.paper.orientation, Orientation::Landscape);
}

TEST(Parser, PaperOptions) {
  EXPECT_EQ(ast("paper A4 landscape (margin: 10, scale: 0.5)"),
            "(paper A4 landscape (options margin:10 scale:0.5))");
  EXPECT_EQ(ast("paper custom (width: 300, height: 2 * w)"),
            "(paper custom (options width:300 height:(* 2 w)))");
  EXPECT_EQ(ast("paper A4 ()"), "(paper A4)");
  EXPECT_EQ(ast("output \"p.pdf\" paper A3 portrait (margin: 5)"),
            "(output \"p.pdf\" A3 portrait (options margin:5))");
  const std::string text = "paper letter (margin: 12.5, scale: 1)";
  const Script script = parse_ok(text);
  const auto& paper = std::get<PaperStmt>(script.statements[0].node).paper;
  ASSERT_EQ(paper.options.size(), 2U);
  ASSERT_TRUE(paper.options[0].label);
  EXPECT_EQ(paper.options[0].label->text, "margin");
  EXPECT_EQ(span_text(text, paper.options[0].span), "margin: 12.5");
  EXPECT_EQ(span_text(text, paper.options[1].span), "scale: 1");
  EXPECT_EQ(paper.orientation, Orientation::Unspecified);
}

TEST(Parser, OutputPlotter) {
  EXPECT_EQ(ast("output \"p.hpgl\" plotter hp7475a"), "(output \"p.hpgl\" plotter hp7475a)");
  EXPECT_EQ(ast("output \"p.hpgl\" paper A3 portrait (margin: 5) plotter \"roland-dxy\""),
            "(output \"p.hpgl\" A3 portrait (options margin:5) plotter roland-dxy)");
  EXPECT_EQ(ast("output \"p.hpgl\" landscape plotter mine"), "(output \"p.hpgl\" landscape plotter mine)");
  const std::string text = "output \"p.hpgl\" plotter \"roland-dxy\"";
  const Script script = parse_ok(text);
  const auto& out = std::get<OutputStmt>(script.statements[0].node);
  EXPECT_FALSE(out.paper.size);
  ASSERT_TRUE(out.plotter);
  EXPECT_EQ(out.plotter->text, "roland-dxy");
  EXPECT_EQ(span_text(text, out.plotter->span), "\"roland-dxy\"");
  // A plotter statement on the next line is not the output's plotter clause.
  EXPECT_EQ(dump(parse_ok("output \"p.hpgl\"\nplotter mine { pens: 2 }")),
            "(output \"p.hpgl\")\n(plotter mine (entries pens:2))\n");
}

TEST(Parser, Pens) {
  EXPECT_EQ(ast("pen 2 (colour: \"red\", width: 0.35)"), "(pen 2 (options colour:\"red\" width:0.35))");
  EXPECT_EQ(ast("pen (i + 1) ()"), "(pen (+ i 1) (options))");
  EXPECT_EQ(ast("draw box(1) at translate(1, 0, 0) pen 3"),
            "(draw (call box 1) at (call translate 1 0 0) pen 3)");
  EXPECT_EQ(ast("draw box(1) pen k + 1"), "(draw (call box 1) pen (+ k 1))");
  EXPECT_EQ(ast("draw a pen f(i)"), "(draw a pen (call f i))");
  EXPECT_EQ(ast("style hidden dashed pen 2"), "(style hidden dashed pen 2)");
  EXPECT_EQ(ast("style hidden levels 3"), "(style hidden levels 3)");
  EXPECT_EQ(ast("style hidden levels n + 1 pen 4"), "(style hidden levels (+ n 1) pen 4)");
  {
    const std::string levels_text = "style hidden levels (n) pen 2";
    const Script levels_script = parse_ok(levels_text);
    const auto& style = std::get<StyleStmt>(levels_script.statements[0].node);
    EXPECT_EQ(style.value.text, "levels");
    ASSERT_TRUE(style.levels);
    EXPECT_EQ(span_text(levels_text, style.levels->span), "n");  // (e) is e, as everywhere
    ASSERT_TRUE(style.pen);
    EXPECT_EQ(span_text(levels_text, style.pen->span), "pen 2");
    EXPECT_FALSE(std::get<StyleStmt>(parse_ok("style hidden dashed").statements[0].node).levels);
  }
  EXPECT_EQ(dump(parse_ok("style hidden levels 2\npen 1 (width: 0.2)")),
            "(style hidden levels 2)\n(pen 1 (options width:0.2))\n");
  const std::string text = "draw a pen 2";
  const Script script = parse_ok(text);
  const auto& draw = std::get<DrawStmt>(script.statements[0].node);
  EXPECT_FALSE(draw.transform);
  ASSERT_TRUE(draw.pen);
  EXPECT_EQ(span_text(text, draw.pen->span), "pen 2");
  EXPECT_EQ(span_text(text, draw.pen->number->span), "2");
  EXPECT_EQ(std::string(statement_keyword(parse_ok("pen 1 ()").statements[0])), "pen");
  // `pen N (` followed by `NAME:` or `)` starts a pen statement, even after a draw on the same line.
  EXPECT_EQ(dump(parse_ok("draw a\npen 2 (colour: \"red\")")),
            "(draw a)\n(pen 2 (options colour:\"red\"))\n");
  EXPECT_EQ(dump(parse_ok("draw a pen 1 pen 2 (width: 1)")), "(draw a pen 1)\n(pen 2 (options width:1))\n");
  EXPECT_EQ(dump(parse_ok("style hidden dashed\npen 1 (width: 0.2)")),
            "(style hidden dashed)\n(pen 1 (options width:0.2))\n");
}

TEST(Parser, Plotters) {
  EXPECT_EQ(ast("plotter mine {\n  base: \"hp7475a\", unit: 0.025\n  pens: 6\n  newline: true\n}"),
            "(plotter mine (entries base:\"hp7475a\" unit:0.025 pens:6 newline:true))");
  EXPECT_EQ(ast("plotter empty {}"), "(plotter empty (entries))");
  const std::string text = "plotter mine { pens: 6 }";
  const Script script = parse_ok(text);
  const auto& plotter = std::get<PlotterStmt>(script.statements[0].node);
  EXPECT_EQ(span_text(text, plotter.name.span), "mine");
  ASSERT_EQ(plotter.entries.size(), 1U);
  EXPECT_EQ(span_text(text, plotter.entries[0].span), "pens: 6");
  EXPECT_EQ(span_text(text, plotter.entries[0].label->span), "pens");
  EXPECT_EQ(std::string(statement_keyword(script.statements[0])), "plotter");
}

TEST(Parser, Views) {
  EXPECT_EQ(ast("view front = side at page (80, 60)"), "(view front side at page (vec 80 60 0) (options))");
  EXPECT_EQ(
      ast("view iso = lookat(eye: e, target: t) at page (1, 2) scale: 0.5 label: \"ISO\" hidden: false"),
      "(view iso (call lookat eye:e target:t) at page (vec 1 2 0) (options scale:0.5 label:\"ISO\" "
      "hidden:false))");
  // Options end where the next statement starts; `view` stays a name elsewhere.
  EXPECT_EQ(dump(parse_ok("view a = c at page (1, 2) scale: 2\nview b = c at page (3, 4)\nlet view = 1")),
            "(view a c at page (vec 1 2 0) (options scale:2))\n(view b c at page (vec 3 4 0) (options))\n(let "
            "view 1)\n");
  const std::string text = "view top = plan at page (100, 150) scale: 10";
  const Script script = parse_ok(text);
  const auto& view = std::get<ViewStmt>(script.statements[0].node);
  EXPECT_EQ(span_text(text, view.name.span), "top");
  EXPECT_EQ(span_text(text, view.camera->span), "plan");
  ASSERT_EQ(view.options.size(), 1U);
  EXPECT_EQ(span_text(text, view.options[0].span), "scale: 10");
  EXPECT_EQ(std::string(statement_keyword(script.statements[0])), "view");
}

TEST(Parser, NewlinesAreWhitespace) {
  const Script a = parse_ok("draw a draw b let c = 1");
  const Script b = parse_ok("draw a\ndraw b\nlet c =\n  1");
  EXPECT_EQ(dump(a), dump(b));
  EXPECT_EQ(a.statements.size(), 3U);
  // Contextual words stay names outside their place.
  EXPECT_EQ(ast("let line = face + vertex + frames + hidden"),
            "(let line (+ (+ (+ face vertex) frames) hidden))");
  EXPECT_EQ(ast("let pen = plotter + custom"), "(let pen (+ plotter custom))");
}

TEST(Parser, UnicodeAndTabsInColumns) {
  const std::string text = "let s = \"é\"\tlet t = 2";
  const Script script = parse_ok(text);
  // 'é' is two bytes but one column; the tab is one column.
  EXPECT_EQ(at(text, script.statements[1].span.begin).column, 13U);
  EXPECT_EQ(script.statements[1].span.begin, 13U);
}

TEST(Parser, EmptyScripts) {
  EXPECT_EQ(parse_ok("").statements.size(), 0U);
  EXPECT_EQ(parse_ok("# nothing\n\n   \n").statements.size(), 0U);
}

TEST(Parser, FileIdTravelsInSpans) {
  ParseResult result = parse("let x = 1", "inc.hls", 7);
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(result.script->file, 7U);
  EXPECT_EQ(result.script->statements[0].span.file, 7U);
  EXPECT_EQ(std::get<LetStmt>(result.script->statements[0].node).value->span.file, 7U);
}

}  // namespace
}  // namespace hlr::lang
