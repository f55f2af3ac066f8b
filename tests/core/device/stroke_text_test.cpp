#include "core/device/stroke_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "core/device/page_plot.hpp"

namespace hlr {
namespace {

using Strokes = std::vector<std::vector<Point2>>;

// The simplex font read straight from Debian's data file, by the format's own rules (each glyph line: a
// 5-digit number, a 3-digit count of pairs, then pairs of letters; a letter's value is its distance from
// 'R'; the first pair is the left and right bearing; " R" lifts the pen; y grows down with the baseline
// at +9) — independent of the library hlrscript reads it with. Glyph lines start at ' ' and follow ASCII.
struct JhfGlyph {
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
    if (c == 0x7f) continue;  // DEL is a control character, drawn as '?'
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

TEST(StrokeText, NonAsciiAndControlBytesAreQuestionMarks) {
  const Strokes q = stroke_text("?", {0, 0}, 3);
  EXPECT_EQ(stroke_text("\xc3\xa9", {0, 0}, 3).size(), 2 * q.size());  // é in UTF-8: two bytes
  EXPECT_EQ(stroke_text("\t", {0, 0}, 3), q);
  EXPECT_TRUE(stroke_text("   ", {0, 0}, 3).empty());
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
