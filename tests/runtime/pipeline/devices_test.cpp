// The output devices end to end through run_cli (tracker issue 4): every example on every built-in
// plotter profile and paper, read back by the independent HP-GL reader (tests/support/hpgl_reader.hpp),
// and hp2xx's picture of the HPGL against the PNG of the same frame. The devices against each other and
// the pen orders: devices_agree_test.cpp; options, paper sizes and errors:
// devices_options_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "core/device/plotters/hpgl_profile.hpp"
#include "runtime/cli/cli.hpp"
#include "tests/runtime/cli_run.hpp"
#include "tests/runtime/runtime_test_support.hpp"
#include "tests/support/hpgl_reader.hpp"
#include "tests/support/raster_compare.hpp"

namespace hlr::runtime {
namespace {

namespace fs = std::filesystem;

using Result = test::CliResult;
using test::read_text;
using test::run;

const fs::path kTestsDir = fs::path(HLR_TEST_DATA_DIR).parent_path();
const fs::path kExamplesDir = kTestsDir.parent_path() / "examples";

std::string current_test_name() { return test::scratch_name("devices"); }

// ---- the examples: tests/CMakeLists.txt's HLR_EXAMPLES list ("path:pages"), read, not copied ----

struct Example {
  std::string path;  // under examples/
  int pages = 1;
};

std::vector<Example> listed_examples() {
  const std::string text = read_text(kTestsDir / "CMakeLists.txt");
  const std::size_t start = text.find("set(HLR_EXAMPLES");
  if (start == std::string::npos) return {};
  const std::size_t end = text.find(')', start);
  std::istringstream words(text.substr(start + 17, end - start - 17));
  std::vector<Example> out;
  for (std::string w; words >> w;) {
    const std::size_t colon = w.find(':');
    if (colon == std::string::npos) continue;
    out.push_back({w.substr(0, colon), std::stoi(w.substr(colon + 1))});
  }
  return out;
}

TEST(DevicesExamples, TheListIsReadAndComplete) {
  const std::vector<Example> all = listed_examples();
  ASSERT_GE(all.size(), 19U);
  const auto listed = [&](const std::string& p) {
    return std::any_of(all.begin(), all.end(), [&](const Example& e) { return e.path == p; });
  };
  EXPECT_TRUE(listed("desens/landing.hls"));
  EXPECT_TRUE(listed("showcase/pens-and-plotter.hls"));
  for (const Example& e : all) EXPECT_TRUE(fs::exists(kExamplesDir / e.path)) << e.path;
}

// The frames to render: all of a one-frame script; three spread over an animation (first, middle, last
// for an odd count) by --frames and --shard.
std::vector<std::string> frame_args(const Example& e) {
  if (e.pages < 3) return {};
  const int step = (e.pages - 1) / 2;
  return {"--frames", "0-" + std::to_string(e.pages - 1), "--shard", "1/" + std::to_string(step)};
}
std::vector<int> expected_frames(const Example& e) {
  if (e.pages < 3) return {0};
  const int step = (e.pages - 1) / 2;
  std::vector<int> frames;
  for (int f = 0; f < e.pages; f += step) frames.push_back(f);
  return frames;
}

std::string frame_file(int frame, const std::string& ext) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "f-%03d.%s", frame, ext.c_str());
  return buf;
}

