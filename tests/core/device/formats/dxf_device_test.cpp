// The DXF writer (core/device/formats/dxf_device.hpp) read by a tiny group-code reader written here: layers,
// linetypes, entities, the y flip, numbers. tests/e2e/dxf_check.py reads whole files back with ezdxf.
#include "core/device/formats/dxf_device.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/device/page/atomic_file.hpp"

namespace hlr {
namespace {

using Pairs = std::vector<std::pair<int, std::string>>;

Pairs pairs_of(const std::string& dxf) {
  std::istringstream in(dxf);
  Pairs out;
  std::string code, value;
  while (std::getline(in, code) && std::getline(in, value)) out.emplace_back(std::stoi(code), value);
  return out;
}

// The values of `code` in the entities (after "ENTITIES") or the tables (before), in order.
std::vector<std::string> values(const Pairs& p, int code, bool entities) {
  std::vector<std::string> out;
  bool in_entities = false;
  for (const auto& [c, v] : p) {
    if (c == 2 && v == "ENTITIES") in_entities = true;
    if (c == code && in_entities == entities) out.push_back(v);
  }
  return out;
}

PlotPage page_of(std::vector<PlotStroke> strokes) {
  PlotPage page;
  page.width_mm = 100;
  page.height_mm = 50;
  page.strokes = std::move(strokes);
  return page;
}

TEST(DxfDevice, R12InMillimetresEndingInEof) {
  const Pairs p = pairs_of(to_dxf(page_of({}), {}));
  ASSERT_FALSE(p.empty());
  EXPECT_EQ(p.back(), (std::pair<int, std::string>{0, "EOF"}));
  const auto version = std::find(p.begin(), p.end(), std::pair<int, std::string>{9, "$ACADVER"});
  ASSERT_NE(version, p.end());
  EXPECT_EQ((version + 1)->second, "AC1009");
  const auto units = std::find(p.begin(), p.end(), std::pair<int, std::string>{9, "$INSUNITS"});
  ASSERT_NE(units, p.end());
  EXPECT_EQ((units + 1)->second, "4");
}

TEST(DxfDevice, LinesAndPolylinesWithYUpFromTheBottom) {
  // A two-point stroke is a LINE; three points a POLYLINE of three VERTEXes. The page's y runs down from
  // the top: y 10 on a 50 mm page is 40 up from the bottom.
  const Pairs p = pairs_of(to_dxf(page_of({{{{10, 10}, {20, 10}}, 1, StrokeLayer::Visible},
                                           {{{30, 5}, {40, 5}, {40, 45}}, 2, StrokeLayer::Visible}}),
                                  {}));
  const std::vector<std::string> kinds = values(p, 0, true);
  EXPECT_EQ(kinds, (std::vector<std::string>{"LINE", "POLYLINE", "VERTEX", "VERTEX", "VERTEX", "SEQEND",
                                             "ENDSEC", "EOF"}));
  const std::vector<std::string> xs = values(p, 10, true), ys = values(p, 20, true);
  // LINE start; POLYLINE's own (0, 0); the three vertices.
  EXPECT_EQ(xs, (std::vector<std::string>{"10.0000", "0.0000", "30.0000", "40.0000", "40.0000"}));
  EXPECT_EQ(ys, (std::vector<std::string>{"40.0000", "0.0000", "45.0000", "45.0000", "5.0000"}));
  EXPECT_EQ(values(p, 11, true), (std::vector<std::string>{"20.0000"}));
  EXPECT_EQ(values(p, 21, true), (std::vector<std::string>{"40.0000"}));
  EXPECT_EQ(values(p, 8, true), (std::vector<std::string>{"PEN1", "PEN2", "PEN2", "PEN2", "PEN2",
                                                          "PEN2"}));  // each on its pen's layer
}

TEST(DxfDevice, ClosedStrokesAreClosedPolylines) {
  const Pairs p =
      pairs_of(to_dxf(page_of({{{{0, 0}, {10, 0}, {10, 10}, {0, 0}}, 1, StrokeLayer::Visible}}), {}));
  EXPECT_EQ(values(p, 70, true), (std::vector<std::string>{"1"}));
  // The closing point is not repeated: the polyline, its three vertices, the end of its sequence.
  EXPECT_EQ(values(p, 0, true),
            (std::vector<std::string>{"POLYLINE", "VERTEX", "VERTEX", "VERTEX", "SEQEND", "ENDSEC", "EOF"}));
}

TEST(DxfDevice, LayersPerPenAndKindWithDashedHiddenLinetypes) {
  const Pairs p = pairs_of(to_dxf(page_of({{{{0, 0}, {1, 1}}, 1, StrokeLayer::Visible},
                                           {{{0, 0}, {1, 2}}, 1, StrokeLayer::Hidden, 1},
                                           {{{0, 0}, {2, 1}}, 3, StrokeLayer::Hidden, 2},
                                           {{{0, 0}, {2, 2}}, 2, StrokeLayer::Hatch}}),
                                  {}));
  // Layer "0", then the drawing's in pen order.
  EXPECT_EQ(values(p, 2, false),
            (std::vector<std::string>{"HEADER", "TABLES", "LTYPE", "CONTINUOUS", "HIDDEN", "HIDDEN2", "LAYER",
                                      "0", "PEN1", "PEN1_HIDDEN", "PEN2_HATCH", "PEN3_HIDDEN_2"}));
  // Their linetypes, and the colours: pen 1 black (7), 2 red (1), 3 green (3).
  EXPECT_EQ(values(p, 6, false),
            (std::vector<std::string>{"CONTINUOUS", "CONTINUOUS", "HIDDEN", "CONTINUOUS", "HIDDEN2"}));
  EXPECT_EQ(values(p, 62, false), (std::vector<std::string>{"7", "7", "7", "1", "3"}));
  // HIDDEN dashes as the PDF's hidden lines do: 2 mm on, 1.2 off; level 2 1.6 and 1.6.
  EXPECT_EQ(values(p, 49, false), (std::vector<std::string>{"2.0000", "-1.2000", "1.6000", "-1.6000"}));
}

TEST(DxfDevice, ColourIndexIsTheNearest) {
  EXPECT_EQ(dxf_colour_index({0, 0, 0}), 7);
  EXPECT_EQ(dxf_colour_index({1, 0, 0}), 1);
  EXPECT_EQ(dxf_colour_index({0, 0, 1}), 5);
  EXPECT_EQ(dxf_colour_index({1, 1, 0}), 2);
  EXPECT_EQ(dxf_colour_index({0.5, 0.5, 0.5}), 8);
  // Orange, #ff8000: the hue 30° at full value, index 30.
  EXPECT_EQ(dxf_colour_index({1, 127.0 / 255, 0}), 30);
}

TEST(DxfDevice, NoNegativeZeroAndBadPagesRefused) {
  const std::string dxf = to_dxf(page_of({{{{-0.00001, 50}, {1e-6, 50}}, 1, StrokeLayer::Visible}}), {});
  EXPECT_EQ(dxf.find("-0.0000"), std::string::npos);
  PlotPage bad = page_of({});
  bad.width_mm = -1;
  EXPECT_THROW(to_dxf(bad, {}), DeviceError);
  PlotPage nan = page_of({{{{NAN, 0}, {1, 1}}, 1, StrokeLayer::Visible}});
  EXPECT_THROW(to_dxf(nan, {}), DeviceError);
}

}  // namespace
}  // namespace hlr
