// The JSON device with hidden lines by occlusion level: each hidden segment carries "level", and
// "hidden_stroke_levels" gives each hidden stroke's level, in the order of hidden_strokes; without levels
// neither member appears, so documents written without them stay as they were.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/camera/ortho_camera.hpp"
#include "core/device/formats/json_device.hpp"
#include "core/device/page/page_layout.hpp"

namespace hlr {
namespace {

using nlohmann::json;

VisibleSegment segment(double y, bool hidden, int level) {
  VisibleSegment s;
  s.p0 = {0, y, 0};
  s.p1 = {1, y, 0};
  s.s0 = {0, y};
  s.s1 = {1, y};
  s.hidden = hidden;
  s.level = static_cast<std::uint16_t>(level);
  return s;
}

PlotStroke stroke(double y, int pen, StrokeLayer layer, int level) {
  return PlotStroke{{{10, y}, {20, y}}, pen, layer, level};
}

// A frame made by hand (neither the engine nor the planner is under test): one visible segment, hidden
// ones at levels 2, 1 and 3, and strokes planned pen by pen, visible first, then level by level.
JsonFrame frame() {
  JsonFrame f;
  f.camera = ortho_camera({.eye = {0, 0, 10}, .target = {}, .up = {0, 1, 0}});
  f.object_names = {"box"};
  f.segments = {segment(0, false, 0), segment(1, true, 2), segment(2, true, 1), segment(3, true, 3)};
  f.plot.layout = fit_to_page(std::nullopt, f.segments, PageSpec{});
  f.plot.page.strokes = {stroke(10, 1, StrokeLayer::Visible, 0), stroke(20, 1, StrokeLayer::Hidden, 1),
                         stroke(30, 1, StrokeLayer::Hidden, 2), stroke(40, 2, StrokeLayer::Hidden, 3)};
  return f;
}

json first_frame(const JsonOptions& o) { return json::parse(to_json_text({frame()}, o))["frames"][0]; }

TEST(JsonDeviceLevels, HiddenSegmentsAndStrokesCarryTheirLevel) {
  JsonOptions o;
  o.include_hidden = true;
  o.levels = true;
  const json f = first_frame(o);
  ASSERT_EQ(f["segments"].size(), 4u);
  EXPECT_FALSE(f["segments"][0].contains("level"));  // visible: level 0 goes without saying
  EXPECT_EQ(f["segments"][1]["level"], 2);
  EXPECT_EQ(f["segments"][2]["level"], 1);
  EXPECT_EQ(f["segments"][3]["level"], 3);
  EXPECT_EQ(f["hidden_stroke_pens"], json::array({1, 1, 2}));
  EXPECT_EQ(f["hidden_stroke_levels"], json::array({1, 2, 3}));
  EXPECT_EQ(f["stroke_pens"], json::array({1}));
  // Schema order: the levels follow the hidden pens.
  const std::string text = to_json_text({frame()}, o);
  EXPECT_LT(text.find("\"hidden_stroke_pens\""), text.find("\"hidden_stroke_levels\""));
  EXPECT_LT(text.find("\"hidden_stroke_levels\""), text.find("\"stats\""));
  // The segment's member comes last, after "hidden".
  EXPECT_NE(text.find("\"hidden\":true,\"level\":2}"), std::string::npos) << text;
}

TEST(JsonDeviceLevels, WithoutLevelsNoLevelMembers) {
  JsonOptions o;
  o.include_hidden = true;
  const json f = first_frame(o);
  ASSERT_EQ(f["segments"].size(), 4u);
  for (const json& s : f["segments"]) EXPECT_FALSE(s.contains("level"));
  EXPECT_FALSE(f.contains("hidden_stroke_levels"));
  EXPECT_EQ(f["hidden_stroke_pens"], json::array({1, 1, 2}));
}

TEST(JsonDeviceLevels, LevelsGoWithTheStrokesPart) {
  JsonOptions o;
  o.include_hidden = true;
  o.levels = true;
  o.parts = *parse_json_parts("segments,stats");
  const json f = first_frame(o);
  EXPECT_FALSE(f.contains("hidden_stroke_levels"));
  EXPECT_EQ(f["segments"][3]["level"], 3);
}

}  // namespace
}  // namespace hlr
