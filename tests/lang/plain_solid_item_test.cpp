// The hand-read plain solid items (lang/plain_solid_item.hpp) are a shortcut only: every script, right or
// wrong, must parse to the same tree and the same messages with it as with the grammar alone.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "lang/ast.hpp"
#include "lang/parser.hpp"

namespace hlr::lang {
namespace {

// Everything the tree and the messages say, items' offsets included.
std::string reading(const std::string& text, bool plain) {
  const ParseResult r = parse(text, "t.hls", 0, ParseOptions{plain});
  std::string out;
  for (const Diagnostic& d : r.diagnostics)
    out += "error " + std::to_string(d.span.begin) + "-" + std::to_string(d.span.end) + " " + d.message +
           " | " + d.hint + "\n";
  if (!r.script) return out;
  out += dump(*r.script) + "\n";
  for (const Stmt& stmt : r.script->statements) {
    const auto* solid = std::get_if<SolidStmt>(&stmt.node);
    if (!solid) continue;
    for (const SolidBody::Item& item : solid->body.items())
      out += std::to_string(static_cast<int>(item.kind)) + "@" + std::to_string(item.begin) + "-" +
             std::to_string(item.end) + " ";
    for (std::uint32_t k = 0; k < solid->body.id_count(); ++k) out += std::string(solid->body.id(k)) + ",";
    out += "\n";
  }
  return out;
}

void expect_same_reading(const std::string& text) {
  const std::string grammar_only = reading(text, false);
  EXPECT_EQ(reading(text, true), grammar_only) << "script:\n" << text;
}

TEST(PlainSolidItem, ReadsAsTheGrammarDoes) {
  for (const char* body : {
           "vertex a = (1, 2, 3)\n face a b c\n line a b",
           "vertex 1 = (0, 10, 0)\nvertex top = (0, 10, 5)\nface 1 top 3 4\nface 5 6 7 8 hole 9 10 11\nline "
           "12 13",
           "vertex a=(1,2,3) vertex b=(-1.5e3,2E-2,0.25) face a b c line a b",
           "vertex 007 = (0, 0, 0)  # a comment\n  face 7 0007 07 # and (1, 2, 3)\nline 7 8",
           "vertex a = (1, 2, 3)\r\n face a b c\r\n",
           "vertex a = (1, 2, 3) # lone \r in a comment\n face a b c",
           "vertex vertexes = (1, 2, 3)\n face faces lines holes hole_ x_1",
           "face a b c hole d e f hole g h i\n face a b c",
           "vertex a = (1, 2, 3) + (0, 0, 1)\n face a b c",
           "vertex a = (1,\n 2, 3)\n face a b c",
           "vertex a = (x, 2, 3)",
           "vertex a = (- 1, 2, 3)",
           "vertex a = (1, 2, 3) face",
           "vertex a = (1.2.3, 0, 0)",
           "vertex a = (1e, 0, 0)",
           "vertex a = (1e999, 0, 0)",
           "vertex a = (1x, 0, 0)",
           "vertex a = (1., 0, 0)",
           "vertex a = (+1, 0, 0)",
           "vertex a == (1, 0, 0)",
           "vertex a (1, 0, 0)",
           "vertex draw = (1, 0, 0)",
           "vertex 99999999999999999999 = (1, 0, 0)",
           "vertex 9223372036854775807 = (1, 0, 0)\n face 9223372036854775807 0 1",
           "face a b 1x",
           "face a b draw",
           "face",
           "face a b hole",
           "line a",
           "line a b c",
           "line 1 99999999999999999999",
           "vertex a = (1, 2, 3)vertex b = (1, 2, 3)",
           "vertex a = (1, 2, 3)}",
           "vertex a = (1, 2, 3)\n draw x",
       }) {
    expect_same_reading("solid s {\n" + std::string(body) + "\n}\ndraw s\n");
    expect_same_reading("solid s (crease: 30) {" + std::string(body) + "}");
    expect_same_reading("solid s {" + std::string(body));  // unclosed
  }
}

// Random bodies (fixed seeds) in every spelling the items allow, and some they do not.
TEST(PlainSolidItem, RandomBodiesReadAsTheGrammarDoes) {
  const std::vector<std::string> ids = {"a", "b", "top", "1", "01", "2", "10", "x_1", "vertexes", "faceA"};
  const std::vector<std::string> numbers = {"0",   "-0",   "1",       "-2",      "3.25",  "-0.5",
                                            "1e3", "2E-2", "-7.5e+1", "1000000", "0.001", "12.5"};
  const std::vector<std::string> pads = {" ", "  ", "\t", "\n", " # note\n", "\r\n", "\n\n  "};
  const std::vector<std::string> blanks = {"", " ", "\t", "  "};
  const std::vector<std::string> broken = {"1.2.3", "1e", "2x", "(", "draw", "hole", "=", "face", "}"};
  for (unsigned seed = 1; seed <= 300; ++seed) {
    std::mt19937 rng(seed);
    auto pick = [&](const std::vector<std::string>& from) { return from[rng() % from.size()]; };
    auto number = [&] { return rng() % 40 == 0 ? pick(broken) : pick(numbers); };
    std::string text = "solid s {" + pick(pads);
    const unsigned items = 1 + rng() % 12;
    for (unsigned i = 0; i < items; ++i) {
      switch (rng() % 3) {
        case 0: {
          text += "vertex" + pick(pads) + pick(ids) + pick(blanks) + "=" + pick(blanks) + "(";
          for (int c = 0; c < 3; ++c) text += pick(blanks) + number() + pick(blanks) + (c < 2 ? "," : ")");
          break;
        }
        case 1: {
          text += "face";
          const unsigned n = 1 + rng() % 5;
          for (unsigned k = 0; k < n; ++k) text += pick(pads) + (rng() % 50 == 0 ? pick(broken) : pick(ids));
          if (rng() % 6 == 0) text += pick(pads) + "hole " + pick(ids) + " " + pick(ids) + " " + pick(ids);
          break;
        }
        default:
          text += "line" + pick(pads) + pick(ids) + pick(pads) + pick(ids);
      }
      text += pick(pads);
    }
    text += "}\n";
    expect_same_reading(text);
  }
}

}  // namespace
}  // namespace hlr::lang
