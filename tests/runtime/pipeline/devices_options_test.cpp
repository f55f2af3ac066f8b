// The device options end to end through run_cli (tracker issue 4): PDF page sizes, pages and title as
// poppler's pdfinfo reads them, PNG pixel sizes as cairo reads them, --scale against a camera worked by
// hand, --stats, and the errors (exit status, message, nothing written). Every example on every plotter,
// and the devices against each other: devices_test.cpp.
#include <cairo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "core/device/plotters/hpgl_profile.hpp"
#include "runtime/cli/cli.hpp"
#include "tests/runtime/cli_run.hpp"
#include "tests/runtime/runtime_test_support.hpp"
#include "tests/support/hpgl_reader.hpp"

namespace hlr::runtime {
namespace {

namespace fs = std::filesystem;

using Result = test::CliResult;
using test::read_text;
using test::run;

std::string current_test_name() { return test::scratch_name("devopts"); }

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The files in `dir` other than the script(s): what a failed run must not leave.
std::vector<std::string> written_files(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() != ".hls") out.push_back(e.path().filename().string());
  return out;
}

const char* kCube =
    "draw cube(2) at rotate(z: 30)\n"
    "camera main = lookat(eye: (6, -8, 5), target: (0, 0, 0))\n";

const char* kThreeFrames =
    "animate frames 3\n"
    "draw cube(2) at rotate(z: 30 * frame)\n"
    "camera main = lookat(eye: (6, -8, 5), target: (0, 0, 0))\n";

// ---- PDF: what poppler reads ----

bool have(const char* tool) {
  return std::system(("command -v " + std::string(tool) + " >/dev/null 2>&1").c_str()) == 0;
}

std::string pdfinfo(const fs::path& pdf) {
  std::string out;
  FILE* p = ::popen(("pdfinfo '" + pdf.string() + "' 2>&1").c_str(), "r");
  if (!p) return out;
  std::array<char, 512> buf;
  while (std::fgets(buf.data(), buf.size(), p)) out += buf.data();
  ::pclose(p);
  return out;
}

// "Page size:  W x H pts" → (W, H).
std::pair<double, double> page_size_pts(const std::string& info) {
  std::smatch m;
  if (!std::regex_search(info, m, std::regex(R"(Page size:\s+([0-9.]+) x ([0-9.]+) pts)"))) return {0, 0};
  return {std::stod(m[1]), std::stod(m[2])};
}

TEST(DevicesPdf, PageSizesPagesAndTitle) {
  ASSERT_TRUE(have("pdfinfo")) << "pdfinfo (poppler-utils) is not installed: run scripts/setup.sh";
  const test::TempDir dir(current_test_name());
  const std::string cube = dir.write("cube.hls", kCube).string();
  const std::string anim = dir.write("anim.hls", kThreeFrames).string();
  // 1 mm = 72 / 25.4 pt. A3 portrait: 297 × 420 mm.
  const fs::path a3 = dir.path() / "a3.pdf";
  ASSERT_EQ(run({cube, "-o", a3.string(), "--paper", "A3", "--portrait"}).code, 0);
  const std::string a3_info = pdfinfo(a3);
  const auto [w3, h3] = page_size_pts(a3_info);
  EXPECT_NEAR(w3, 841.89, 0.01) << a3_info;
  EXPECT_NEAR(h3, 1190.55, 0.01) << a3_info;
  EXPECT_TRUE(contains(a3_info, "Pages:           1\n")) << a3_info;
  EXPECT_TRUE(contains(a3_info, "Title:           " + cube + "\n")) << a3_info;
  EXPECT_TRUE(contains(a3_info, "Creator:         hlrscript\n")) << a3_info;
  // A custom size, landscape by default: 300 × 200 mm.
  const fs::path custom = dir.path() / "custom.pdf";
  ASSERT_EQ(run({cube, "-o", custom.string(), "--paper", "300x200"}).code, 0);
  const auto [wc, hc] = page_size_pts(pdfinfo(custom));
  EXPECT_NEAR(wc, 850.39, 0.01);
  EXPECT_NEAR(hc, 566.93, 0.01);
  // One page per frame; the title is the script as named on the command line.
  const fs::path pages = dir.path() / "anim.pdf";
  ASSERT_EQ(run({anim, "-o", pages.string()}).code, 0);
  const std::string info = pdfinfo(pages);
  EXPECT_TRUE(contains(info, "Pages:           3\n")) << info;
  EXPECT_TRUE(contains(info, "Title:           " + anim + "\n")) << info;
  const auto [wa, ha] = page_size_pts(info);  // A4 landscape, the default paper
  EXPECT_NEAR(wa, 841.89, 0.01);
  EXPECT_NEAR(ha, 595.28, 0.01);
}

// ---- PNG: what cairo reads back ----

std::pair<int, int> png_size(const fs::path& png) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(png.c_str());
  std::pair<int, int> size{-1, -1};
  if (cairo_surface_status(s) == CAIRO_STATUS_SUCCESS)
    size = {cairo_image_surface_get_width(s), cairo_image_surface_get_height(s)};
  cairo_surface_destroy(s);
  return size;
}

