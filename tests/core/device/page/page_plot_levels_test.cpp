// plot_page() with hidden lines by occlusion level: which hidden pieces are planned, the level and pen
// each stroke gets (the hidden pen + level − 1, else the object's pen), a last level past the last pen,
// the pieces counted per level; and the dash pattern each level is drawn with on PDF, SVG and PNG.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <utility>
#include <vector>

#include "core/device/page/atomic_file.hpp"
#include "core/device/page/page_plot.hpp"
#include "core/device/page/page_style.hpp"

namespace hlr {
namespace {

// A horizontal piece at height y of `object`, hidden at `level` (0: visible).
VisibleSegment piece(double y, std::uint32_t object, int level) {
  VisibleSegment s;
  s.s0 = {-1, y};
  s.s1 = {1, y};
  s.object = object;
  s.hidden = level > 0;
  s.level = static_cast<std::uint16_t>(level);
  return s;
}

// Five pieces apart from each other: object 0 visible and hidden at levels 1, 2, 3; object 1 at level 1.
std::vector<VisibleSegment> scene() {
  return {piece(0.8, 0, 0), piece(0.4, 0, 1), piece(0, 0, 2), piece(-0.4, 0, 3), piece(-0.8, 1, 1)};
}

PagePlotOptions options(HiddenStyle hidden, std::optional<int> hidden_pen = std::nullopt) {
  PagePlotOptions o;
  o.object_pens = {4, 7};
  o.hidden = hidden;
  o.hidden_pen = hidden_pen;
  o.plan.order = PenOrder::Greedy;
  return o;
}

const Rect2 kFrame{-1, -1, 1, 1};

// (pen, level) of every hidden stroke, counted.
std::map<std::pair<int, int>, int> hidden_strokes(const PagePlot& plot) {
  std::map<std::pair<int, int>, int> out;
  for (const PlotStroke& s : plot.page.strokes)
    if (s.layer == StrokeLayer::Hidden) ++out[{s.pen, s.level}];
  return out;
}

TEST(PagePlotLevels, EachLevelInTheObjectsPenWithoutAHiddenPen) {
  const PagePlot plot = plot_page(scene(), kFrame, "", options(HiddenStyle::counted(3)));
  const std::map<std::pair<int, int>, int> expected{{{4, 1}, 1}, {{4, 2}, 1}, {{4, 3}, 1}, {{7, 1}, 1}};
  EXPECT_EQ(hidden_strokes(plot), expected);
  EXPECT_EQ(plot.visible_segments, 1u);
  EXPECT_EQ(plot.level_pieces, (std::vector<std::size_t>{0, 2, 1, 1}));
}

TEST(PagePlotLevels, LevelKInTheHiddenPenPlusKMinusOne) {
  const PagePlot plot = plot_page(scene(), kFrame, "", options(HiddenStyle::counted(3), 10));
  // Level 1 of both objects in pen 10, level 2 in 11, level 3 in 12; the visible piece keeps pen 4.
  const std::map<std::pair<int, int>, int> expected{{{10, 1}, 2}, {{11, 2}, 1}, {{12, 3}, 1}};
  EXPECT_EQ(hidden_strokes(plot), expected);
  std::set<int> visible_pens;
  for (const PlotStroke& s : plot.page.strokes)
    if (s.layer == StrokeLayer::Visible) visible_pens.insert(s.pen);
  EXPECT_EQ(visible_pens, std::set<int>{4});
}

TEST(PagePlotLevels, LevelsDeeperThanAskedAreLeftOut) {
  const PagePlot plot = plot_page(scene(), kFrame, "", options(HiddenStyle::counted(2)));
  const std::map<std::pair<int, int>, int> expected{{{4, 1}, 1}, {{4, 2}, 1}, {{7, 1}, 1}};
  EXPECT_EQ(hidden_strokes(plot), expected);
  EXPECT_EQ(plot.level_pieces, (std::vector<std::size_t>{0, 2, 1}));
}

TEST(PagePlotLevels, PlainDashedAndOffIgnoreLevels) {
  const PagePlot dashed = plot_page(scene(), kFrame, "", options(HiddenStyle::dashed(), 5));
  // Every hidden piece on the one hidden pen, at level 0: the layer as before levels existed.
  const std::map<std::pair<int, int>, int> expected{{{5, 0}, 4}};
  EXPECT_EQ(hidden_strokes(dashed), expected);
  EXPECT_TRUE(dashed.level_pieces.empty());
  const PagePlot off = plot_page(scene(), kFrame, "", options(HiddenStyle::off(), 5));
  EXPECT_TRUE(hidden_strokes(off).empty());
  EXPECT_EQ(off.page.strokes.size(), 1u);
}

TEST(PagePlotLevels, ALevelsPenPastTheLastPenIsAnError) {
  // Levels 1..3 from pen 254 need pen 256: the level-3 piece cannot be drawn.
  EXPECT_THROW(plot_page(scene(), kFrame, "", options(HiddenStyle::counted(3), 254)), DeviceError);
  // Pen 253 + 3 − 1 = 255: the last pen, drawn.
  EXPECT_NO_THROW(plot_page(scene(), kFrame, "", options(HiddenStyle::counted(3), 253)));
}

TEST(PagePlotLevels, PlotterDashesKeepLevels) {
  PagePlotOptions o = options(HiddenStyle::counted(3), 10);
  o.hidden_dashes = DashPattern{};
  const PagePlot plot = plot_page(scene(), kFrame, "", o);
  std::set<std::pair<int, int>> seen;
  for (const PlotStroke& s : plot.page.strokes)
    if (s.layer == StrokeLayer::Hidden) seen.insert({s.pen, s.level});
  EXPECT_EQ(seen, (std::set<std::pair<int, int>>{{10, 1}, {11, 2}, {12, 3}}));
  EXPECT_GT(plot.stats.hidden_dashes, 4u);  // the pieces are long enough for several dashes each
}

// The documented patterns (core/device/page/page_style.hpp): level 1 as plain hidden lines, then each
// level 0.4 mm less dash down to 0.4 mm and 0.4 mm more gap.
TEST(PageStyleLevels, DashPatternPerLevel) {
  const double expected[][2] = {{2, 1.2}, {1.6, 1.6}, {1.2, 2.0}, {0.8, 2.4}, {0.4, 2.8}, {0.4, 3.2}};
  for (int level = 1; level <= 6; ++level) {
    EXPECT_NEAR(level_dash_mm(level), expected[level - 1][0], 1e-12) << level;
    EXPECT_NEAR(level_gap_mm(level), expected[level - 1][1], 1e-12) << level;
  }
  EXPECT_NEAR(level_gap_mm(16), 7.2, 1e-12);
  // Plain hidden strokes (level 0) and level 1 look alike: today's 2 mm dashes and 1.2 mm gaps.
  EXPECT_EQ(dash_on_mm(0.25, 0), dash_on_mm(0.25));
  EXPECT_EQ(dash_off_mm(0.25, 1), dash_off_mm(0.25));
  EXPECT_NEAR(dash_on_mm(0.25), 1.75, 1e-12);
  // No two levels share a pattern.
  std::set<std::pair<double, double>> patterns;
  for (int level = 1; level <= kMaxOcclusionLevel; ++level)
    patterns.insert({dash_on_mm(0.3, level), dash_off_mm(0.3, level)});
  EXPECT_EQ(patterns.size(), static_cast<std::size_t>(kMaxOcclusionLevel));
}

}  // namespace
}  // namespace hlr
