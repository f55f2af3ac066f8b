// Expressions read by hand (lang/plain_expression.hpp) are a shortcut only: every script, right or wrong,
// must parse to the same tree — every node's span and height included — and the same messages with it as
// with the grammar alone. Random expressions (fixed seed), the same broken at random places, and every
// script the project ships are read both ways.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "lang/ast.hpp"
#include "lang/parser.hpp"

namespace hlr::lang {
namespace {

std::string where(const SourceSpan& span) {
  return "@" + std::to_string(span.file) + ":" + std::to_string(span.begin) + "-" + std::to_string(span.end);
}

// Every node of an expression with its span and height, and every name's span.
void walk(const Expr& e, std::string& out);
void walk(const ExprPtr& e, std::string& out) {
  if (e) {
    walk(*e, out);
  } else {
    out += "-";
  }
}
void walk(const Name& name, std::string& out) { out += name.text + where(name.span) + " "; }
void walk(const std::vector<Argument>& args, std::string& out) {
  for (const Argument& arg : args) {
    out += "arg" + where(arg.span) + " ";
    if (arg.label) walk(*arg.label, out);
    walk(arg.value, out);
  }
}

void walk(const Expr& e, std::string& out) {
  out += "(h" + std::to_string(e.height) + where(e.span) + " ";
  std::visit(
      [&](const auto& node) {
        using T = std::decay_t<decltype(node)>;
        if constexpr (std::is_same_v<T, StringLit>) {
          for (const StringPart& part : node.parts) {
            out += "part[" + part.text + "|" + part.format + "]" + where(part.span) + " ";
            walk(part.expr, out);
          }
        } else if constexpr (std::is_same_v<T, VectorLit>) {
          for (const ExprPtr& c : node.components) walk(c, out);
        } else if constexpr (std::is_same_v<T, ListLit>) {
          for (const ExprPtr& item : node.items) walk(item, out);
        } else if constexpr (std::is_same_v<T, ListComprehension>) {
          walk(node.element, out);
          walk(*node.variable, out);
          walk(node.iterable, out);
          walk(node.condition, out);
        } else if constexpr (std::is_same_v<T, UnaryExpr>) {
          walk(node.operand, out);
        } else if constexpr (std::is_same_v<T, BinaryExpr>) {
          out += std::string(to_string(node.op)) + where(node.op_span) + " ";
          walk(node.lhs, out);
          walk(node.rhs, out);
        } else if constexpr (std::is_same_v<T, CallExpr>) {
          walk(node.callee, out);
          walk(node.args, out);
        } else if constexpr (std::is_same_v<T, MemberExpr>) {
          walk(node.object, out);
          walk(*node.member, out);
        } else if constexpr (std::is_same_v<T, IndexExpr>) {
          walk(node.object, out);
          walk(node.index, out);
        }
      },
      e.node);
  out += ")";
}

void walk(const std::vector<Stmt>& statements, std::string& out);
void walk(const Stmt& stmt, std::string& out) {
  out += std::string(statement_keyword(stmt)) + where(stmt.span) + " ";
  if (const auto* let = std::get_if<LetStmt>(&stmt.node)) {
    walk(let->name, out);
    walk(let->value, out);
  } else if (const auto* def = std::get_if<DefStmt>(&stmt.node)) {
    walk(def->name, out);
    for (const Param& param : def->params) {
      walk(param.name, out);
      walk(param.default_value, out);
    }
    walk(def->value, out);
    if (def->body) walk(def->body->statements, out);
  } else if (const auto* loop = std::get_if<ForStmt>(&stmt.node)) {
    walk(loop->iterable, out);
    walk(loop->body.statements, out);
  } else if (const auto* branch = std::get_if<IfStmt>(&stmt.node)) {
    walk(branch->condition, out);
    walk(branch->then_block.statements, out);
    if (branch->else_block) walk(branch->else_block->statements, out);
  } else if (const auto* draw = std::get_if<DrawStmt>(&stmt.node)) {
    walk(draw->object, out);
    walk(draw->transform, out);
    if (draw->pen) walk(draw->pen->number, out);
  } else if (const auto* camera = std::get_if<CameraStmt>(&stmt.node)) {
    walk(camera->value, out);
  } else if (const auto* ret = std::get_if<ReturnStmt>(&stmt.node)) {
    walk(ret->value, out);
  } else if (const auto* solid = std::get_if<SolidStmt>(&stmt.node)) {
    walk(solid->options, out);
    for (std::size_t k = 0; k < solid->body.position_count(); ++k) walk(solid->body.position_at(k), out);
  }
  out += "\n";
}
void walk(const std::vector<Stmt>& statements, std::string& out) {
  for (const Stmt& stmt : statements) walk(stmt, out);
}

// Everything the tree and the messages say.
std::string reading(const std::string& text, bool plain) {
  ParseOptions options;
  options.plain_expressions = plain;
  const ParseResult r = parse(text, "t.hls", 3, options);
  std::string out;
  for (const Diagnostic& d : r.diagnostics) out += format(d, *r.source);
  if (!r.script) return out;
  out += dump(*r.script) + "\n";
  walk(r.script->statements, out);
  return out;
}

void expect_same_reading(const std::string& text) {
  const std::string grammar_only = reading(text, false);
  EXPECT_EQ(reading(text, true), grammar_only) << "script:\n" << text;
}

TEST(PlainExpression, ReadsAsTheGrammarDoes) {
  for (const char* text : {
           "let a = 1 + 2 * 3 - -4 / 5 % 6",
           "let a = (1 + 2) * (3)",
           "let a = ((x))",
           "let v = (1, 2)\nlet w = ( 1 ,\n 2 , 3 )",
           "let a = not not x and y or z then w",
           "let r = 0 .. n + 1",
           "let c = a <= b\nlet d = a != b\nlet e = a == b\nlet f = a > b",
           "let m = f(1, k: 2, j : (3, 4))[0].x . y",
           "let m = f()\n(2)",
           "let s = \"plain\" + \"\" + \"esc \\\"q\\\" \\n\\t\\{\\}\\\\ é\"",
           "let s = \"n {i:04} of {n}\"",
           "let l = []\nlet l2 = [1, [2, 3], [ ]]",
           "let q = [x * 2 for x in 0..3 if x % 2 == 0]\nlet p = [ y for y in l ]",
           "let t = translate(3, 0, 1) then rotate(z: 3) then scale(1.5)",
           "let n = 1.5e3 + 2E-2 + 0.25 + 7 + 1.x + 1.e5",
           "let w = vertex + face + pen + frames + hidden",
           "let x = a # comment (1\n  + b # another\n  * c",
           "def f(a, b = 2) = a * b + sin(a * 30) - max(a, 1)",
           "draw box(1, 1, 1) at translate(0, 0, 1) pen 2\ndraw a pen 2 (colour: \"red\")",
           "if a < b { let c = 1 } else if not d { draw e }",
           "for i in 0..4 { draw post(1 + i) at translate(2*i, 0, 0) }",
           "camera c = lookat(eye: (40, 30, 20), target: (0, 0, 0))",
           "label \"x\" at page (20, 15) size: 4",
           "solid s (crease: 30) { vertex a = (x, 2, 3) + (0, 0, 1)\n face a b c }",
           "let a = 1 < 2 < 3",
           "let a = 1 .. 2 .. 3",
           "let a = 1 +",
           "let a = f(1,)",
           "let a = f(a: )",
           "let a = (1, 2, 3, 4)",
           "let a = (1, 2",
           "let a = [1, 2",
           "let a = [x for in l]",
           "let a = [x for x on l]",
           "let a = b.",
           "let a = b. 5",
           "let a = 1.2.3 + 1e + 1x",
           "let a = 1e999",
           "let a = \"open",
           "let a = \"bad \\q escape\"",
           "let a = \"{\"",
           "let a = not",
           "let a = - - -",
           "let a = f(then)",
           "let a = b c",
           "let a = 1 = 2",
           "let a = x[1",
       }) {
    expect_same_reading(text);
  }
}

TEST(PlainExpression, DeepNestingIsLeftToTheGrammar) {
  std::string deep = "let a = ";
  for (int i = 0; i < 70; ++i) deep += "(";
  deep += "1";
  for (int i = 0; i < 70; ++i) deep += ")";
  expect_same_reading(deep);
  std::string long_sum = "let a = 1";
  for (int i = 0; i < 300; ++i) long_sum += " + 1";
  expect_same_reading(long_sum);
  std::string negations = "let a = ";
  for (int i = 0; i < 62; ++i) negations += "-";
  expect_same_reading(negations + "1");
  std::string nots = "let a = ";
  for (int i = 0; i < 70; ++i) nots += "not ";
  expect_same_reading(nots + "x");
}

// A random expression of every form, with random padding and comments between tokens.
class ExpressionWriter {
 public:
  explicit ExpressionWriter(std::uint32_t seed) : rng_(seed) {}