TEST(DevicesPng, PixelSizeFollowsPaperAndDpi) {
  const test::TempDir dir(current_test_name());
  const std::string cube = dir.write("cube.hls", kCube).string();
  // A4 landscape at 100 dpi: 297 × 100 / 25.4 = 1169.3, 210 × 100 / 25.4 = 826.8 → 1169 × 827.
  const fs::path a4 = dir.path() / "a4.png";
  ASSERT_EQ(run({cube, "-o", a4.string(), "--dpi", "100"}).code, 0);
  EXPECT_EQ(png_size(a4), std::make_pair(1169, 827));
  // A5 portrait at 72 dpi: 148 × 72 / 25.4 = 419.5 → 420 (round half up), 210 × 72 / 25.4 = 595.3 → 595.
  const fs::path a5 = dir.path() / "a5.png";
  ASSERT_EQ(run({cube, "-o", a5.string(), "--dpi", "72", "--paper", "A5", "--portrait"}).code, 0);
  EXPECT_EQ(png_size(a5), std::make_pair(420, 595));
}

// ---- --scale: 1 picture unit = N mm, centred ----

// ortho(height: h) maps h world units to the picture's 2 units (focal 2/h); with height 2 one world unit
// is one picture unit, so at --scale 5 the 10-unit cube seen face on is a 50 mm square, centred on the
// A4 landscape page (148.5, 105). Turned 45° about z and seen from the side (along +y, from y = −40), it
// shows two faces: its horizontal diagonal, 10·√2 = 14.14 units (70.7 mm), wide and 10 units high.
TEST(DevicesScale, StrokesSpanTheScaledCube) {
  const test::TempDir dir(current_test_name());
  struct Case {
    const char* placement;
    const char* eye;
    const char* up;
    double width_mm, height_mm;
  };
  const Case cases[] = {
      {"", "(0, 0, 40)", "(0, 1, 0)", 50, 50},
      {" at rotate(z: 45)", "(0, -40, 0)", "(0, 0, 1)", 50 * std::sqrt(2.0), 50},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.placement);
    const std::string script =
        dir.write("cube.hls", std::string("draw cube(10)") + c.placement + "\ncamera main = ortho(eye: " +
                                  c.eye + ", target: (0, 0, 0), up: " + c.up + ", height: 2)\n")
            .string();
    const fs::path json = dir.path() / "cube.json";
    const Result r = run({script, "-o", json.string(), "--scale", "5"});
    ASSERT_EQ(r.code, 0) << r.err;
    const nlohmann::json doc = nlohmann::json::parse(read_text(json));
    const nlohmann::json& f = doc["frames"][0];
    EXPECT_EQ(f["layout"]["mm_per_unit"], 5.0);
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
    for (const auto& stroke : f["strokes"])
      for (const auto& p : stroke) {
        x0 = std::min(x0, p[0].get<double>()), x1 = std::max(x1, p[0].get<double>());
        y0 = std::min(y0, p[1].get<double>()), y1 = std::max(y1, p[1].get<double>());
      }
    EXPECT_NEAR(x1 - x0, c.width_mm, 0.03);  // the 0.025 mm grid
    EXPECT_NEAR(y1 - y0, c.height_mm, 0.03);
    EXPECT_NEAR(0.5 * (x0 + x1), 148.5, 0.03);
    EXPECT_NEAR(0.5 * (y0 + y1), 105, 0.03);
  }
}

// ---- errors: exit status, message, and nothing written ----

