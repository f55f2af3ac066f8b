#include "core/device/json_device.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>

#include "core/camera/desens_camera.hpp"
#include "core/camera/lookat_camera.hpp"
#include "core/camera/orbit_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "core/device/atomic_file.hpp"

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

// A unit cube's visible-looking pieces; the first two share an end point so they form one stroke.
JsonFrame cube_frame(const Camera& camera) {
  JsonFrame f;
  f.frame = 3;
  f.time = 0.25;
  f.camera = camera;
  f.object_names = {"cube", "wedge"};
  f.segments = {piece(camera, {1, 1, 1}, {-1, 1, 1}, 0, 4), piece(camera, {-1, 1, 1}, {-1, -1, 1}, 0, 5),
                piece(camera, {1, -1, 1}, {1, -1, -1}, 1, 7), piece(camera, {1, 1, -1}, {1, 1, 1}, 0, 9)};
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

// Page points computed independently of the device: the shared layout plus the 1e-6 mm grid.
std::vector<std::vector<Point2>> expected_strokes(const JsonFrame& f, const JsonOptions& o, bool hidden) {
  const PageLayout l = fit_to_page(f.camera.frame, f.segments, {o.paper, o.margin_mm});
  std::vector<std::vector<Point2>> out;
  for (const VisibleSegment& s : f.segments) {
    if (s.hidden != hidden) continue;
    const Point2 a = l.to_page_mm(s.s0), b = l.to_page_mm(s.s1);
    if (!out.empty() && std::abs(out.back().back().x - a.x) < 1e-7 &&
        std::abs(out.back().back().y - a.y) < 1e-7)
      out.back().push_back(b);
    else
      out.push_back({a, b});
  }
  return out;
}

void expect_strokes(const json& got, const std::vector<std::vector<Point2>>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    ASSERT_EQ(got[i].size(), want[i].size()) << "stroke " << i;
    for (std::size_t k = 0; k < want[i].size(); ++k) {
      EXPECT_NEAR(got[i][k][0].get<double>(), want[i][k].x, 5e-7) << i << "," << k;
      EXPECT_NEAR(got[i][k][1].get<double>(), want[i][k].y, 5e-7) << i << "," << k;
    }
  }
}

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

  const PageLayout l = fit_to_page(std::nullopt, f.segments, {o.paper, o.margin_mm});
  EXPECT_EQ(fr["layout"]["mm_per_unit"].get<double>(), l.scale);
  EXPECT_NEAR(fr["layout"]["origin_mm"][0].get<double>(), l.origin().x, 1e-9);
  EXPECT_NEAR(fr["layout"]["origin_mm"][1].get<double>(), l.origin().y, 1e-9);

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

  // Segments 0 and 1 meet head to tail; 2 and 3 stand alone.
  const auto want = expected_strokes(f, o, false);
  ASSERT_EQ(want.size(), 3u);
  expect_strokes(fr["strokes"], want);
  EXPECT_FALSE(fr.contains("hidden_strokes"));

  // Stats summed independently from the segments themselves.
  double down = 0, up = 0;
  Point2 pen{0, 0};
  for (const auto& stroke : want) {
    up += distance(pen, stroke.front());
    for (std::size_t k = 1; k < stroke.size(); ++k) down += distance(stroke[k - 1], stroke[k]);
    pen = stroke.back();
  }
  up += distance(pen, Point2{0, 0});
  double down_from_segments = 0;
  for (const VisibleSegment& s : f.segments) down_from_segments += l.scale * distance(s.s0, s.s1);
  const json& st = fr["stats"];
  EXPECT_EQ(st["segments"], 4);
  EXPECT_NEAR(st["pen_down_mm"].get<double>(), down, 1e-5);
  EXPECT_NEAR(st["pen_down_mm"].get<double>(), down_from_segments, 1e-5);
  EXPECT_NEAR(st["pen_up_mm"].get<double>(), up, 1e-5);
  EXPECT_EQ(st["lifts"], 3);
  EXPECT_EQ(st.size(), 4u);
}