  std::string expression(int depth) {
    std::string out = operand(depth);
    const int ops = pick(4);
    for (int i = 0; i < ops; ++i) out += pad() + any_of(kOperators) + pad() + operand(depth);
    return out;
  }

 private:
  static constexpr const char* kOperators[] = {
      "+", "-", "*", "/", "%", "..", "==", "!=", "<", "<=", ">", ">=", "and", "or", "then"};
  static constexpr const char* kNames[] = {"a", "b_2", "vertex", "face", "pen", "frames", "x", "size"};

  template <std::size_t N>
  std::string any_of(const char* const (&words)[N]) {
    return words[static_cast<std::size_t>(pick(static_cast<int>(N)))];
  }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  std::string pad() {
    switch (pick(8)) {
      case 0:
        return "";
      case 1:
        return "\n  ";
      case 2:
        return " # note\n";
      case 3:
        return "\t";
      default:
        return " ";
    }
  }

  std::string operand(int depth) {
    const int kinds = depth > 0 ? 14 : 5;
    std::string out;
    switch (pick(kinds)) {
      case 0:
        out = std::to_string(pick(100));
        break;
      case 1: {
        const char* const numbers[] = {"1.5", "2e3", "0.25E-2", "007", "3.0"};
        out = any_of(numbers);
        break;
      }
      case 2:
        out = any_of(kNames);
        break;
      case 3:
        out = pick(2) ? "true" : "false";
        break;
      case 4: {
        const char* const strings[] = {"\"\"", "\"text\"", "\"a\\\"b\\n\"", "\"é {x}\"", "\"{a:03} {b}\""};
        out = any_of(strings);
        break;
      }
      case 5:
        out = "-" + pad() + operand(depth - 1);
        break;
      case 6:
        out = "not " + operand(depth - 1);
        break;
      case 7:
        out = "(" + pad() + expression(depth - 1) + pad() + ")";
        break;
      case 8:
        out = "(" + expression(depth - 1) + "," + pad() + expression(depth - 1) +
              (pick(2) ? ", " + expression(depth - 1) : "") + ")";
        break;
      case 9: {
        out = "[";
        const int n = pick(4);
        for (int i = 0; i < n; ++i) out += (i ? "," + pad() : "") + expression(depth - 1);
        out += "]";
        break;
      }
      case 10:
        out = "[" + expression(depth - 1) + " for v in " + expression(depth - 1) +
              (pick(2) ? " if " + expression(depth - 1) : "") + "]";
        break;
      default: {
        out = any_of(kNames);
        const int suffixes = 1 + pick(3);
        for (int i = 0; i < suffixes; ++i) {
          switch (pick(3)) {
            case 0: {
              out += pad() + "(";
              const int n = pick(4);
              for (int k = 0; k < n; ++k) {
                out += k ? "," + pad() : "";
                if (pick(2)) out += any_of(kNames) + pad() + ":" + pad();
                out += expression(depth - 1);
              }
              out += ")";
              break;
            }
            case 1:
              out += pad() + "[" + expression(depth - 1) + "]";
              break;
            default:
              out += pad() + "." + pad() + any_of(kNames);
          }
        }
      }
    }
    return out;
  }