TEST(DevicesErrors, UnknownPlotterOnTheCommandLine) {
  const test::TempDir dir(current_test_name());
  const std::string cube = dir.write("cube.hls", kCube).string();
  const Result r = run({cube, "-o", (dir.path() / "x.hpgl").string(), "--plotter", "nosuch"});
  EXPECT_EQ(r.code, 64);
  EXPECT_TRUE(contains(r.err, "--plotter: unknown plotter 'nosuch'")) << r.err;
  EXPECT_TRUE(contains(r.err, "hp7475a, hp7440a, hp7550, roland-dxy, generic")) << r.err;
  EXPECT_EQ(written_files(dir.path()), std::vector<std::string>{});
}

TEST(DevicesErrors, UnknownPlotterInTheScriptIsLocatedAtItsName) {
  const test::TempDir dir(current_test_name());
  const std::string out = (dir.path() / "x.hpgl").string();
  const std::string first_line = "output \"" + out + "\" plotter nosuch";
  const std::string script = dir.write("p.hls", first_line + "\n" + kCube).string();
  const Result r = run({script, "--out-dir", dir.path().string()});
  EXPECT_EQ(r.code, 65);
  // The column of 'nosuch' (1-based): after `output "PATH" plotter `.
  const std::string at = script + ":1:" + std::to_string(first_line.find("nosuch") + 1) + ": error: ";
  EXPECT_TRUE(contains(r.err, at + "unknown plotter 'nosuch'")) << r.err;
  EXPECT_EQ(written_files(dir.path()), std::vector<std::string>{});
}

TEST(DevicesErrors, UsageMistakes) {
  const test::TempDir dir(current_test_name());
  const std::string anim = dir.write("anim.hls", kThreeFrames).string();
  const Result paper = run({anim, "-o", (dir.path() / "x.pdf").string(), "--paper", "A9"});
  EXPECT_EQ(paper.code, 64);
  EXPECT_TRUE(contains(paper.err, "--paper A9: unknown paper size")) << paper.err;
  // Three frames, one SVG file: refused before anything is rendered.
  const Result svg = run({anim, "-o", (dir.path() / "x.svg").string()});
  EXPECT_EQ(svg.code, 64);
  EXPECT_TRUE(contains(svg.err, "{frame:03}")) << svg.err;
  // --dpi is limited to 10..2400 on the command line.
  const Result dpi = run({anim, "-o", (dir.path() / "x.png").string(), "--dpi", "5000"});
  EXPECT_EQ(dpi.code, 64);
  EXPECT_TRUE(contains(dpi.err, "--dpi 5000: expected a number from 10 to 2400")) << dpi.err;
  EXPECT_EQ(written_files(dir.path()), std::vector<std::string>{});
}

// A profile refuses paper it does not take, and says which sizes it takes.
TEST(DevicesErrors, PaperThePlotterDoesNotTake) {
  const test::TempDir dir(current_test_name());
  const std::string cube = dir.write("cube.hls", kCube).string();
  const Result r =
      run({cube, "-o", (dir.path() / "x.hpgl").string(), "--plotter", "hp7440a", "--paper", "A3"});
  EXPECT_EQ(r.code, 73);
  EXPECT_TRUE(contains(r.err, "plotter 'hp7440a' takes no 420 × 297 mm page")) << r.err;
  EXPECT_TRUE(contains(r.err, "A4 (297 × 210 mm), Letter (279.4 × 215.9 mm)")) << r.err;
  EXPECT_EQ(written_files(dir.path()), std::vector<std::string>{});
}

TEST(DevicesErrors, PenBeyondThePlottersPens) {
  const test::TempDir dir(current_test_name());
  const std::string script =
      dir.write("p7.hls", "draw cube(2) pen 7\ncamera main = lookat(eye: (6, -8, 5), target: (0, 0, 0))\n")
          .string();
  const fs::path hpgl = dir.path() / "x.hpgl";
  const Result r = run({script, "-o", hpgl.string(), "--plotter", "hp7475a"});
  EXPECT_EQ(r.code, 73);
  EXPECT_TRUE(contains(r.err, "uses pen 7 but plotter 'hp7475a' has pens 1–6")) << r.err;
  EXPECT_EQ(written_files(dir.path()), std::vector<std::string>{});
  // The 8-pen 7550 takes it (--plain: no caption, which is drawn with pen 1).
  EXPECT_EQ(run({script, "-o", hpgl.string(), "--plotter", "hp7550", "--plain"}).code, 0);
  const hlr::test::HpglReplay replay = hlr::test::read_hpgl(read_text(hpgl));
  ASSERT_EQ(replay.error, "");
  ASSERT_FALSE(replay.runs.empty());
  for (const hlr::test::HpglRun& run : replay.runs) EXPECT_EQ(run.pen, 7);
}

