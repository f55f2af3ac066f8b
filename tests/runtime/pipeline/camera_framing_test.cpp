// The camera frames the picture (LANGUAGE_SPEC "Page"): the page scale and origin follow from the camera
// and the paper only. The expected millimetres are worked out here by hand from that rule — the drawing
// area is the paper minus the margins, the camera's window spans its shorter side — and a pinhole
// projection written out in the test, never read back from the program.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "tests/runtime/cli_run.hpp"
#include "tests/runtime/runtime_test_support.hpp"
#include "tests/support/temp_dir.hpp"

namespace hlr::runtime {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string current_test_name() { return test::scratch_name("framing"); }

// Every frame of the script as JSON.
json render_frames(const hlr::test::TempDir& dir, const std::string& text,
                   std::vector<std::string> extra = {}) {
  const std::string script = dir.write("scene.hls", text).string();
  const fs::path out = dir.path() / "scene.json";
  std::vector<std::string> args{script, "-o", out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const test::CliResult r = test::run(args);
  EXPECT_EQ(r.code, 0) << r.err;
  if (r.code != 0) return json::array();
  return json::parse(test::read_text(out))["frames"];
}

struct Bounds {
  double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300;
  int points = 0;
};

Bounds stroke_bounds(const json& frame) {
  Bounds b;
  for (const json& stroke : frame["strokes"])
    for (const json& p : stroke) {
      const double x = p[0], y = p[1];
      b.xmin = std::min(b.xmin, x);
      b.xmax = std::max(b.xmax, x);
      b.ymin = std::min(b.ymin, y);
      b.ymax = std::max(b.ymax, y);
      ++b.points;
    }
  return b;
}

// A4 landscape with the default 12 mm margins: a 273 × 186 mm drawing area centred at (148.5, 105).
constexpr double kRoomW = 297 - 24, kRoomH = 210 - 24, kCentreX = 148.5, kCentreY = 105;

// The turntable: a perspective camera orbiting a 4 × 1 × 2 box. The page scale is one fov across
// the drawing area's shorter side in every frame — 186 mm for 2 picture units — and the view's axis lands
// on the page centre.
TEST(CameraFraming, ATurntableKeepsItsScale) {
  const hlr::test::TempDir dir(current_test_name());
  const json frames =
      render_frames(dir,
                    "animate frames 8\n"
                    "draw box(4, 1, 2) at translate(-2, -0.5, 0)\n"
                    "let a = 360 * frame / 8\n"
                    "camera spin = lookat(eye: (9 * cos(a), 9 * sin(a), 4), target: (0, 0, 1), "
                    "fov: 40)\n");
  ASSERT_EQ(frames.size(), 8U);
  for (const json& f : frames) {
    SCOPED_TRACE(f["frame"].dump());
    EXPECT_NEAR(f["layout"]["mm_per_unit"].get<double>(), kRoomH / 2, 1e-9);
    EXPECT_NEAR(f["layout"]["origin_mm"][0].get<double>(), kCentreX, 1e-9);
    EXPECT_NEAR(f["layout"]["origin_mm"][1].get<double>(), kCentreY, 1e-9);
    const json& frame = f["camera"]["frame"];
    EXPECT_NEAR(frame[2].get<double>(), kRoomW / kRoomH, 1e-12);
    EXPECT_NEAR(frame[3].get<double>(), 1, 1e-12);
  }
}

// A small second object does not move or rescale the first: the strokes of the box are where they were.
TEST(CameraFraming, ASecondObjectDoesNotRescaleTheFirst) {
  const hlr::test::TempDir dir(current_test_name());
  const std::string camera = "camera main = lookat(eye: (8, -9, 6), target: (0, 0, 1), fov: 40)\n";
  const json alone = render_frames(dir, "draw box(4, 1, 2)\n" + camera);
  const json with = render_frames(dir, "draw box(4, 1, 2)\ndraw cube(0.3) at translate(-3, 2, 0)\n" + camera);
  ASSERT_EQ(alone.size(), 1U);
  ASSERT_EQ(with.size(), 1U);
  EXPECT_EQ(alone[0]["layout"], with[0]["layout"]);
}

// The projection written out: page mm of world point p seen by lookat(eye, target, up z, fov) on A4
// landscape — right = forward × up, picture = focal·(right·v, up·v)/(forward·v), 93 mm per unit.
std::array<double, 2> expected_page_mm(std::array<double, 3> eye, std::array<double, 3> target, double fov,
                                       std::array<double, 3> p) {
  auto sub = [](auto a, auto b) { return std::array<double, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
  auto dot = [](auto a, auto b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto unit = [&](auto a) {
    const double n = std::sqrt(dot(a, a));
    return std::array<double, 3>{a[0] / n, a[1] / n, a[2] / n};
  };
  auto cross = [](auto a, auto b) {
    return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                 a[0] * b[1] - a[1] * b[0]};
  };
  const auto f = unit(sub(target, eye));
  const auto r = unit(cross(f, std::array<double, 3>{0, 0, 1}));
  const auto u = cross(r, f);
  const auto v = sub(p, eye);
  const double focal = 1 / std::tan(fov * std::numbers::pi / 360);
  const double x = focal * dot(r, v) / dot(f, v), y = focal * dot(u, v) / dot(f, v);
  return {kCentreX + kRoomH / 2 * x, kCentreY - kRoomH / 2 * y};
}

// The walk-through: a street of boxes, some beside and behind the eye. The drawing is what the
// camera sees at its own scale — not shrunk to a dot by lines running out to the near plane — and cut at
// the picture frame.
TEST(CameraFraming, AWalkThroughCameraDrawsWhatItSees) {
  const hlr::test::TempDir dir(current_test_name());
  const json frames = render_frames(dir,
                                    "for i in 0..8 {\n"
                                    "  draw box(6, 4, 5 + i) at translate(8 * i - 8, 5, 0)\n"
                                    "  draw box(6, 4, 4 + i) at translate(8 * i - 8, -9, 0)\n"
                                    "}\n"
                                    "camera walk = lookat(eye: (8, 0, 1.7), target: (30, 0, 2), fov: 60)\n");
  ASSERT_EQ(frames.size(), 1U);
  const json& f = frames[0];
  EXPECT_NEAR(f["layout"]["mm_per_unit"].get<double>(), kRoomH / 2, 1e-9);
  const Bounds b = stroke_bounds(f);
  ASSERT_GT(b.points, 20);
  // Everything inside the frame: the drawing area, the frame's aspect being the area's.
  EXPECT_GE(b.xmin, 12 - 1e-6);
  EXPECT_LE(b.xmax, 297 - 12 + 1e-6);
  EXPECT_GE(b.ymin, 12 - 1e-6);
  EXPECT_LE(b.ymax, 210 - 12 + 1e-6);
  // Boxes beside the eye run out of the frame on both sides: the drawing reaches its left and right edges.
  EXPECT_NEAR(b.xmin, 12, 0.05);
  EXPECT_NEAR(b.xmax, 285, 0.05);
  // A visible corner straight ahead lands where the pinhole puts it: the near bottom corner of the box
  // at x = 32, the street's right side (y = -5), ground level.
  const auto corner = expected_page_mm({8, 0, 1.7}, {30, 0, 2}, 60, {32, -5, 0});
  bool found = false;
  for (const json& stroke : f["strokes"])
    for (const json& p : stroke)
      found = found || (std::abs(p[0].get<double>() - corner[0]) < 0.05 &&
                        std::abs(p[1].get<double>() - corner[1]) < 0.05);
  EXPECT_TRUE(found) << "no stroke point at (" << corner[0] << ", " << corner[1] << ") mm";
}

// ortho(height: H): H world units across the drawing area's shorter side, on portrait paper its width.
TEST(CameraFraming, OrthoHeightSpansTheShorterSide) {
  const hlr::test::TempDir dir(current_test_name());
  const std::string scene =
      "draw box(min: (-1, -1, -1), max: (1, 1, 1))\n"
      "camera front = ortho(eye: (0, -10, 0), target: (0, 0, 0), height: 4)\n";
  for (const bool portrait : {false, true}) {
    SCOPED_TRACE(portrait ? "portrait" : "landscape");
    const json frames = render_frames(dir, scene, {portrait ? "--portrait" : "--landscape"});
    ASSERT_EQ(frames.size(), 1U);
    const Bounds b = stroke_bounds(frames[0]);
    const double shorter = portrait ? 210 - 24 : kRoomH;  // portrait A4: 186 × 273 mm
    const double mm_per_world = shorter / 4;
    EXPECT_NEAR(b.xmax - b.xmin, 2 * mm_per_world, 0.05);
    EXPECT_NEAR(b.ymax - b.ymin, 2 * mm_per_world, 0.05);
    const double cx = portrait ? 105 : kCentreX, cy = portrait ? 148.5 : kCentreY;
    EXPECT_NEAR(0.5 * (b.xmin + b.xmax), cx, 0.05);
    EXPECT_NEAR(0.5 * (b.ymin + b.ymax), cy, 0.05);
  }
}

// Albers' orbit: its pictures are in screen units, and 180 of them span the shorter side.
TEST(CameraFraming, OrbitFramesAlbersScreen) {
  const hlr::test::TempDir dir(current_test_name());
  const json frames = render_frames(dir,
                                    "draw box(min: (-10, -10, -10), max: (10, 10, 10))\n"
                                    "camera a = orbit(theta: 0, phi: 90, rho: 425, d: 1549)\n");
  ASSERT_EQ(frames.size(), 1U);
  EXPECT_NEAR(frames[0]["layout"]["mm_per_unit"].get<double>(), kRoomH / 180, 1e-9);
  // From +x, level: the face x = 10 is a square 1549·20/415 screen units across, centred.
  const Bounds b = stroke_bounds(frames[0]);
  EXPECT_NEAR(b.xmax - b.xmin, 1549.0 * 20 / 415 * kRoomH / 180, 0.05);
}

// fit: "drawing" (and --fit drawing) fits what is drawn, as before cameras framed the page: a big and a
// small box fill the same drawing area at different scales. --fit camera overrides the script.
TEST(CameraFraming, FittingTheDrawingIsAnExplicitChoice) {
  const hlr::test::TempDir dir(current_test_name());
  const std::string camera = "camera main = lookat(eye: (8, -9, 6), target: (0, 0, 1), fov: 40)\n";
  const json big = render_frames(dir, "paper A4 (fit: \"drawing\")\ndraw box(4, 1, 2)\n" + camera);
  const json small = render_frames(dir, "paper A4 (fit: \"drawing\")\ndraw box(1, 1, 1)\n" + camera);
  ASSERT_EQ(big.size(), 1U);
  ASSERT_EQ(small.size(), 1U);
  EXPECT_GT(small[0]["layout"]["mm_per_unit"].get<double>(),
            1.5 * big[0]["layout"]["mm_per_unit"].get<double>());
  for (const json* f : {&big, &small}) {
    const Bounds b = stroke_bounds((*f)[0]);
    // Fitted: the drawing touches the margins on one side or the other.
    EXPECT_TRUE(std::abs(b.xmax - b.xmin - kRoomW) < 0.05 || std::abs(b.ymax - b.ymin - kRoomH) < 0.05);
  }
  const json framed =
      render_frames(dir, "paper A4 (fit: \"drawing\")\ndraw box(1, 1, 1)\n" + camera, {"--fit", "camera"});
  ASSERT_EQ(framed.size(), 1U);
  EXPECT_NEAR(framed[0]["layout"]["mm_per_unit"].get<double>(), kRoomH / 2, 1e-9);
  const json cli = render_frames(dir, "draw box(1, 1, 1)\n" + camera, {"--fit", "drawing"});
  ASSERT_EQ(cli.size(), 1U);
  EXPECT_EQ(cli[0]["layout"], small[0]["layout"]);
}

// With a scale the camera's window is the whole drawing area at that scale, centred on the view's axis,
// and what lies beyond it is cut at the margins.
TEST(CameraFraming, AScaleFramesTheDrawingAreaAtThatScale) {
  const hlr::test::TempDir dir(current_test_name());
  const json frames = render_frames(dir,
                                    "draw box(min: (-3, -0.8, -1), max: (3, 0.8, 1))\n"
                                    "camera top = ortho(eye: (0, 0, 10), target: (0, 0, 0), up: (0, 1, 0), "
                                    "height: 2)\n",
                                    {"--scale", "100"});
  ASSERT_EQ(frames.size(), 1U);
  // height 2: one picture unit is one world unit; 6 units at 100 mm would be 600 mm, cut at 273; the
  // 1.6 units across are 160 mm, whole.
  const Bounds b = stroke_bounds(frames[0]);
  EXPECT_NEAR(b.xmin, 12, 0.05);
  EXPECT_NEAR(b.xmax, 285, 0.05);
  EXPECT_NEAR(b.ymax - b.ymin, 160, 0.05);
  EXPECT_NEAR(0.5 * (b.ymin + b.ymax), kCentreY, 0.05);
}

// A bad fit: is refused at the option with the choices.
TEST(CameraFraming, AnUnknownFitIsRefusedAtTheOption) {
  const hlr::test::TempDir dir(current_test_name());
  const std::string script = dir.write("bad.hls",
                                       "paper A4 (fit: \"page\")\ndraw cube(1)\ncamera c = lookat(eye: (3, "
                                       "-4, 2), target: (0, 0, 0))\n")
                                 .string();
  const test::CliResult r = test::run({script, "-o", (dir.path() / "x.json").string()});
  EXPECT_EQ(r.code, 65);
  EXPECT_NE(r.err.find("bad.hls:1:11"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\"camera\" or \"drawing\""), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "x.json"));
  const test::CliResult cli = test::run({script, "--fit", "page"});
  EXPECT_NE(cli.code, 0);
  EXPECT_NE(cli.err.find("--fit takes 'camera' or 'drawing'"), std::string::npos) << cli.err;
}

// A view that draws nonsense though the script is valid gets one warning, at the camera, naming the
// frames: the eye inside a closed solid; a near plane that cuts away most of what is in front of the eye.
TEST(CameraFraming, ViewsThatDrawNonsenseAreWarnedOnce) {
  const hlr::test::TempDir dir(current_test_name());
  const std::string inside = dir.write("inside.hls",
                                       "animate frames 4\n"
                                       "draw box(10, 10, 10) at translate(-5, -5, -5)\n"
                                       "camera c = lookat(eye: (frame, 0, 0), target: (5, 1, 0))\n")
                                 .string();
  const test::CliResult r = test::run({inside, "-o", (dir.path() / "inside.json").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(
      r.err.find("inside.hls:3:1: warning: camera 'c': the eye is inside the closed solid 'box', so the "
                 "drawing shows it from inside (frames 0 to 3)"),
      std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("warning", r.err.find("warning") + 1), std::string::npos) << r.err;  // once
  const std::string near = dir.write("near.hls",
                                     "draw box(10, 10, 10)\n"
                                     "camera c = lookat(eye: (-20, 5, 5), target: (0, 5, 5), near: 35)\n")
                               .string();
  const test::CliResult n = test::run({near, "-o", (dir.path() / "near.json").string()});
  ASSERT_EQ(n.code, 0) << n.err;
  EXPECT_NE(n.err.find("near.hls:2:1: warning: camera 'c': the near plane (depth 35) cuts away most of what "
                       "lies in front of the eye (8 of 8 vertices) (frame 0)"),
            std::string::npos)
      << n.err;
}

}  // namespace
}  // namespace hlr::runtime