TEST(JsonDevice, StrokesFitTheCameraFrameAndTheMargins) {
  LookatParameters p = kLookat;
  p.aspect = 1.5;
  const Camera camera = lookat_camera(p);
  const JsonFrame f = cube_frame(camera);
  const JsonOptions o;
  const json fr = parse(to_json_text({f}, o))["frames"][0];
  EXPECT_EQ(fr["camera"]["frame"], json::array({-1.5, -1.0, 1.5, 1.0}));
  // Frame 3 × 2 on room 273 × 186: scale min(91, 93) = 91.
  EXPECT_DOUBLE_EQ(fr["layout"]["mm_per_unit"].get<double>(), 91);
  EXPECT_NEAR(fr["layout"]["origin_mm"][0].get<double>(), 148.5, 1e-12);
  EXPECT_NEAR(fr["layout"]["origin_mm"][1].get<double>(), 105, 1e-12);
  expect_strokes(fr["strokes"], expected_strokes(f, o, false));
  for (const json& stroke : fr["strokes"])
    for (const json& pt : stroke) {
      EXPECT_GE(pt[0].get<double>(), 12);
      EXPECT_LE(pt[0].get<double>(), 285);
      EXPECT_GE(pt[1].get<double>(), 12);
      EXPECT_LE(pt[1].get<double>(), 198);
    }
}