// The 2-unit cube seen by an ortho camera of height 2 (1 world unit = 1 picture unit) from 34.7° up is
// 2.85 units tall: its vertical edges 2·cos 34.7° = 1.64, plus its top face, 2.12 deep along the view, at
// sin 34.7°: 1.21. At --scale 100 that is 285 mm, beyond the 192 mm the 7475A reaches on A4 (x 10–284.7,
// y 13.9–206 mm). Framed by the camera (the default) the picture is cut at the drawing area, which the
// plotter's reach narrows, so it plots; fitting the drawing instead (--fit drawing), it is refused unless
// clipped; clipped, cut at the A4 range's edges (0..11040 × 0..7721).
TEST(DevicesErrors, BeyondThePlottersReachUnlessClipped) {
  const test::TempDir dir(current_test_name());
  const std::string script =
      dir.write("big.hls",
                "draw cube(2) at rotate(z: 30)\n"
                "camera main = ortho(eye: (20, -30, 25), target: (0, 0, 0), height: 2)\n")
          .string();
  const fs::path hpgl = dir.path() / "x.hpgl";
  const Result framed = run({script, "-o", hpgl.string(), "--plotter", "hp7475a", "--scale", "100"});
  EXPECT_EQ(framed.code, 0) << framed.err;
  fs::remove(hpgl);
  const Result r =
      run({script, "-o", hpgl.string(), "--plotter", "hp7475a", "--scale", "100", "--fit", "drawing"});
  EXPECT_EQ(r.code, 73);
  EXPECT_TRUE(contains(r.err, "outside what plotter 'hp7475a' can draw on A4 paper")) << r.err;
  EXPECT_TRUE(contains(r.err, "cut it with --clip")) << r.err;
  EXPECT_EQ(written_files(dir.path()), std::vector<std::string>{});
  const Result clipped = run(
      {script, "-o", hpgl.string(), "--plotter", "hp7475a", "--scale", "100", "--fit", "drawing", "--clip"});
  ASSERT_EQ(clipped.code, 0) << clipped.err;
  const hlr::test::HpglReplay replay = hlr::test::read_hpgl(read_text(hpgl));
  ASSERT_EQ(replay.error, "");
  EXPECT_GE(replay.runs.size(), 3U);
  int on_edge = 0;
  for (const hlr::test::HpglRun& run : replay.runs)
    for (const hlr::test::HpglPos& p : run.points) {
      EXPECT_GE(p.x, 0);
      EXPECT_LE(p.x, 11040);
      EXPECT_GE(p.y, 0);
      EXPECT_LE(p.y, 7721);
      on_edge += p.x == 0 || p.x == 11040 || p.y == 0 || p.y == 7721;
    }
  EXPECT_GE(on_edge, 4);  // strokes cut where they leave the reach
}

TEST(DevicesErrors, TooManyPixels) {
  const test::TempDir dir(current_test_name());
  const std::string cube = dir.write("cube.hls", kCube).string();
  // A0 landscape at 300 dpi: 1189 × 300 / 25.4 = 14043, 841 × 300 / 25.4 = 9933 pixels: 139.5 megapixels.
  // The largest dpi within 100 megapixels: 25.4 · √(1e8 / (1189 · 841)) = 254.0, offered as 253.
  const Result r = run({cube, "-o", (dir.path() / "x.png").string(), "--paper", "A0", "--dpi", "300"});
  EXPECT_EQ(r.code, 73);
  EXPECT_TRUE(contains(r.err, "14043 x 9933 pixels")) << r.err;
  EXPECT_TRUE(contains(r.err, "100 megapixels")) << r.err;
  EXPECT_TRUE(contains(r.err, "lower the dpi to at most 253")) << r.err;
  EXPECT_EQ(written_files(dir.path()), std::vector<std::string>{});
}

TEST(DevicesErrors, MissingDirectory) {
  const test::TempDir dir(current_test_name());
  const std::string cube = dir.write("cube.hls", kCube).string();
  for (const char* name : {"x.pdf", "x.svg", "x.png", "x.hpgl", "x.json"}) {
    const fs::path target = dir.path() / "missing" / name;
    const Result r = run({cube, "-o", target.string()});
    EXPECT_EQ(r.code, 73) << name;
    EXPECT_TRUE(contains(r.err, "directory '" + (dir.path() / "missing").string() + "' does not exist"))
        << r.err;
  }
  EXPECT_FALSE(fs::exists(dir.path() / "missing"));
  EXPECT_EQ(written_files(dir.path()), std::vector<std::string>{});
}

