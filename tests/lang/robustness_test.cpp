// Fuzz-ish robustness: random bytes, random token soups and random edits of the DESIGN.md sketch,
// all from fixed seeds. The parser must never crash or hang, and must return either an AST or at
// least one diagnostic whose span lies inside the text. Failing cases print their seed and input.
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <string>

#include "lang/parser.hpp"

namespace hlr::lang {
namespace {

void check_result(const std::string& text, std::uint32_t seed) {
  const ParseResult result = parse(text, "fuzz.hls", 3);
  SCOPED_TRACE("seed " + std::to_string(seed) + ", input: " + text);
  ASSERT_NE(result.source, nullptr);
  if (result.ok()) {
    EXPECT_TRUE(result.diagnostics.empty());
    EXPECT_EQ(dump(*result.script).empty(), result.script->statements.empty());
    return;
  }
  ASSERT_FALSE(result.diagnostics.empty());
  for (const Diagnostic& d : result.diagnostics) {
    EXPECT_EQ(d.span.file, 3U);
    EXPECT_LE(d.span.begin, d.span.end);
    EXPECT_LE(d.span.end, text.size());
    const SourcePos at = result.source->position(d.span.begin);
    EXPECT_GE(at.line, 1U);
    EXPECT_LE(at.line, result.source->line_count());
    EXPECT_GE(at.column, 1U);
    EXPECT_FALSE(d.message.empty());
    const std::string printed = format(d, *result.source);
    EXPECT_EQ(printed.rfind("fuzz.hls:", 0), 0U);
  }
}

TEST(Robustness, RandomBytes) {
  for (std::uint32_t seed = 0; seed < 1500; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> length(0, 160);
    std::uniform_int_distribution<int> byte(0, 255);
    std::string text(static_cast<std::size_t>(length(rng)), '\0');
    for (char& c : text) c = static_cast<char>(byte(rng));
    check_result(text, seed);
  }
}

TEST(Robustness, RandomTokenSoups) {
  static constexpr std::array kTokens = {
      "solid",  "let",     "def",    "return", "for",    "in",     "if",    "else",    "draw",   "at",
      "camera", "animate", "frames", "fps",    "output", "paper",  "style", "hidden",  "dashed", "include",
      "then",   "and",     "or",     "not",    "true",   "vertex", "face",  "hole",    "line",   "x",
      "i",      "lookat",  "A4",     "0",      "12",     "1.5",    "2e3",   "1.2.3",   "\"s\"",  "\"{t:03}\"",
      "\"",     "{",       "}",      "(",      ")",      "[",      "]",     ",",       ":",      "=",
      "==",     "..",      ".",      "+",      "-",      "*",      "/",     "%",       "<",      ">=",
      "#c\n",   "\n",      "\t",     "@",      "é",      ";",      "pen",   "plotter", "custom"};
  for (std::uint32_t seed = 0; seed < 1500; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> count(0, 60);
    std::uniform_int_distribution<std::size_t> pick(0, kTokens.size() - 1);
    std::string text;
    for (int n = count(rng); n > 0; --n) {
      text += kTokens[pick(rng)];
      if (rng() % 3 != 0) text += ' ';
    }
    check_result(text, seed);
  }
}

// 1500 seeded variants of `sketch`, each with one to four random deletions or insertions of `alphabet`.
void check_random_edits(const std::string& sketch, std::string_view alphabet) {
  for (std::uint32_t seed = 0; seed < 1500; ++seed) {
    std::mt19937 rng(seed);
    std::string text = sketch;
    for (int edits = 1 + static_cast<int>(rng() % 4); edits > 0; --edits) {
      const std::size_t at = rng() % (text.size() + 1);
      if (rng() % 2 == 0 && at < text.size()) {
        text.erase(at, 1 + rng() % 3);
      } else {
        text.insert(at, 1, alphabet[rng() % alphabet.size()]);
      }
    }
    check_result(text, seed);
  }
}

TEST(Robustness, RandomEditsOfTheSketch) {
  const std::string sketch =
      "solid lblock {\n  vertex 1 = (0, 10, 0)\n  vertex top = (0, 10, 5)\n  face 1 top 3 4\n"
      "  face 5 6 7 8 hole 9 10 11\n  line 12 13\n}\nlet m = import(\"bunny.off\")\n"
      "def post(h) = prism(regular(6, 0.5), h)\n"
      "for i in 0..4 { draw post(1 + i) at translate(2*i, 0, 0) }\ndraw lblock\n"
      "draw m at rotate(z: 30) then scale(2)\n"
      "camera main = lookat(eye: (30, 20, 15), target: (0, 0, 0), up: (0, 0, 1), fov: 40)\n"
      "animate frames 48 fps 12\noutput \"landing-{frame:03}.pdf\" paper A4 landscape\nstyle hidden dashed\n";
  check_random_edits(sketch, "(){}[],=.\"#@x1 \n");
}

TEST(Robustness, RandomEditsOfDeviceSettings) {
  const std::string sketch =
      "pen 2 (colour: \"red\", width: 0.35)\npen (n + 1) ()\n"
      "plotter mine {\n  base: \"hp7475a\", pens: 6\n  moves: \"absolute\"\n}\n"
      "output \"p.hpgl\" paper custom portrait (width: 300, height: 200, margin: 5) plotter \"roland-dxy\"\n"
      "paper A4 landscape (margin: 10, scale: 0.5)\n"
      "draw a at translate(1, 0, 0) pen 2\ndraw b pen f(i)\npen 3 (width: 1)\n"
      "style hidden dashed pen 3\n";
  check_random_edits(sketch, "(){}[],=.:\"#@x1 \n");
}

}  // namespace
}  // namespace hlr::lang