bool same_name(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

// The range the device must keep to: the one named like the paper, else the any-size one.
const HpglPaperRange* range_for(const HpglProfile& p, const std::string& paper) {
  for (const HpglPaperRange& r : p.ranges)
    if (!r.any_size() && same_name(r.paper, paper)) return &r;
  for (const HpglPaperRange& r : p.ranges)
    if (r.any_size()) return &r;
  return nullptr;
}

// Every position the reader reconstructs (pen up or down) lies within the range's limits and on the sheet
// (sheet_w × sheet_h mm; plotter (0, 0) at the range's origin), every pen within 1..pen_count, no PU/PD
// holds more than max_pairs_per_pd pairs, and something is drawn.
void expect_plottable(const std::string& text, const HpglProfile& p, const HpglPaperRange& r, double sheet_w,
                      double sheet_h, const std::string& what) {
  SCOPED_TRACE(what);
  const hlr::test::HpglParse parsed = hlr::test::parse_hpgl(text);
  ASSERT_EQ(parsed.error, "");
  std::size_t widest = 0;
  for (const hlr::test::HpglCommand& c : parsed.commands)
    if (c.mnemonic == "PD" || c.mnemonic == "PU") widest = std::max(widest, c.params.size() / 2);
  EXPECT_LE(widest, static_cast<std::size_t>(p.max_pairs_per_pd));
  const hlr::test::HpglReplay replay = hlr::test::replay_hpgl(parsed.commands);
  ASSERT_EQ(replay.error, "");
  EXPECT_TRUE(replay.pen_up_at_end);
  ASSERT_FALSE(replay.runs.empty());
  long x0 = 1L << 40, x1 = -x0, y0 = x0, y1 = -x0;
  for (const hlr::test::HpglPos& v : replay.visited) {
    x0 = std::min(x0, v.x), x1 = std::max(x1, v.x), y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
  }
  EXPECT_GE(x0, r.x_min);
  EXPECT_LE(x1, r.x_max);
  EXPECT_GE(y0, r.y_min);
  EXPECT_LE(y1, r.y_max);
  constexpr double kEps = 1e-9;
  EXPECT_GE(x0 * p.unit_mm + r.origin_x_mm, -kEps);
  EXPECT_LE(x1 * p.unit_mm + r.origin_x_mm, sheet_w + kEps);
  EXPECT_GE(y0 * p.unit_mm + r.origin_y_mm, -kEps);
  EXPECT_LE(y1 * p.unit_mm + r.origin_y_mm, sheet_h + kEps);
  for (const hlr::test::HpglRun& run : replay.runs) {
    EXPECT_GE(run.pen, 1);
    EXPECT_LE(run.pen, p.pen_count);
  }
}

class EveryExample : public ::testing::TestWithParam<Example> {};

// Every example × every built-in profile × A4 and A3 landscape (where the profile takes the paper) and
// A4 portrait: one HPGL file per frame, every one within the plotter's reach. A sheet of views is placed in
// millimetres on its own paper (landscape, A3 or A4): it is plotted on that paper only.
TEST_P(EveryExample, PlotsWithinEveryProfilesReach) {
  const Example& e = GetParam();
  const test::TempDir dir(current_test_name());
  const std::string script = (kExamplesDir / e.path).string();
  const std::vector<int> frames = expected_frames(e);
  struct Paper {
    std::string name;
    bool portrait;
    double w, h;  // the page as drawn
  };
  const Paper papers[] = {{"A4", false, 297, 210}, {"A3", false, 420, 297}, {"A4", true, 210, 297}};
  const std::string text = read_text(script);
  const bool sheet = text.find("\nview ") != std::string::npos;
  const std::string sheet_paper = text.find("\npaper A3 landscape") != std::string::npos ? "A3" : "A4";
  int plotted = 0;
  for (const HpglProfile& p : builtin_hpgl_profiles()) {
    for (const Paper& paper : papers) {
      if (sheet && (paper.portrait || paper.name != sheet_paper)) continue;
      const std::string what = p.name + " " + paper.name + (paper.portrait ? " portrait" : " landscape");
      const fs::path sub = dir.path() / (p.name + "-" + paper.name + (paper.portrait ? "p" : "l"));
      fs::create_directories(sub);
      std::vector<std::string> args = {
          script, "-o", (sub / "f-{frame:03}.hpgl").string(), "--plotter", p.name, "--paper", paper.name};
      if (paper.portrait) args.push_back("--portrait");
      for (const std::string& a : frame_args(e)) args.push_back(a);
      const Result r = run(args);
      const HpglPaperRange* range = range_for(p, paper.name);
      if (!range) {  // the profile does not take this paper (the message: DevicesErrors)
        EXPECT_EQ(r.code, 73) << what << "\n" << r.err;
        EXPECT_TRUE(fs::is_empty(sub)) << what;
        continue;
      }
      ASSERT_EQ(r.code, 0) << what << "\n" << r.err;
      std::size_t files = 0;
      for (auto it = fs::directory_iterator(sub); it != fs::directory_iterator(); ++it) ++files;
      EXPECT_EQ(files, frames.size()) << what;
      // The sheet as loaded: a sized range's own (a portrait page is turned onto it); else the page.
      const double sheet_w = range->any_size() ? paper.w : range->width_mm;
      const double sheet_h = range->any_size() ? paper.h : range->height_mm;
      for (const int f : frames) {
        const fs::path file = sub / frame_file(f, "hpgl");
        ASSERT_TRUE(fs::exists(file)) << file;
        expect_plottable(read_text(file), p, *range, sheet_w, sheet_h, what + " " + file.filename().string());
      }
      ++plotted;
    }
  }
  // hp7475a, hp7550, roland-dxy and generic take both sizes; hp7440a only A4: 4 × 3 + 2. A sheet: 4 on
  // A3, 5 on A4.
  EXPECT_EQ(plotted, !sheet ? 14 : sheet_paper == "A3" ? 4 : 5);
}

std::string example_test_name(const ::testing::TestParamInfo<Example>& info) {
  std::string name = info.param.path.substr(0, info.param.path.size() - 4);  // without ".hls"
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Devices, EveryExample, ::testing::ValuesIn(listed_examples()), example_test_name);

// Beyond A4 and A3: every paper each profile declares (the generic one: A4 and Legal), either orientation,
// relative and absolute moves, on one example.
TEST(DevicesPlotters, EveryRangeEitherOrientationEitherMoves) {
  const test::TempDir dir(current_test_name());
  const std::string script = (kExamplesDir / "showcase/workshop.hls").string();
  const fs::path hpgl = dir.path() / "x.hpgl";
  const std::map<std::string, std::pair<double, double>> sizes = {{"A4", {297, 210}},
                                                                  {"A3", {420, 297}},
                                                                  {"Letter", {279.4, 215.9}},
                                                                  {"Tabloid", {431.8, 279.4}},
                                                                  {"Legal", {355.6, 215.9}}};
  int plotted = 0;
  for (const HpglProfile& p : builtin_hpgl_profiles()) {
    std::vector<std::string> papers;
    for (const HpglPaperRange& r : p.ranges) papers.push_back(r.any_size() ? "Legal" : r.paper);
    if (p.ranges.front().any_size()) papers.push_back("A4");
    for (const std::string& paper : papers) {
      const auto [w, h] = sizes.at(paper);
      for (const bool portrait : {false, true}) {
        for (const std::string moves : {"relative", "absolute"}) {
          const std::string what = p.name + " " + paper + (portrait ? " portrait " : " landscape ") + moves;
          fs::remove(hpgl);
          const Result r = run({script, "-o", hpgl.string(), "--plotter", p.name, "--paper", paper,
                                portrait ? "--portrait" : "--landscape", "--hpgl-moves", moves});
          ASSERT_EQ(r.code, 0) << what << "\n" << r.err;
          const HpglPaperRange* range = range_for(p, paper);
          ASSERT_NE(range, nullptr);
          const double page_w = portrait ? h : w, page_h = portrait ? w : h;
          const std::string text = read_text(hpgl);
          // PR appears only in relative mode.
          EXPECT_EQ(text.find("PR;") != std::string::npos, moves == "relative") << what;
          expect_plottable(text, p, *range, range->any_size() ? page_w : range->width_mm,
                           range->any_size() ? page_h : range->height_mm, what);
          ++plotted;
        }
      }
    }
  }
  // hp7475a 4 papers, hp7440a 2, hp7550 4, roland-dxy 2, generic 2; × 2 orientations × 2 move modes.
  EXPECT_EQ(plotted, 14 * 4);
}

// ---- hp2xx's picture of the HPGL against the PNG of the same frame ----

class Hp2xxAgainstPng : public ::testing::TestWithParam<std::string> {};

TEST_P(Hp2xxAgainstPng, SameDrawing) {
  ASSERT_TRUE(hlr::test::have_hp2xx()) << "hp2xx is not installed: run scripts/setup.sh";
  const test::TempDir dir(current_test_name());
  const std::string script = (kExamplesDir / GetParam()).string();
  const fs::path png = dir.path() / "x.png", hpgl = dir.path() / "x.hpgl";
  // 100 dpi on both sides; the PNG's default 0.25 mm pens are about one pixel wide, as hp2xx draws.
  const Result a = run({script, "-o", png.string(), "--plain", "--dpi", "100", "--hidden", "off"});
  ASSERT_EQ(a.code, 0) << a.err;
  const Result b = run({script, "-o", hpgl.string(), "--plotter", "generic", "--plain", "--hidden", "off"});
  ASSERT_EQ(b.code, 0) << b.err;
  const hlr::test::Ink cairo = hlr::test::ink_of_png(png);
  ASSERT_EQ(cairo.w, 1169);      // A4 landscape at 100 dpi
  ASSERT_GT(cairo.count, 500U);  // a drawing, not a few stray pixels
  const fs::path work = dir.path() / "hp2xx";
  fs::create_directories(work);
  const hlr::test::Ink plotted = hlr::test::hp2xx_ink(read_text(hpgl), work, 100);
  ASSERT_GT(plotted.count, 500U);
  // hp2xx crops to the drawing: the normalised boxes match only if the drawing has the same size.
  EXPECT_NEAR(plotted.x1 - plotted.x0, cairo.x1 - cairo.x0, 4);
  EXPECT_NEAR(plotted.y1 - plotted.y0, cairo.y1 - cairo.y0, 4);
  const hlr::test::Agreement g = hlr::test::compare_ink(cairo, plotted);
  EXPECT_TRUE(g.aspect_ok);
  EXPECT_GE(g.expected_found, 0.95) << "hp2xx's ink near the PNG's: " << g.actual_found;
  EXPECT_GE(g.actual_found, 0.95) << "PNG's ink near hp2xx's: " << g.expected_found;
  // The comparison tells a mirror image apart: the PNG flipped left to right does not match.
  hlr::test::Ink mirrored = cairo;
  for (int y = 0; y < cairo.h; ++y)
    for (int x = 0; x < cairo.w; ++x)
      mirrored.on[static_cast<std::size_t>(y) * cairo.w + x] = cairo.at(cairo.w - 1 - x, y) ? 1 : 0;
  mirrored.x0 = cairo.w - 1 - cairo.x1;
  mirrored.x1 = cairo.w - 1 - cairo.x0;
  const hlr::test::Agreement wrong = hlr::test::compare_ink(mirrored, plotted);
  EXPECT_LT(std::min(wrong.expected_found, wrong.actual_found), 0.8)
      << wrong.expected_found << " " << wrong.actual_found;
}

INSTANTIATE_TEST_SUITE_P(Devices, Hp2xxAgainstPng,
                         ::testing::Values("desens/carrier-2.hls", "showcase/gear.hls",
                                           "showcase/platonic.hls", "albers/tetrahedron.hls"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param.substr(0, info.param.size() - 4);
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace hlr::runtime