// ---- the pens-and-plotter example: its plotter declaration reaches the HPGL ----

// -o names the file; the script's `output ... plotter desk7475` still picks the plotter: VS15, at most
// 16 pairs per PU/PD, a newline after every command, the 7475A's A4 range (0..11040 × 0..7721), pens 1-4
// (pen 4 the hidden layer's).
TEST(DevicesExample, PensAndPlotterUsesItsPlotter) {
  const test::TempDir dir(current_test_name());
  const std::string script =
      (fs::path(HLR_TEST_DATA_DIR).parent_path().parent_path() / "examples/showcase/pens-and-plotter.hls")
          .string();
  const fs::path hpgl = dir.path() / "pens.hpgl";
  const Result r = run({script, "-o", hpgl.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = read_text(hpgl);
  EXPECT_EQ(text.substr(0, 10), "IN;\nVS15;\n");
  const hlr::test::HpglParse parsed = hlr::test::parse_hpgl(text);
  ASSERT_EQ(parsed.error, "");
  EXPECT_EQ(std::count(text.begin(), text.end(), ';'), std::count(text.begin(), text.end(), '\n'));
  EXPECT_EQ(parsed.commands.size(), static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')));
  std::size_t widest = 0;
  for (const hlr::test::HpglCommand& c : parsed.commands) widest = std::max(widest, c.params.size() / 2);
  EXPECT_EQ(widest, 16U);  // long strokes are cut at exactly 16 pairs
  const hlr::test::HpglReplay replay = hlr::test::replay_hpgl(parsed.commands);
  ASSERT_EQ(replay.error, "");
  std::set<int> pens;
  for (const hlr::test::HpglRun& run : replay.runs) pens.insert(run.pen);
  EXPECT_EQ(pens, (std::set<int>{1, 2, 3, 4}));
  for (const hlr::test::HpglPos& p : replay.visited) {
    EXPECT_TRUE(p.x >= 0 && p.x <= 11040 && p.y >= 0 && p.y <= 7721) << p.x << ", " << p.y;
  }
  // Without the hidden layer, pen 4 is not used.
  const Result visible = run({script, "-o", hpgl.string(), "--hidden", "off"});
  ASSERT_EQ(visible.code, 0) << visible.err;
  pens.clear();
  for (const hlr::test::HpglRun& run : hlr::test::read_hpgl(read_text(hpgl)).runs) pens.insert(run.pen);
  EXPECT_EQ(pens, (std::set<int>{1, 2, 3}));
}

// ---- --stats: the plan line per frame, matching what JSON reports ----

TEST(DevicesStats, PlanLinePerFrame) {
  const test::TempDir dir(current_test_name());
  const std::string anim = dir.write("anim.hls", kThreeFrames).string();
  const fs::path json = dir.path() / "anim.json";
  const Result r = run({anim, "-o", json.string(), "--stats"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(read_text(json));
  ASSERT_EQ(doc["frames"].size(), 3U);
  const std::regex line_re(R"(frame (\d+) -> anim\.json: .*, (\d+) lifts \(lower bound (\d+)\))");
  int lines = 0;
  for (auto it = std::sregex_iterator(r.err.begin(), r.err.end(), line_re); it != std::sregex_iterator();
       ++it, ++lines) {
    const int frame = std::stoi((*it)[1]);
    ASSERT_EQ(frame, lines);
    const nlohmann::json& stats = doc["frames"][frame]["stats"];
    EXPECT_EQ(std::stoul((*it)[2]), stats["lifts"].get<std::size_t>());
    EXPECT_EQ(std::stoul((*it)[3]), stats["lift_lower_bound"].get<std::size_t>());
    // A cube seen with three faces: a hexagonal outline and three inner edges from its near corner to
    // every other outline corner. Odd vertices: that corner and the three outline corners → 2 strokes.
    EXPECT_EQ(stats["lift_lower_bound"], 2);
  }
  EXPECT_EQ(lines, 3) << r.err;
  // Without --stats, no plan lines.
  const Result quiet = run({anim, "-o", json.string()});
  EXPECT_FALSE(contains(quiet.err, "lifts")) << quiet.err;
}

}  // namespace
}  // namespace hlr::runtime
