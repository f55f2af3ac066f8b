#include "core/device/formats/json_device.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/camera/desens_camera.hpp"
#include "core/camera/lookat_camera.hpp"
#include "core/camera/orbit_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "core/device/page/atomic_file.hpp"
#include "core/device/page/page_layout.hpp"

namespace hlr {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const LookatParameters kLookat{.eye = {30, 20, 15}, .target = {0, 0, 0}, .up = {0, 0, 1}, .fov_deg = 40};

VisibleSegment piece(const Camera& c, Point3 a, Point3 b, std::uint32_t object = 0, std::uint32_t edge = 0) {
  VisibleSegment s;
  s.p0 = a;
  s.p1 = b;
  s.s0 = c.project(a);
  s.s1 = c.project(b);
  s.object = object;
  s.edge = edge;
  return s;
}

PlotStroke stroke(std::vector<Point2> points, int pen, StrokeLayer layer) {
  return PlotStroke{std::move(points), pen, layer};
}

// A planned page made by hand (the planner is not under test): two pens, visible before hidden within a
// pen as the plan orders them, so the layers interleave. Stroke 2 starts where stroke 0 ends: the device
// must still keep them apart.
PagePlot hand_plot(const PageLayout& layout) {
  PagePlot p;
  p.layout = layout;
  p.page.strokes = {stroke({{20, 30}, {40, 30}, {40, 50}}, 2, StrokeLayer::Visible),
                    stroke({{100, 100}, {120.5, 110.25}}, 2, StrokeLayer::Hidden),
                    stroke({{40, 50}, {80, 70}}, 3, StrokeLayer::Visible),
                    stroke({{10.5, 11.25}, {12, 13}, {14, 15}, {16, 17}}, 3, StrokeLayer::Hidden)};
  p.stats.pieces = 7;
  p.stats.merged_pieces = 6;
  p.stats.pen_down_mm = 123.5;
  p.stats.pen_up_mm = 456.25;
  p.stats.pen_up_mean_mm = 91.25;
  p.stats.pen_up_median_mm = 80.5;
  p.stats.lifts = 4;
  p.stats.lift_lower_bound = 3;
  p.stats.plot_seconds = 2.75;
  p.stats.planning_ms = 12;
  p.visible_segments = 4;
  return p;
}

// A unit cube's visible-looking pieces, laid out on the default page the way plot_page fits them.
JsonFrame cube_frame(const Camera& camera) {
  JsonFrame f;
  f.frame = 3;
  f.time = 0.25;
  f.camera = camera;
  f.object_names = {"cube", "wedge"};
  f.segments = {piece(camera, {1, 1, 1}, {-1, 1, 1}, 0, 4), piece(camera, {-1, 1, 1}, {-1, -1, 1}, 0, 5),
                piece(camera, {1, -1, 1}, {1, -1, -1}, 1, 7), piece(camera, {1, 1, -1}, {1, 1, 1}, 0, 9)};
  f.plot = hand_plot(fit_to_page(camera.frame, f.segments, PageSpec{}));
  return f;
}

json parse(const std::string& text) { return json::parse(text); }

void expect_vec3(const json& j, double x, double y, double z, double tolerance = 1e-12) {
  ASSERT_TRUE(j.is_array());
  ASSERT_EQ(j.size(), 3u);
  EXPECT_NEAR(j[0].get<double>(), x, tolerance);
  EXPECT_NEAR(j[1].get<double>(), y, tolerance);
  EXPECT_NEAR(j[2].get<double>(), z, tolerance);
}

std::vector<std::string> keys(const nlohmann::ordered_json& object) {
  std::vector<std::string> out;
  for (auto it = object.begin(); it != object.end(); ++it) out.push_back(it.key());
  return out;
}

// The hand plot's strokes as the schema spells them.
const json kVisibleStrokes = {{{20.0, 30.0}, {40.0, 30.0}, {40.0, 50.0}}, {{40.0, 50.0}, {80.0, 70.0}}};
const json kHiddenStrokes = {{{100.0, 100.0}, {120.5, 110.25}},
                             {{10.5, 11.25}, {12.0, 13.0}, {14.0, 15.0}, {16.0, 17.0}}};

TEST(JsonDevice, DocumentFieldsForALookatFrame) {
  const Camera camera = lookat_camera(kLookat);
  const JsonFrame f = cube_frame(camera);
  JsonOptions o;
  o.title = "cube test";
  const json doc = parse(to_json_text({f}, o));

  EXPECT_EQ(doc["format"], "hlrscript.lines/1");
  EXPECT_EQ(doc["title"], "cube test");
  const json& page = doc["page"];
  EXPECT_EQ(page["width_mm"], 297.0);
  EXPECT_EQ(page["height_mm"], 210.0);
  EXPECT_EQ(page["margin_mm"], 12.0);
  EXPECT_EQ(page["origin"], "top-left");
  EXPECT_EQ(page["y"], "down");
  ASSERT_EQ(doc["frames"].size(), 1u);

  const json& fr = doc["frames"][0];
  EXPECT_EQ(fr["frame"], 3);
  EXPECT_EQ(fr["time"], 0.25);

  const json& cam = fr["camera"];
  EXPECT_EQ(cam["kind"], "perspective");
  EXPECT_EQ(cam["constructor"], "lookat");
  expect_vec3(cam["eye"], 30, 20, 15);
  const Vector3 d = normalize(kLookat.target - kLookat.eye);
  expect_vec3(cam["direction"], d.x, d.y, d.z);
  EXPECT_EQ(cam["focal"].get<double>(), camera.focal);
  EXPECT_EQ(cam["offset"], json::array({0.0, 0.0}));
  EXPECT_EQ(cam["near_depth"].get<double>(), camera.near_depth);
  EXPECT_FALSE(cam.contains("frame"));
  for (int i = 0; i < 3; ++i) {
    const Vector3 row = camera.viewFromWorld.row(i);
    EXPECT_EQ(cam["view_from_world"]["m"][i], json::array({row.x, row.y, row.z}));
  }
  const Vector3 t = camera.viewFromWorld.t;
  EXPECT_EQ(cam["view_from_world"]["t"], json::array({t.x, t.y, t.z}));

  // No camera frame: the pieces' extent is fitted.
  const PageLayout l = fit_to_page(std::nullopt, f.segments, PageSpec{});
  EXPECT_EQ(fr["layout"]["mm_per_unit"].get<double>(), l.scale);
  const Point2 origin = l.to_page_mm({0, 0});
  EXPECT_NEAR(fr["layout"]["origin_mm"][0].get<double>(), origin.x, 1e-9);
  EXPECT_NEAR(fr["layout"]["origin_mm"][1].get<double>(), origin.y, 1e-9);

  const json& segs = fr["segments"];
  ASSERT_EQ(segs.size(), f.segments.size());
  for (std::size_t i = 0; i < f.segments.size(); ++i) {
    const VisibleSegment& s = f.segments[i];
    const json& j = segs[i];
    EXPECT_EQ(j["p"],
              json::array({json::array({s.p0.x, s.p0.y, s.p0.z}), json::array({s.p1.x, s.p1.y, s.p1.z})}));
    EXPECT_EQ(j["s"], json::array({json::array({s.s0.x, s.s0.y}), json::array({s.s1.x, s.s1.y})}));
    EXPECT_EQ(j["object"], f.object_names[s.object]);
    EXPECT_EQ(j["edge"], s.edge);
    EXPECT_EQ(j["hidden"], false);
    EXPECT_FALSE(j.contains("other"));
    EXPECT_EQ(j.size(), 5u);
  }

  // The plot's visible strokes in order, not joined although stroke 1 starts where stroke 0 ends.
  EXPECT_EQ(fr["strokes"], kVisibleStrokes);
  EXPECT_EQ(fr["stroke_pens"], json::array({2, 3}));
  EXPECT_FALSE(fr.contains("hidden_strokes"));
  EXPECT_FALSE(fr.contains("hidden_stroke_pens"));

  const json want_stats = {{"segments", 4},           {"pen_down_mm", 123.5},     {"pen_up_mm", 456.25},
                           {"pen_up_mean_mm", 91.25}, {"pen_up_median_mm", 80.5}, {"lifts", 4},
                           {"lift_lower_bound", 3},   {"plot_seconds", 2.75},     {"pen_order", "optimized"}};
  EXPECT_EQ(fr["stats"], want_stats);
}

TEST(JsonDevice, LayoutOfTheCameraFrameMapsPictureToPage) {
  LookatParameters p = kLookat;
  p.aspect = 1.5;
  const Camera camera = lookat_camera(p);
  JsonFrame f = cube_frame(camera);
  // What plot_page would draw: every piece mapped through the frame's layout.
  const PageLayout layout = fit_to_page(camera.frame, f.segments, PageSpec{});
  f.plot.page.strokes.clear();
  for (const VisibleSegment& s : f.segments)
    f.plot.page.strokes.push_back(
        stroke({layout.to_page_mm(s.s0), layout.to_page_mm(s.s1)}, 1, StrokeLayer::Visible));
  const json fr = parse(to_json_text({f}, {}))["frames"][0];
  EXPECT_EQ(fr["camera"]["frame"], json::array({-1.5, -1.0, 1.5, 1.0}));
  // Frame 3 × 2 on room 273 × 186: scale min(91, 93) = 91, picture (0, 0) at the page centre.
  const double s = fr["layout"]["mm_per_unit"].get<double>();
  const double x0 = fr["layout"]["origin_mm"][0].get<double>(),
               y0 = fr["layout"]["origin_mm"][1].get<double>();
  EXPECT_DOUBLE_EQ(s, 91);
  EXPECT_NEAR(x0, 148.5, 1e-12);
  EXPECT_NEAR(y0, 105, 1e-12);
  // The documented mapping, page = origin_mm + mm_per_unit·(u, −v), reproduces every stroke point.
  const json& strokes = fr["strokes"];
  ASSERT_EQ(strokes.size(), f.segments.size());
  for (std::size_t i = 0; i < f.segments.size(); ++i) {
    const Point2 ends[2] = {f.segments[i].s0, f.segments[i].s1};
    ASSERT_EQ(strokes[i].size(), 2u);
    for (int k = 0; k < 2; ++k) {
      const double x = strokes[i][k][0].get<double>(), y = strokes[i][k][1].get<double>();
      EXPECT_NEAR(x, x0 + s * ends[k].x, 1e-9) << i << "," << k;
      EXPECT_NEAR(y, y0 - s * ends[k].y, 1e-9) << i << "," << k;
      EXPECT_GE(x, 12);
      EXPECT_LE(x, 285);
      EXPECT_GE(y, 12);
      EXPECT_LE(y, 198);
    }
  }
  EXPECT_EQ(fr["stroke_pens"], json::array({1, 1, 1, 1}));
}

TEST(JsonDevice, LayoutIsThePlotsNotRecomputed) {
  JsonFrame f = cube_frame(lookat_camera(kLookat));
  f.plot.layout.scale = 2.5;
  f.plot.layout.picture_centre = {1, -2};
  const json fr = parse(to_json_text({f}, {}))["frames"][0];
  EXPECT_EQ(fr["layout"]["mm_per_unit"], 2.5);
  // Picture (0, 0) is (−1, +2) from the centre (148.5, 105): x 148.5 − 2.5, y 105 − 2.5·2 (y down).
  EXPECT_EQ(fr["layout"]["origin_mm"], json::array({146.0, 100.0}));
}

TEST(JsonDevice, StrokesAndPensByLayerInPlottingOrder) {
  const JsonFrame f = cube_frame(lookat_camera(kLookat));
  JsonOptions o;
  const json off = parse(to_json_text({f}, o))["frames"][0];
  EXPECT_EQ(off["strokes"], kVisibleStrokes);
  EXPECT_EQ(off["stroke_pens"], json::array({2, 3}));
  EXPECT_FALSE(off.contains("hidden_strokes"));
  EXPECT_FALSE(off.contains("hidden_stroke_pens"));

  o.include_hidden = true;
  const json on = parse(to_json_text({f}, o))["frames"][0];
  EXPECT_EQ(on["strokes"], kVisibleStrokes);
  EXPECT_EQ(on["stroke_pens"], json::array({2, 3}));
  EXPECT_EQ(on["hidden_strokes"], kHiddenStrokes);
  EXPECT_EQ(on["hidden_stroke_pens"], json::array({2, 3}));
  EXPECT_EQ(on["stats"], off["stats"]);  // the plan's numbers, whatever is listed

  // Reversed plotting order and other pens come through as given.
  JsonFrame g = f;
  std::reverse(g.plot.page.strokes.begin(), g.plot.page.strokes.end());
  g.plot.page.strokes[0].pen = 7;
  const json rev = parse(to_json_text({g}, o))["frames"][0];
  EXPECT_EQ(rev["strokes"], json::array({kVisibleStrokes[1], kVisibleStrokes[0]}));
  EXPECT_EQ(rev["stroke_pens"], json::array({3, 2}));
  EXPECT_EQ(rev["hidden_strokes"], json::array({kHiddenStrokes[1], kHiddenStrokes[0]}));
  EXPECT_EQ(rev["hidden_stroke_pens"], json::array({7, 2}));
}

TEST(JsonDevice, OnlyHiddenStrokes) {
  JsonFrame f = cube_frame(lookat_camera(kLookat));
  for (PlotStroke& s : f.plot.page.strokes) s.layer = StrokeLayer::Hidden;
  JsonOptions o;
  o.include_hidden = true;
  const json fr = parse(to_json_text({f}, o))["frames"][0];
  EXPECT_EQ(fr["strokes"], json::array());
  EXPECT_EQ(fr["stroke_pens"], json::array());
  ASSERT_EQ(fr["hidden_strokes"].size(), 4u);
  EXPECT_EQ(fr["hidden_strokes"][0], kVisibleStrokes[0]);
  EXPECT_EQ(fr["hidden_strokes"][1], kHiddenStrokes[0]);
  EXPECT_EQ(fr["hidden_stroke_pens"], json::array({2, 2, 3, 3}));
}

TEST(JsonDevice, PenOrderIsReportedAsGiven) {
  JsonOptions o;
  o.pen_order = "greedy";
  const json st = parse(to_json_text({cube_frame(lookat_camera(kLookat))}, o))["frames"][0]["stats"];
  EXPECT_EQ(st["pen_order"], "greedy");
  o.pen_order = "none";
  EXPECT_EQ(parse(to_json_text({cube_frame(lookat_camera(kLookat))}, o))["frames"][0]["stats"]["pen_order"],
            "none");
}

TEST(JsonDevice, OrthographicCamera) {
  const OrthoParameters p{.eye = {4, -3, 2}, .target = {1, 1, 0}, .up = {0, 0, 1}, .height = 8};
  const Camera camera = ortho_camera(p);
  const json cam = parse(to_json_text({cube_frame(camera)}, {}))["frames"][0]["camera"];
  EXPECT_EQ(cam["kind"], "orthographic");
  EXPECT_EQ(cam["constructor"], "ortho");
  expect_vec3(cam["eye"], 4, -3, 2);  // a point on the view axis
  const Vector3 d = normalize(p.target - p.eye);
  expect_vec3(cam["direction"], d.x, d.y, d.z);
  EXPECT_DOUBLE_EQ(cam["focal"].get<double>(), 0.25);
  EXPECT_FALSE(cam.contains("near_depth"));
}

TEST(JsonDevice, DesensCameraIsPerspective) {
  const DesensParameters p;  // object 40 in front along −x, eye at x = +F
  const Camera camera = desens_camera(p);
  const json cam = parse(to_json_text({cube_frame(camera)}, {}))["frames"][0]["camera"];
  EXPECT_EQ(cam["kind"], "perspective");
  EXPECT_EQ(cam["constructor"], "desens");
  const Point3 eye = desens_observer_points(p).eye;
  expect_vec3(cam["eye"], eye.x, eye.y, eye.z);
  expect_vec3(cam["eye"], 40 + p.focal, 0, 0);
  expect_vec3(cam["direction"], -1, 0, 0);
  EXPECT_EQ(cam["frame"], json::array({-1.0, -1.0, 1.0, 1.0}));

  DesensParameters turned;
  turned.heading = {30, -10, 5};
  turned.attitude = {15, 0, 0};
  turned.observer_position = {5, 2, 3};
  const Camera c2 = desens_camera(turned);
  const json cam2 = parse(to_json_text({cube_frame(c2)}, {}))["frames"][0]["camera"];
  const Point3 eye2 = desens_observer_points(turned).eye;
  expect_vec3(cam2["eye"], eye2.x, eye2.y, eye2.z, 1e-9);
  // The view direction points from the eye through the picture origin (x = 0 plane, one F away).
  const Vector3 d2 = normalize(desens_observer_points(turned).picture_origin - eye2);
  expect_vec3(cam2["direction"], d2.x, d2.y, d2.z, 1e-12);
}

TEST(JsonDevice, OrbitCameraLooksAtTheOrigin) {
  const OrbitParameters p{.theta_deg = 30, .phi_deg = 60, .rho = 10, .d = 2};
  const json cam = parse(to_json_text({cube_frame(orbit_camera(p))}, {}))["frames"][0]["camera"];
  EXPECT_EQ(cam["kind"], "perspective");
  EXPECT_EQ(cam["constructor"], "orbit");
  const double th = p.theta_deg * std::numbers::pi / 180, ph = p.phi_deg * std::numbers::pi / 180;
  const Vector3 e{10 * std::sin(ph) * std::cos(th), 10 * std::sin(ph) * std::sin(th), 10 * std::cos(ph)};
  expect_vec3(cam["eye"], e.x, e.y, e.z, 1e-12);
  expect_vec3(cam["direction"], -e.x / 10, -e.y / 10, -e.z / 10, 1e-12);
}

TEST(JsonDevice, HiddenPiecesOnlyWhenAsked) {
  const Camera camera = lookat_camera(kLookat);
  JsonFrame f = cube_frame(camera);
  VisibleSegment h = piece(camera, {-1, -1, -1}, {1, -1, -1}, 1, 2);
  h.hidden = true;
  f.segments.insert(f.segments.begin() + 1, h);

  JsonOptions o;
  const json off = parse(to_json_text({f}, o))["frames"][0];
  ASSERT_EQ(off["segments"].size(), 4u);
  for (const json& s : off["segments"]) EXPECT_EQ(s["hidden"], false);
  EXPECT_EQ(off["segments"][1]["edge"], 5);  // the visible piece that followed the hidden one
  EXPECT_EQ(off["stats"]["segments"], 4);

  o.include_hidden = true;
  const json on = parse(to_json_text({f}, o))["frames"][0];
  ASSERT_EQ(on["segments"].size(), 5u);
  EXPECT_EQ(on["segments"][1]["hidden"], true);
  EXPECT_EQ(on["segments"][1]["object"], "wedge");
  EXPECT_EQ(on["segments"][1]["edge"], 2);
  EXPECT_EQ(on["stats"]["segments"], 4);  // visible pieces only
}

TEST(JsonDevice, IntersectionPiecesNameTheOtherObject) {
  const Camera camera = lookat_camera(kLookat);
  JsonFrame f = cube_frame(camera);
  f.segments[2].source = SegmentSource::Intersection;
  f.segments[2].object = 0;
  f.segments[2].other = 1;
  const json s = parse(to_json_text({f}, {}))["frames"][0]["segments"][2];
  EXPECT_EQ(s["object"], "cube");
  EXPECT_EQ(s["other"], "wedge");
  EXPECT_FALSE(s.contains("edge"));
}

TEST(JsonDevice, NumbersRoundTripExactly) {
  const Camera camera = lookat_camera(kLookat);
  JsonFrame f;
  f.camera = camera;
  f.object_names = {"x"};
  f.time = 1.0 / 3.0;
  VisibleSegment s;
  s.p0 = {0.1 + 0.2, 1.0 / 3.0, 1e-300};
  s.p1 = {-1.2345678901234567e200, std::nextafter(1.0, 2.0), 5e-324};
  s.s0 = {2.0 / 3.0, -0.7};
  s.s1 = {std::numeric_limits<double>::max() / 1e300, 0.1};
  f.segments = {s};
  f.plot.layout.scale = 1.0 / 7.0;
  f.plot.page.strokes = {
      stroke({{0.1 + 0.2, 2.0 / 3.0}, {std::nextafter(100.0, 0.0), 1e-7}}, 1, StrokeLayer::Visible)};
  f.plot.stats.pen_down_mm = 1.0 / 3.0;
  f.plot.stats.pen_up_median_mm = std::nextafter(5.0, 6.0);
  f.plot.stats.plot_seconds = 0.1 + 0.7;
  const json fr = parse(to_json_text({f}, {}))["frames"][0];
  EXPECT_EQ(fr["time"].get<double>(), 1.0 / 3.0);
  const json& p = fr["segments"][0]["p"];
  EXPECT_EQ(p[0][0].get<double>(), 0.1 + 0.2);
  EXPECT_EQ(p[0][1].get<double>(), 1.0 / 3.0);
  EXPECT_EQ(p[0][2].get<double>(), 1e-300);
  EXPECT_EQ(p[1][0].get<double>(), -1.2345678901234567e200);
  EXPECT_EQ(p[1][1].get<double>(), std::nextafter(1.0, 2.0));
  EXPECT_EQ(p[1][2].get<double>(), 5e-324);
  EXPECT_EQ(fr["segments"][0]["s"][0][0].get<double>(), 2.0 / 3.0);
  EXPECT_EQ(fr["segments"][0]["s"][1][0].get<double>(), s.s1.x);
  EXPECT_EQ(fr["camera"]["focal"].get<double>(), camera.focal);
  EXPECT_EQ(fr["layout"]["mm_per_unit"].get<double>(), 1.0 / 7.0);
  const json& pts = fr["strokes"][0];
  EXPECT_EQ(pts[0][0].get<double>(), 0.1 + 0.2);
  EXPECT_EQ(pts[0][1].get<double>(), 2.0 / 3.0);
  EXPECT_EQ(pts[1][0].get<double>(), std::nextafter(100.0, 0.0));
  EXPECT_EQ(pts[1][1].get<double>(), 1e-7);
  EXPECT_EQ(fr["stats"]["pen_down_mm"].get<double>(), 1.0 / 3.0);
  EXPECT_EQ(fr["stats"]["pen_up_median_mm"].get<double>(), std::nextafter(5.0, 6.0));
  EXPECT_EQ(fr["stats"]["plot_seconds"].get<double>(), 0.1 + 0.7);
}

// The error names the frame and the offending field.
void expect_error_mentions(const std::vector<JsonFrame>& frames, const JsonOptions& o,
                           const std::string& what) {
  try {
    to_json_text(frames, o);
    ADD_FAILURE() << "no error for " << what;
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("frame 3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

TEST(JsonDevice, NonFiniteNumbersAndMissingNamesAreErrors) {
  const Camera camera = lookat_camera(kLookat);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  {
    JsonFrame f = cube_frame(camera);
    f.segments[1].p0.y = nan;
    EXPECT_THROW(to_json_text({f}, {}), DeviceError);
  }
  {
    JsonFrame f = cube_frame(camera);
    f.segments[0].s1.x = inf;
    EXPECT_THROW(to_json_text({f}, {}), DeviceError);
  }
  {
    JsonFrame f = cube_frame(camera);
    f.time = inf;
    expect_error_mentions({f}, {}, "time");
  }
  {
    JsonFrame f = cube_frame(camera);  // a hidden NaN piece is checked when it is written
    f.segments[0].hidden = true;
    f.segments[0].p0.x = nan;
    JsonOptions o;
    o.include_hidden = true;
    EXPECT_THROW(to_json_text({f}, o), DeviceError);
  }
  {
    JsonFrame f = cube_frame(camera);
    f.object_names = {"cube"};  // segment 2 names object 1
    expect_error_mentions({f}, {}, "object 1");
  }
  {
    JsonFrame f = cube_frame(camera);
    f.segments[0].source = SegmentSource::Intersection;
    f.segments[0].other = 2;  // only two names
    expect_error_mentions({f}, {}, "object 2");
  }
}

TEST(JsonDevice, NonFiniteLayoutStrokesAndStatsAreErrors) {
  const Camera camera = lookat_camera(kLookat);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  {
    JsonFrame f = cube_frame(camera);
    f.plot.layout.scale = inf;
    expect_error_mentions({f}, {}, "layout");
  }
  {
    JsonFrame f = cube_frame(camera);
    f.plot.layout.picture_centre.y = nan;
    expect_error_mentions({f}, {}, "layout");
  }
  {
    JsonFrame f = cube_frame(camera);
    f.plot.page.strokes[2].points[1].y = nan;  // the second visible stroke
    expect_error_mentions({f}, {}, "stroke");
  }
  {
    JsonFrame f = cube_frame(camera);
    f.plot.page.strokes[3].points[0].x = -inf;  // a hidden stroke: checked when it is written
    JsonOptions o;
    EXPECT_EQ(parse(to_json_text({f}, o))["frames"][0]["strokes"], kVisibleStrokes);
    o.include_hidden = true;
    expect_error_mentions({f}, o, "stroke");
  }
  double PlanStats::*const fields[] = {&PlanStats::pen_down_mm, &PlanStats::pen_up_mm,
                                       &PlanStats::pen_up_mean_mm, &PlanStats::pen_up_median_mm,
                                       &PlanStats::plot_seconds};
  for (double PlanStats::*field : fields)
    for (const double bad : {nan, inf, -inf}) {
      JsonFrame f = cube_frame(camera);
      f.plot.stats.*field = bad;
      EXPECT_THROW(to_json_text({f}, {}), DeviceError);
    }
}

TEST(JsonDevice, PageComesFromTheFirstFrame) {
  const Camera camera = desens_camera({});
  std::vector<JsonFrame> frames{cube_frame(camera), cube_frame(camera)};
  const PageSpec letter{*paper_by_name("letter"), 20};
  frames[0].plot.page.width_mm = letter.paper.width_mm;
  frames[0].plot.page.height_mm = letter.paper.height_mm;
  frames[0].plot.page.margin_mm = letter.margin_mm;
  frames[0].plot.layout = fit_to_page(camera.frame, frames[0].segments, letter);
  frames[1].frame = 4;
  const json doc = parse(to_json_text(frames, {}));
  EXPECT_EQ(doc["page"]["width_mm"], 215.9);
  EXPECT_EQ(doc["page"]["height_mm"], 279.4);
  EXPECT_EQ(doc["page"]["margin_mm"], 20.0);
  // Frame [−1, 1]² on room 175.9 × 239.4: the width limits; each frame keeps its own plot's layout.
  EXPECT_DOUBLE_EQ(doc["frames"][0]["layout"]["mm_per_unit"].get<double>(), 175.9 / 2);
  EXPECT_NEAR(doc["frames"][0]["layout"]["origin_mm"][0].get<double>(), 215.9 / 2, 1e-12);
  EXPECT_NEAR(doc["frames"][0]["layout"]["origin_mm"][1].get<double>(), 279.4 / 2, 1e-12);
  EXPECT_DOUBLE_EQ(doc["frames"][1]["layout"]["mm_per_unit"].get<double>(), 93);  // 186 / 2 on A4

  const json swapped = parse(to_json_text({frames[1], frames[0]}, {}));
  EXPECT_EQ(swapped["page"]["width_mm"], 297.0);
  EXPECT_EQ(swapped["page"]["height_mm"], 210.0);
  EXPECT_EQ(swapped["page"]["margin_mm"], 12.0);
}

TEST(JsonDevice, UnusablePageIsAnError) {
  const Camera camera = lookat_camera(kLookat);
  {
    JsonFrame f = cube_frame(camera);
    f.plot.page.margin_mm = 200;  // more than half of 210
    EXPECT_THROW(to_json_text({f}, {}), DeviceError);
  }
  {
    JsonFrame f = cube_frame(camera);
    f.plot.page.width_mm = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(to_json_text({f}, {}), DeviceError);
  }
  {
    JsonFrame f = cube_frame(camera);
    f.plot.page.height_mm = std::numeric_limits<double>::infinity();
    EXPECT_THROW(to_json_text({f}, {}), DeviceError);
  }
}

TEST(JsonDevice, InvalidUtf8IsAnError) {
  const Camera camera = lookat_camera(kLookat);
  {
    JsonFrame f = cube_frame(camera);
    f.object_names[1] = "wedge\xff";
    EXPECT_THROW(to_json_text({f}, {}), DeviceError);
    JsonOptions compact;
    compact.pretty = false;
    EXPECT_THROW(to_json_text({f}, compact), DeviceError);
  }
  {
    JsonOptions o;
    o.title = "bad \xc3(";  // a lead byte without its continuation
    EXPECT_THROW(to_json_text({cube_frame(camera)}, o), DeviceError);
  }
  {
    JsonFrame f = cube_frame(camera);
    f.object_names[0] = "W\xc3\xbcrfel";  // valid UTF-8 passes through unchanged
    EXPECT_EQ(parse(to_json_text({f}, {}))["frames"][0]["segments"][0]["object"], "W\xc3\xbcrfel");
  }
}

TEST(JsonDevice, DeterministicPrettyAndCompact) {
  const Camera camera = lookat_camera(kLookat);
  std::vector<JsonFrame> frames{cube_frame(camera),
                                cube_frame(ortho_camera({.eye = {1, 2, 3}, .target = {}}))};
  frames[1].frame = 4;
  frames[1].time = 0.5;
  JsonOptions o;
  const std::string pretty = to_json_text(frames, o);
  EXPECT_EQ(pretty, to_json_text(frames, o));
  o.pretty = false;
  const std::string compact = to_json_text(frames, o);
  EXPECT_EQ(compact, to_json_text(frames, o));
  EXPECT_EQ(parse(pretty), parse(compact));
  EXPECT_EQ(compact.find('\n'), compact.size() - 1);
  EXPECT_EQ(compact.find(' '), std::string::npos);
  EXPECT_EQ(pretty.back(), '\n');
  // Schema order, one segment and one stroke per line in the pretty form.
  EXPECT_EQ(pretty.rfind("{\n  \"format\": \"hlrscript.lines/1\",\n", 0), 0u) << pretty.substr(0, 80);
  EXPECT_NE(pretty.find("\n        {\"p\":[["), std::string::npos) << pretty;
  EXPECT_NE(
      pretty.find("\n        [[20.0,30.0],[40.0,30.0],[40.0,50.0]],\n        [[40.0,50.0],[80.0,70.0]]\n"),
      std::string::npos)
      << pretty;
  EXPECT_NE(pretty.find("\"stroke_pens\": [2,3],\n"), std::string::npos) << pretty;
  EXPECT_FALSE(parse(pretty).contains("title"));
  const json doc = parse(pretty);
  ASSERT_EQ(doc["frames"].size(), 2u);
  EXPECT_EQ(doc["frames"][1]["frame"], 4);
  EXPECT_EQ(doc["frames"][1]["time"], 0.5);
}

TEST(JsonDevice, KeysInSchemaOrder) {
  JsonOptions o;
  o.title = "t";
  o.include_hidden = true;
  for (const bool pretty : {true, false}) {
    o.pretty = pretty;
    const auto doc = nlohmann::ordered_json::parse(to_json_text({cube_frame(lookat_camera(kLookat))}, o));
    using V = std::vector<std::string>;
    EXPECT_EQ(keys(doc), (V{"format", "title", "page", "frames"}));
    EXPECT_EQ(keys(doc["page"]), (V{"width_mm", "height_mm", "margin_mm", "origin", "y"}));
    const auto& fr = doc["frames"][0];
    EXPECT_EQ(keys(fr), (V{"frame", "time", "camera", "layout", "segments", "strokes", "stroke_pens",
                           "hidden_strokes", "hidden_stroke_pens", "stats"}));
    EXPECT_EQ(keys(fr["camera"]), (V{"kind", "constructor", "eye", "direction", "focal", "offset",
                                     "near_depth", "view_from_world"}));
    EXPECT_EQ(keys(fr["layout"]), (V{"mm_per_unit", "origin_mm"}));
    EXPECT_EQ(keys(fr["segments"][0]), (V{"p", "s", "object", "edge", "hidden"}));
    EXPECT_EQ(keys(fr["stats"]),
              (V{"segments", "pen_down_mm", "pen_up_mm", "pen_up_mean_mm", "pen_up_median_mm", "lifts",
                 "lift_lower_bound", "plot_seconds", "pen_order"}));
  }
}

TEST(JsonDevice, EmptyDocumentAndEmptyFrame) {
  const json none = parse(to_json_text({}, {}));
  EXPECT_EQ(none["format"], "hlrscript.lines/1");
  EXPECT_EQ(none["page"]["width_mm"], 297.0);  // the default page
  EXPECT_EQ(none["page"]["height_mm"], 210.0);
  EXPECT_EQ(none["page"]["margin_mm"], 12.0);
  EXPECT_EQ(none["frames"], json::array());

  JsonFrame f;
  f.camera = lookat_camera(kLookat);
  JsonOptions o;
  o.include_hidden = true;
  const json fr = parse(to_json_text({f}, o))["frames"][0];
  EXPECT_EQ(fr["segments"], json::array());
  EXPECT_EQ(fr["strokes"], json::array());
  EXPECT_EQ(fr["stroke_pens"], json::array());
  EXPECT_EQ(fr["hidden_strokes"], json::array());
  EXPECT_EQ(fr["hidden_stroke_pens"], json::array());
  EXPECT_EQ(fr["layout"], (json{{"mm_per_unit", 1.0}, {"origin_mm", {148.5, 105.0}}}));
  EXPECT_EQ(fr["stats"], (json{{"segments", 0},
                               {"pen_down_mm", 0.0},
                               {"pen_up_mm", 0.0},
                               {"pen_up_mean_mm", 0.0},
                               {"pen_up_median_mm", 0.0},
                               {"lifts", 0},
                               {"lift_lower_bound", 0},
                               {"plot_seconds", 0.0},
                               {"pen_order", "optimized"}}));
}

class JsonFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("hlr-json-test-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  static std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  fs::path dir_;
};

TEST_F(JsonFile, WritesTheSameTextAtomically) {
  const std::vector<JsonFrame> frames{cube_frame(lookat_camera(kLookat))};
  const fs::path target = dir_ / "out.json";
  write_json(target, frames, {});
  EXPECT_EQ(slurp(target), to_json_text(frames, {}));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator{}), 1);  // no temporary left
}

TEST_F(JsonFile, MissingDirectoryThrowsAndLeavesNothing) {
  const fs::path missing = dir_ / "no-such-dir";
  const fs::path target = missing / "out.json";
  try {
    write_json(target, {cube_frame(lookat_camera(kLookat))}, {});
    ADD_FAILURE() << "no error";
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(missing));
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(JsonFile, BadFrameKeepsThePreviousFile) {
  const fs::path target = dir_ / "out.json";
  { std::ofstream(target) << "previous"; }
  JsonFrame f = cube_frame(lookat_camera(kLookat));
  f.plot.page.strokes[0].points[1].x = std::numeric_limits<double>::quiet_NaN();
  try {
    write_json(target, {f}, {});
    ADD_FAILURE() << "no error";
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(target), "previous");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator{}), 1);
}

TEST_F(JsonFile, InvalidUtf8CreatesNoFile) {
  const fs::path target = dir_ / "out.json";
  JsonFrame f = cube_frame(lookat_camera(kLookat));
  f.object_names[0] = "\xfe\xff";
  try {
    write_json(target, {f}, {});
    ADD_FAILURE() << "no error";
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_empty(dir_));
}

}  // namespace
}  // namespace hlr
