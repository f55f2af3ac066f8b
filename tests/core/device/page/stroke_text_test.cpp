#include "core/device/page/stroke_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "core/device/page/page_plot.hpp"
#include "core/device/page/stroke_glyphs.hpp"

namespace hlr {
namespace {

using Strokes = std::vector<std::vector<Point2>>;

// The simplex font read straight from Debian's data file, by the format's own rules (each glyph line: a
// 5-digit number, a 3-digit count of pairs, then pairs of letters; a letter's value is its distance from
// 'R'; the first pair is the left and right bearing; " R" lifts the pen; y grows down with the baseline
// at +9) — independent of the library hlrscript reads it with. Glyph lines start at ' ' and follow ASCII.
struct JhfGlyph {
  int number = 0;  // the Hershey number
  int left = 0, right = 0;
  std::vector<std::vector<std::pair<int, int>>> strokes;
};

std::map<char, JhfGlyph> read_jhf(const std::string& path) {
  std::ifstream in(path);
  std::map<char, JhfGlyph> glyphs;
  std::string line, record;
  char next = ' ';
  while (std::getline(in, line)) {
    record += line;
    const int pairs = std::stoi(record.substr(5, 3));
    if (static_cast<int>(record.size()) < 8 + 2 * pairs) continue;  // a glyph may continue on the next line
    JhfGlyph g;
    g.number = std::stoi(record.substr(0, 5));
    g.left = record[8] - 'R';
    g.right = record[9] - 'R';
    g.strokes.emplace_back();
    for (int i = 1; i < pairs; ++i) {
      const char a = record[8 + 2 * i], b = record[9 + 2 * i];
      if (a == ' ' && b == 'R') {
        g.strokes.emplace_back();
        continue;
      }
      g.strokes.back().push_back({a - 'R', b - 'R'});
    }
    std::erase_if(g.strokes, [](const auto& s) { return s.size() < 2; });
    glyphs[next++] = g;
    record.clear();
  }
  return glyphs;
}

TEST(StrokeText, EveryPrintableLetterIsTheFontFilesGlyph) {
  const std::map<char, JhfGlyph> jhf = read_jhf("/usr/share/hershey-fonts/futural.jhf");
  ASSERT_EQ(jhf.size(), 96u);  // ' ' to DEL
  const double cap = 21;       // one font unit per mm
  for (const auto& [c, g] : jhf) {
    if (c == 0x7f) continue;  // DEL is a control character, drawn as a box
    SCOPED_TRACE(std::string(1, c));
    const Strokes got = stroke_text(std::string(1, c), {100, 50}, cap);
    ASSERT_EQ(got.size(), g.strokes.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
      ASSERT_EQ(got[k].size(), g.strokes[k].size());
      for (std::size_t i = 0; i < got[k].size(); ++i) {
        // Page mm, y down: x from the left bearing, the file's y (down, baseline at 9) from the baseline.
        EXPECT_DOUBLE_EQ(got[k][i].x, 100 + g.strokes[k][i].first - g.left);
        EXPECT_DOUBLE_EQ(got[k][i].y, 50 + g.strokes[k][i].second - 9);
      }
    }
    EXPECT_DOUBLE_EQ(stroke_text_width_mm(std::string(1, c), cap), g.right - g.left);
  }
}

TEST(StrokeText, LettersAdvanceAndScale) {
  // "H" is 22 units wide with stems at 4 and 18: at a 2.1 mm cap, 2.2 mm, the second H's stem at 2.6 mm.
  const Strokes hh = stroke_text("HH", {0, 10}, 2.1);
  ASSERT_EQ(hh.size(), 6u);
  EXPECT_NEAR(hh[3][0].x, 2.2 + 0.4, 1e-12);
  EXPECT_NEAR(hh[0][0].y, 10 - 2.1, 1e-12);  // the stem's top at the cap height above the baseline
  EXPECT_NEAR(hh[0][1].y, 10, 1e-12);
  EXPECT_NEAR(stroke_text_width_mm("HH", 2.1), 4.4, 1e-12);
}

// Glyph `g` of a jhf file as stroke_text() would place it: baseline at the origin, y down, cap 21 mm.
Strokes placed(const JhfGlyph& g) {
  Strokes out;
  for (const auto& s : g.strokes) {
    std::vector<Point2>& t = out.emplace_back();
    for (const auto& [x, y] : s) t.push_back({1.0 * (x - g.left), 1.0 * (y - 9)});
  }
  return out;
}

// Greek from Hershey's simplex Greek, by the Hershey numbers of its 24 capitals (527–550) and small
// letters (627–650) in the alphabet's order, read from the font file by the test's own reader.
TEST(StrokeText, GreekLettersAreTheSimplexGreekGlyphs) {
  const std::map<char, JhfGlyph> jhf = read_jhf("/usr/share/hershey-fonts/greeks.jhf");
  std::map<int, JhfGlyph> by_number;
  for (const auto& [c, g] : jhf) by_number[g.number] = g;
  const std::u32string capitals = U"ΑΒΓΔΕΖΗΘΙΚΛΜΝΞΟΠΡΣΤΥΦΧΨΩ", small = U"αβγδεζηθικλμνξοπρστυφχψω";
  ASSERT_EQ(capitals.size(), 24u);
  for (int k = 0; k < 24; ++k)
    for (const auto& [letters, first] : {std::pair{capitals, 527}, std::pair{small, 627}}) {
      const std::u32string one(1, letters[static_cast<std::size_t>(k)]);
      std::string utf8;  // the letter in UTF-8 (two bytes: U+0391–U+03C9)
      const auto c = static_cast<unsigned>(one[0]);
      utf8 += static_cast<char>(0xc0 | (c >> 6));
      utf8 += static_cast<char>(0x80 | (c & 0x3f));
      SCOPED_TRACE(utf8);
      ASSERT_TRUE(by_number.count(first + k));
      EXPECT_EQ(stroke_text(utf8, {0, 0}, 21), placed(by_number[first + k]));
    }
  EXPECT_EQ(stroke_text("ς", {0, 0}, 21), stroke_text("σ", {0, 0}, 21));  // final sigma
}

double top_mm(const Strokes& s) {  // the highest point, page y down: the least y
  double top = 1e9;
  for (const auto& k : s)
    for (const Point2& p : k) top = std::min(top, p.y);
  return top;
}

// A letter with accents is its base letter, whole and at its advance, with each accent above it (or,
// a cedilla, below the baseline); a superscript is its digit at 0.6 with its top at the cap height.
TEST(StrokeText, AccentedLettersAreComposedFromTheirParts) {
  const Strokes e = stroke_text("e", {0, 0}, 21), e_acute = stroke_text("é", {0, 0}, 21);
  ASSERT_EQ(e_acute.size(), e.size() + 1);
  EXPECT_TRUE(std::equal(e.begin(), e.end(), e_acute.begin()));
  EXPECT_LT(top_mm({e_acute.back()}), top_mm(e) - 1);  // above the e
  EXPECT_DOUBLE_EQ(stroke_text_width_mm("é", 21), stroke_text_width_mm("e", 21));
  EXPECT_EQ(stroke_text("Ü", {0, 0}, 21).size(), stroke_text("U", {0, 0}, 21).size() + 2);  // two dots
  const Strokes c_cedilla = stroke_text("ç", {0, 0}, 21);
  double low = -1e9;
  for (const Point2& p : c_cedilla.back()) low = std::max(low, p.y);
  EXPECT_GT(low, 3);  // below the baseline
  // í drops the dot of the i under its accent.
  const Strokes i = stroke_text("i", {0, 0}, 21), dotless = stroke_text("ı", {0, 0}, 21);
  ASSERT_EQ(dotless.size() + 1, i.size());
  EXPECT_TRUE(missing_glyphs("ı").empty());
  const Strokes i_acute = stroke_text("í", {0, 0}, 21);
  ASSERT_EQ(i_acute.size(), dotless.size() + 1);
  EXPECT_TRUE(std::equal(dotless.begin(), dotless.end(), i_acute.begin()));
  const Strokes two = stroke_text("2", {0, 0}, 21), squared = stroke_text("²", {0, 0}, 21);
  ASSERT_EQ(squared.size(), two.size());
  EXPECT_NEAR(top_mm(squared), -21, 0.6 * 1 + 1e-9);
  EXPECT_NEAR(stroke_text_width_mm("²", 21), 0.6 * stroke_text_width_mm("2", 21), 1e-12);
  EXPECT_EQ(stroke_text("µ", {0, 0}, 21), stroke_text("μ", {0, 0}, 21));  // micro sign: the Greek mu
  EXPECT_EQ(stroke_text("½", {0, 0}, 21).size(), stroke_text("1/2", {0, 0}, 21).size());
  for (const char* made : {"ß", "°", "ø", "Ł", "æ", "…", "“"})
    EXPECT_TRUE(missing_glyphs(made).empty()) << made;
}

// A character no font holds, an ill-formed byte and a control character are each drawn as a box (a
// closed rectangle), and named once by missing_glyphs().
TEST(StrokeText, MissingCharactersAreBoxesAndNamed) {
  const Strokes box = stroke_text("✓", {0, 0}, 21);
  ASSERT_EQ(box.size(), 1u);
  EXPECT_EQ(box[0].size(), 5u);
  EXPECT_EQ(box[0].front(), box[0].back());
  EXPECT_EQ(stroke_text("\xff", {0, 0}, 21), box);
  EXPECT_EQ(stroke_text("\t", {0, 0}, 21), box);
  EXPECT_EQ(missing_glyphs("Größe ✓ 1 ✓ ☃"), U"✓☃");
  EXPECT_TRUE(missing_glyphs("Größe 1 m³, 20 °C, Ωμ").empty());
  EXPECT_EQ(describe_code_point(U'✓'), "U+2713 '✓'");
  EXPECT_EQ(describe_code_point(U'\t'), "U+0009");
  EXPECT_EQ(decode_utf8("a\xffé"), U"a\ufffdé");
}

// The caption planned with the drawing: in the bottom margin, inside the pen's reach, in pen 1, and no
// longer a string for the device to print.
TEST(StrokeText, TheCaptionIsPlannedInTheBottomMargin) {
  const std::vector<VisibleSegment> none;
  PagePlotOptions o;
  o.spec.margin_mm = 12;
  const Rect2 frame{0, 0, 4, 3};
  const PagePlot printed = plot_page(none, frame, "camera main", o);
  EXPECT_EQ(printed.page.caption, "camera main");
  EXPECT_TRUE(printed.page.strokes.empty());

  o.caption_as_strokes = true;
  o.reach_margin_mm = 5;
  const PagePlot drawn = plot_page(none, frame, "camera main", o);
  EXPECT_EQ(drawn.page.caption, "");
  ASSERT_FALSE(drawn.page.strokes.empty());
  double ymin = 1e9, ymax = -1e9, xmin = 1e9;
  for (const PlotStroke& s : drawn.page.strokes) {
    EXPECT_EQ(s.pen, 1);
    for (const Point2& p : s.points) {
      ymin = std::min(ymin, p.y);
      ymax = std::max(ymax, p.y);
      xmin = std::min(xmin, p.x);
    }
  }
  EXPECT_GT(ymin, 210 - 12);  // below the drawing's area
  EXPECT_LE(ymax, 210 - 5);   // within reach
  EXPECT_NEAR(xmin, 12, 1);   // from the left margin
}

TEST(StrokeText, ALongCaptionShrinksToThePage) {
  PagePlotOptions o;
  o.spec.margin_mm = 12;
  o.caption_as_strokes = true;
  const std::string caption(400, 'W');
  const PagePlot drawn = plot_page({}, Rect2{0, 0, 4, 3}, caption, o);
  double xmax = 0;
  for (const PlotStroke& s : drawn.page.strokes)
    for (const Point2& p : s.points) xmax = std::max(xmax, p.x);
  EXPECT_LE(xmax, 297 - 12 + 1e-9);
  EXPECT_GT(xmax, 297 - 12 - 1);
}

}  // namespace
}  // namespace hlr