  std::mt19937 rng_;
};

TEST(PlainExpression, RandomExpressionsReadAsTheGrammarDoes) {
  ExpressionWriter writer(20261204);
  std::mt19937 breaker(7);
  const std::string breaking = "()[],.:+-*<=!\"{}#\n x1";
  for (int i = 0; i < 1500; ++i) {
    const std::string text = "let r = " + writer.expression(3) + "\ndraw r";
    expect_same_reading(text);
    // The same, broken: a character dropped, or one put in.
    std::string broken = text;
    const std::size_t at = std::uniform_int_distribution<std::size_t>(8, broken.size() - 1)(breaker);
    if (breaker() % 2) {
      broken.erase(at, 1);
    } else {
      broken.insert(at, 1, breaking[breaker() % breaking.size()]);
    }
    expect_same_reading(broken);
  }
}

TEST(PlainExpression, ShippedScriptsReadAsTheGrammarDoes) {
  std::size_t scripts = 0;
  for (const char* folder : {"examples", "stdlib", "tests/data"}) {
    const std::filesystem::path root = std::filesystem::path(HLR_SOURCE_DIR) / folder;
    if (!std::filesystem::exists(root)) continue;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
      if (entry.path().extension() != ".hls") continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::ostringstream text;
      text << in.rdbuf();
      expect_same_reading(text.str());
      ++scripts;
    }
  }
  EXPECT_GE(scripts, 30U);
}

}  // namespace
}  // namespace hlr::lang