// Only an end meeting the next start joins: reversed or non-consecutive matches stay separate strokes.
TEST(JsonDevice, JoinsOnlyHeadToTailConsecutivePieces) {
  const Camera camera = ortho_camera({.eye = {0, 0, 10}, .target = {0, 0, 0}, .up = {0, 1, 0}, .height = 2});
  JsonFrame f;
  f.camera = camera;
  f.object_names = {"a"};
  f.segments = {piece(camera, {0, 0, 0}, {1, 0, 0}),  piece(camera, {1, 0, 0}, {1, 1, 0}),
                piece(camera, {0, 1, 0}, {1, 1, 0}),     // ends where the last one ended: reversed, no join
                piece(camera, {5, 5, 0}, {6, 5, 0}),     // elsewhere
                piece(camera, {0, 0, 0}, {-1, 0, 0}),    // starts where stroke 0 started: not consecutive
                piece(camera, {-1, 0, 0}, {-1, 0, 0})};  // zero length: left out
  const JsonOptions o;
  const json fr = parse(to_json_text({f}, o))["frames"][0];
  const json& strokes = fr["strokes"];
  ASSERT_EQ(strokes.size(), 4u);
  EXPECT_EQ(strokes[0].size(), 3u);
  EXPECT_EQ(strokes[1].size(), 2u);
  EXPECT_EQ(strokes[2].size(), 2u);
  EXPECT_EQ(strokes[3].size(), 2u);
  EXPECT_EQ(fr["stats"]["segments"], 6);
  EXPECT_EQ(fr["stats"]["lifts"], 4);
  EXPECT_EQ(fr["segments"].size(), 6u);
  // The frame-less extent is x ∈ [−1, 6], y ∈ [0, 5]: scale min(273/7, 186/5) = 37.2.
  EXPECT_DOUBLE_EQ(fr["layout"]["mm_per_unit"].get<double>(), 37.2);
  const double s = 37.2;
  const double x0 = 148.5 - 2.5 * s, y0 = 105 + 2.5 * s;  // picture (0, 0)
  EXPECT_NEAR(strokes[0][0][0].get<double>(), x0, 1e-6);
  EXPECT_NEAR(strokes[0][0][1].get<double>(), y0, 1e-6);
  EXPECT_NEAR(strokes[0][2][0].get<double>(), x0 + s, 1e-6);
  EXPECT_NEAR(strokes[0][2][1].get<double>(), y0 - s, 1e-6);  // picture up is page up
  // Pen-down: 1 + 1 + 1 + 1 + 1 units; pen-up: origin → (0,0), (1,1) → (0,1), (1,1) → (5,5),
  // (6,5) → (0,0), (−1,0) → page origin.
  EXPECT_NEAR(fr["stats"]["pen_down_mm"].get<double>(), 5 * s, 1e-5);
  const double up =
      std::hypot(x0, y0) + s + s * std::hypot(4, 4) + s * std::hypot(6, 5) + std::hypot(x0 - s, y0);
  EXPECT_NEAR(fr["stats"]["pen_up_mm"].get<double>(), up, 1e-5);
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
  f.segments.insert(f.segments.begin() + 1, h);  // between the two joinable visible pieces

  JsonOptions o;
  const json off = parse(to_json_text({f}, o))["frames"][0];
  EXPECT_EQ(off["segments"].size(), 4u);
  for (const json& s : off["segments"]) EXPECT_EQ(s["hidden"], false);
  EXPECT_FALSE(off.contains("hidden_strokes"));
  EXPECT_EQ(off["stats"]["segments"], 4);
  EXPECT_EQ(off["strokes"].size(), 3u);  // the hidden piece does not break the visible stroke

  o.include_hidden = true;
  const json on = parse(to_json_text({f}, o))["frames"][0];
  ASSERT_EQ(on["segments"].size(), 5u);
  EXPECT_EQ(on["segments"][1]["hidden"], true);
  EXPECT_EQ(on["segments"][1]["object"], "wedge");
  EXPECT_EQ(on["stats"]["segments"], 4);  // stats describe the visible strokes
  EXPECT_EQ(on["strokes"], off["strokes"]);
  expect_strokes(on["hidden_strokes"], expected_strokes(f, o, true));
  EXPECT_EQ(on["hidden_strokes"].size(), 1u);
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
    try {
      to_json_text({f}, {});
      ADD_FAILURE() << "no error";
    } catch (const DeviceError& e) {
      EXPECT_NE(std::string(e.what()).find("frame 3"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("time"), std::string::npos) << e.what();
    }
  }
  {
    JsonFrame f = cube_frame(camera);  // a hidden NaN piece is still checked only when it is written
    f.segments[0].hidden = true;
    f.segments[0].p0.x = nan;
    f.segments[0].s0.x = 0;
    JsonOptions o;
    o.include_hidden = true;
    EXPECT_THROW(to_json_text({f}, o), DeviceError);
  }
  {
    JsonFrame f = cube_frame(camera);
    f.object_names = {"cube"};  // segment 2 names object 1
    EXPECT_THROW(to_json_text({f}, {}), DeviceError);
  }
  {
    JsonOptions o;
    o.margin_mm = 200;
    EXPECT_THROW(to_json_text({cube_frame(camera)}, o), DeviceError);
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
  // Schema order, and one segment per line in the pretty form.
  EXPECT_EQ(pretty.rfind("{\n  \"format\": \"hlrscript.lines/1\",\n", 0), 0u) << pretty.substr(0, 80);
  EXPECT_NE(pretty.find("\n        {\"p\":[["), std::string::npos) << pretty;
  EXPECT_LT(pretty.find("\"camera\""), pretty.find("\"segments\""));
  EXPECT_LT(pretty.find("\"segments\""), pretty.find("\"strokes\""));
  EXPECT_LT(pretty.find("\"strokes\""), pretty.find("\"stats\""));
  EXPECT_FALSE(parse(pretty).contains("title"));
  const json doc = parse(pretty);
  ASSERT_EQ(doc["frames"].size(), 2u);
  EXPECT_EQ(doc["frames"][1]["frame"], 4);
  EXPECT_EQ(doc["frames"][1]["time"], 0.5);
}

TEST(JsonDevice, EmptyDocumentAndEmptyFrame) {
  const json none = parse(to_json_text({}, {}));
  EXPECT_EQ(none["format"], "hlrscript.lines/1");
  EXPECT_EQ(none["frames"], json::array());

  JsonFrame f;
  f.camera = lookat_camera(kLookat);
  const json fr = parse(to_json_text({f}, {}))["frames"][0];
  EXPECT_EQ(fr["segments"], json::array());
  EXPECT_EQ(fr["strokes"], json::array());
  EXPECT_EQ(fr["stats"], (json{{"segments", 0}, {"pen_down_mm", 0.0}, {"pen_up_mm", 0.0}, {"lifts", 0}}));
}

TEST(JsonDevice, PaperAndMarginComeFromTheOptions) {
  JsonOptions o;
  o.paper = *paper_by_name("letter");
  o.margin_mm = 20;
  const Camera camera = desens_camera({});
  const json doc = parse(to_json_text({cube_frame(camera)}, o));
  EXPECT_EQ(doc["page"]["width_mm"], 215.9);
  EXPECT_EQ(doc["page"]["height_mm"], 279.4);
  EXPECT_EQ(doc["page"]["margin_mm"], 20.0);
  // Frame [−1, 1]² on room 175.9 × 239.4: the width limits.
  EXPECT_DOUBLE_EQ(doc["frames"][0]["layout"]["mm_per_unit"].get<double>(), 175.9 / 2);
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
  f.segments[0].p1.z = std::numeric_limits<double>::quiet_NaN();
  try {
    write_json(target, {f}, {});
    ADD_FAILURE() << "no error";
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(target), "previous");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator{}), 1);
}

}  // namespace
}  // namespace hlr
