#include "core/device/formats/plotter_svg.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/device/page/atomic_file.hpp"

namespace hlr {
namespace {

PlotPage page_of(std::vector<PlotStroke> strokes, double w = 100, double h = 50) {
  PlotPage page;
  page.width_mm = w;
  page.height_mm = h;
  page.strokes = std::move(strokes);
  return page;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(PlotterSvg, SizedInMillimetresWithAMatchingViewBox) {
  const std::string svg = to_plotter_svg(page_of({}, 297, 210), {});
  EXPECT_NE(svg.find("width=\"297mm\" height=\"210mm\" viewBox=\"0 0 297 210\""), std::string::npos) << svg;
  EXPECT_EQ(count(svg, "<g "), 0u);  // nothing to draw, nothing drawn
  EXPECT_EQ(count(svg, "<path"), 0u);
}

TEST(PlotterSvg, OneLayerPerPenInPenOrderAndPathsInPlannedOrder) {
  // Planned order: pen 2, pen 1, pen 2 again, a hidden stroke of pen 1.
  const PlotPage page = page_of({{{{10, 10}, {20, 10}}, 2, StrokeLayer::Visible},
                                 {{{30, 30}, {40, 30}, {40, 40}}, 1, StrokeLayer::Visible},
                                 {{{50, 10}, {60, 10}}, 2, StrokeLayer::Visible},
                                 {{{1, 2}, {3, 4}}, 1, StrokeLayer::Hidden}});
  const std::string svg = to_plotter_svg(page, {});
  const std::size_t l1 = svg.find("inkscape:label=\"1 black\""),
                    l1h = svg.find("inkscape:label=\"1 hidden\"");
  const std::size_t l2 = svg.find("inkscape:label=\"2 red\"");
  ASSERT_NE(l1, std::string::npos) << svg;
  ASSERT_NE(l1h, std::string::npos) << svg;
  ASSERT_NE(l2, std::string::npos) << svg;
  EXPECT_LT(l1, l1h);
  EXPECT_LT(l1h, l2);
  EXPECT_EQ(count(svg, "inkscape:groupmode=\"layer\""), 3u);
  // Pen 2's layer holds s0 then s2; pen 1's s1; the hidden layer s3, dashed.
  const std::size_t s0 = svg.find("id=\"s0\""), s2 = svg.find("id=\"s2\"");
  EXPECT_GT(s0, l2);
  EXPECT_LT(s0, s2);
  EXPECT_GT(svg.find("id=\"s1\""), l1);
  EXPECT_LT(svg.find("id=\"s1\""), l1h);
  EXPECT_NE(svg.find("d=\"M 30,30 L 40,30 40,40\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
  EXPECT_EQ(count(svg, "stroke-dasharray"), 1u);
  EXPECT_EQ(count(svg, "fill=\"none\""), 3u);
  EXPECT_EQ(svg.find("<text"), std::string::npos);
  EXPECT_EQ(svg.find("<rect"), std::string::npos);
}

TEST(PlotterSvg, LayersCarryThePensColourAndWidth) {
  PlotterSvgOptions options;
  options.pens.set(3, {0.1, 0.2, 0.3, 0.7});
  const std::string svg = to_plotter_svg(page_of({{{{1, 1}, {2, 2}}, 3, StrokeLayer::Visible}}), options);
  EXPECT_NE(svg.find("inkscape:label=\"3 #1a334d\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("stroke=\"#1a334d\" stroke-width=\"0.7\""), std::string::npos) << svg;
}

TEST(PlotterSvg, NumbersToAThousandthWithoutNegativeZero) {
  const std::string svg =
      to_plotter_svg(page_of({{{{0.0000004, 12.3456789}, {99.9995, 1.0 / 3}}, 1, StrokeLayer::Visible}}), {});
  EXPECT_NE(svg.find("d=\"M 0,12.346 L 100,0.333\""), std::string::npos) << svg;
  EXPECT_EQ(svg.find("-0"), std::string::npos);
}

TEST(PlotterSvg, TheTitleIsEscapedAndNotDrawn) {
  PlotterSvgOptions options;
  options.title = "a<b & \"c\"";
  const std::string svg = to_plotter_svg(page_of({}), options);
  EXPECT_NE(svg.find("<title>a&lt;b &amp; &quot;c&quot;</title>"), std::string::npos) << svg;
}

TEST(PlotterSvg, PointsOffThePageAreRefusedUnlessClipped) {
  const PlotPage page = page_of({{{{-10, 25}, {50, 25}, {50, 80}}, 1, StrokeLayer::Visible}});
  try {
    (void)to_plotter_svg(page, {});
    FAIL() << "expected DeviceError";
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("(-10, 25) mm lies off the 100 × 50 mm page"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("--clip"), std::string::npos);
  }
  PlotterSvgOptions clip;
  clip.clip = true;
  const std::string svg = to_plotter_svg(page, clip);
  EXPECT_NE(svg.find("d=\"M 0,25 L 50,25 50,50\""), std::string::npos) << svg;
}

TEST(PlotterSvg, AStrokeLeavingAndReenteringIsCutIntoPieces) {
  PlotterSvgOptions clip;
  clip.clip = true;
  const std::string svg =
      to_plotter_svg(page_of({{{{10, 10}, {10, 70}, {20, 70}, {20, 10}}, 1, StrokeLayer::Visible}}), clip);
  EXPECT_NE(svg.find("id=\"s0\" d=\"M 10,10 L 10,50\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("id=\"s0-1\" d=\"M 20,50 L 20,10\""), std::string::npos) << svg;
}

TEST(PlotterSvg, BadPagesAndPointsAreErrors) {
  EXPECT_THROW((void)to_plotter_svg(page_of({}, 0, 10), {}), DeviceError);
  EXPECT_THROW((void)to_plotter_svg(page_of({}, 10, std::nan("")), {}), DeviceError);
  EXPECT_THROW((void)to_plotter_svg(page_of({{{{1, 1}, {std::nan(""), 2}}, 1, StrokeLayer::Visible}}), {}),
               DeviceError);
}

TEST(PlotterSvg, LayerLabelsNameTheColour) {
  EXPECT_EQ(plotter_svg_layer_label(1, default_pen_style(1), StrokeLayer::Visible), "1 black");
  EXPECT_EQ(plotter_svg_layer_label(4, default_pen_style(4), StrokeLayer::Visible), "4 blue");
  EXPECT_EQ(plotter_svg_layer_label(7, default_pen_style(7), StrokeLayer::Visible), "7 #cc9900");
  EXPECT_EQ(plotter_svg_layer_label(2, default_pen_style(2), StrokeLayer::Hidden), "2 hidden");
  EXPECT_EQ(plotter_svg_layer_label(2, default_pen_style(2), StrokeLayer::Hidden, 3), "2 hidden 3");
  EXPECT_EQ(plotter_svg_layer_label(3, default_pen_style(3), StrokeLayer::Hatch), "3 hatch");
}

// Hidden lines by occlusion level: a layer per pen and level, "N hidden K", after the pen's visible layer
// and in level order (the plan's), each with its level's dash array (0.25 mm pens: dash − 0.25, gap +
// 0.25: level 1 1.75 1.45, level 2 1.35 1.85, level 3 0.95 2.25).
TEST(PlotterSvg, ALayerPerOcclusionLevel) {
  const StrokeLayer V = StrokeLayer::Visible, H = StrokeLayer::Hidden;
  const PlotPage page = page_of({{{{1, 1}, {2, 1}}, 1, V, 0},
                                 {{{1, 2}, {2, 2}}, 1, H, 1},
                                 {{{1, 3}, {2, 3}}, 1, H, 2},
                                 {{{1, 4}, {2, 4}}, 1, H, 3},
                                 {{{1, 5}, {2, 5}}, 2, H, 1}});
  const std::string svg = to_plotter_svg(page, {});
  const std::size_t v1 = svg.find("inkscape:label=\"1 black\""),
                    h11 = svg.find("inkscape:label=\"1 hidden 1\""),
                    h12 = svg.find("inkscape:label=\"1 hidden 2\""),
                    h13 = svg.find("inkscape:label=\"1 hidden 3\""),
                    h21 = svg.find("inkscape:label=\"2 hidden 1\"");
  for (std::size_t at : {v1, h11, h12, h13, h21}) ASSERT_NE(at, std::string::npos) << svg;
  EXPECT_LT(v1, h11);
  EXPECT_LT(h11, h12);
  EXPECT_LT(h12, h13);
  EXPECT_LT(h13, h21);
  EXPECT_EQ(count(svg, "inkscape:groupmode=\"layer\""), 5u);
  EXPECT_EQ(svg.find("\"1 hidden\""), std::string::npos);  // no plain hidden layer
  EXPECT_NE(svg.find("id=\"layer-1-hidden-2\""), std::string::npos) << svg;
  // Each layer's dash array is its level's; s2 (level 2) sits in the level-2 layer.
  const std::size_t d1 = svg.find("stroke-dasharray=\"1.75 1.45\""),
                    d2 = svg.find("stroke-dasharray=\"1.35 1.85\""),
                    d3 = svg.find("stroke-dasharray=\"0.95 2.25\"");
  ASSERT_NE(d1, std::string::npos) << svg;
  ASSERT_NE(d2, std::string::npos) << svg;
  ASSERT_NE(d3, std::string::npos) << svg;
  EXPECT_GT(d2, h12);
  EXPECT_LT(d2, h13);
  EXPECT_EQ(count(svg, "stroke-dasharray=\"1.75 1.45\""), 2u);  // level 1 of pens 1 and 2
  const std::size_t s2 = svg.find("id=\"s2\"");
  EXPECT_GT(s2, h12);
  EXPECT_LT(s2, h13);
}

}  // namespace
}  // namespace hlr
