// Hidden lines on pen plotters are drawn as dashes, never solid: the files are read back (HPGL by the
// tests' own reader, G-code line by line) and their pen-down runs measured against the same frame's
// JSON, which keeps the hidden pieces whole.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/runtime/cli_run.hpp"
#include "tests/runtime/runtime_test_support.hpp"
#include "tests/support/hpgl_reader.hpp"
#include "tests/support/temp_dir.hpp"

namespace hlr::runtime {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string current_test_name() { return test::scratch_name("plotter-hidden"); }

// The box, with its hidden edges asked for.
constexpr const char* kBox =
    "draw box(4, 1, 2)\n"
    "camera main = lookat(eye: (8, -9, 6), target: (2, 0.5, 1), fov: 30)\n"
    "style hidden dashed\n";

// Pen-down runs as lengths in mm.
struct Runs {
  std::vector<double> lengths;
  double total() const {
    double t = 0;
    for (double l : lengths) t += l;
    return t;
  }
};

// The same page for every device: no caption, margins wider than any plotter's reach.
std::vector<std::string> page_args(const fs::path& out, const char* hidden) {
  return {"-o", out.string(), "--plain", "--margin", "20", "--hidden", hidden};
}

std::string render(const hlr::test::TempDir& dir, const std::string& name, const char* hidden,
                   std::vector<std::string> extra = {}) {
  const std::string script = dir.write("box.hls", kBox).string();
  const fs::path out = dir.path() / name;
  std::vector<std::string> args{script};
  for (const std::string& a : page_args(out, hidden)) args.push_back(a);
  args.insert(args.end(), extra.begin(), extra.end());
  const test::CliResult r = test::run(args);
  EXPECT_EQ(r.code, 0) << r.err;
  return test::read_text(out);
}

Runs hpgl_runs(const std::string& text) {
  const hlr::test::HpglReplay replay = hlr::test::read_hpgl(text);
  EXPECT_EQ(replay.error, "");
  Runs runs;
  for (const hlr::test::HpglRun& run : replay.runs) {
    double l = 0;
    for (std::size_t k = 1; k < run.points.size(); ++k)
      l += std::hypot(static_cast<double>(run.points[k].x - run.points[k - 1].x),
                      static_cast<double>(run.points[k].y - run.points[k - 1].y));
    runs.lengths.push_back(l * 0.025);  // the generic profile: 40 plotter units a millimetre
  }
  return runs;
}

// G-code: G0 moves with the pen up, G1 moves with it down; a run ends at the next G0.
Runs gcode_runs(const std::string& text) {
  Runs runs;
  std::istringstream in(text);
  std::string line;
  double x = 0, y = 0;
  bool in_run = false;
  while (std::getline(in, line)) {
    const bool draw = line.rfind("G1 X", 0) == 0, travel = line.rfind("G0 X", 0) == 0;
    if (!draw && !travel) continue;
    double nx = 0, ny = 0;
    std::istringstream words(line.substr(3));
    std::string w;
    while (words >> w) {
      if (w[0] == 'X') nx = std::stod(w.substr(1));
      if (w[0] == 'Y') ny = std::stod(w.substr(1));
    }
    if (draw) {
      if (!in_run) runs.lengths.push_back(0);
      runs.lengths.back() += std::hypot(nx - x, ny - y);
    }
    in_run = draw;
    x = nx;
    y = ny;
  }
  return runs;
}

// The hidden pieces' whole length on the page: JSON's planned strokes with the hidden layer on, less
// those with it off.
double hidden_length_mm(const hlr::test::TempDir& dir) {
  const json on = json::parse(render(dir, "on.json", "dashed"))["frames"][0]["stats"];
  const json off = json::parse(render(dir, "off.json", "off"))["frames"][0]["stats"];
  return on["pen_down_mm"].get<double>() - off["pen_down_mm"].get<double>();
}

// What a plotter draws of the hidden lines: between 2/3.5 of their length (the bare 2 mm dash, 1.5 mm
// gap pattern) and that plus one dash a stroke (each stroke starts and ends with a dash); in runs no
// longer than a stretched dash, and many of them.
void expect_dashed(const Runs& dashed, const Runs& visible_only, double hidden_mm) {
  ASSERT_GT(hidden_mm, 50);  // the box hides three edges
  const double hidden_drawn = dashed.total() - visible_only.total();
  EXPECT_GT(hidden_drawn, hidden_mm * 2 / 3.5 - 0.5);
  EXPECT_LT(hidden_drawn, hidden_mm * 0.7);
  const std::size_t dashes = dashed.lengths.size() - visible_only.lengths.size();
  EXPECT_GE(static_cast<double>(dashes), hidden_mm / 3.5 - 3);
  // Every run the hidden layer added is a dash: the visible runs are the same lengths as before.
  std::vector<double> a = dashed.lengths, b = visible_only.lengths;
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  std::size_t matched = 0, j = 0;
  for (double l : a) {
    while (j < b.size() && b[j] < l - 0.01) ++j;
    if (j < b.size() && std::abs(b[j] - l) <= 0.01) {
      ++matched;
      ++j;
    } else {
      EXPECT_LT(l, 2 * 1.25) << "a pen-down run of " << l << " mm is not a dash";
    }
  }
  EXPECT_EQ(matched, b.size());
}

TEST(PlotterHiddenLines, HpglDrawsHiddenLinesAsDashes) {
  const hlr::test::TempDir dir(current_test_name());
  const double hidden_mm = hidden_length_mm(dir);
  const Runs dashed = hpgl_runs(render(dir, "on.hpgl", "dashed"));
  const Runs visible = hpgl_runs(render(dir, "off.hpgl", "off"));
  expect_dashed(dashed, visible, hidden_mm);
}

TEST(PlotterHiddenLines, GcodeDrawsHiddenLinesAsDashes) {
  const hlr::test::TempDir dir(current_test_name());
  const double hidden_mm = hidden_length_mm(dir);
  const Runs dashed = gcode_runs(render(dir, "on.gcode", "dashed"));
  const Runs visible = gcode_runs(render(dir, "off.gcode", "off"));
  expect_dashed(dashed, visible, hidden_mm);
}

// --dash sets the pattern: 4 mm dashes with 1 mm gaps draw about four fifths of the hidden length.
TEST(PlotterHiddenLines, DashSetsThePattern) {
  const hlr::test::TempDir dir(current_test_name());
  const double hidden_mm = hidden_length_mm(dir);
  const Runs dashed = hpgl_runs(render(dir, "on.hpgl", "dashed", {"--dash", "4,1"}));
  const Runs visible = hpgl_runs(render(dir, "off.hpgl", "off"));
  const double hidden_drawn = dashed.total() - visible.total();
  EXPECT_GT(hidden_drawn, hidden_mm * 0.8 - 0.5);
  EXPECT_LT(hidden_drawn, hidden_mm * 0.9);
  const test::CliResult bad = test::run({"x.hls", "--dash", "2"});
  EXPECT_EQ(bad.code, 64);
  EXPECT_NE(bad.err.find("--dash 2: expected DASH,GAP in millimetres"), std::string::npos) << bad.err;
}

// The hidden layer on its own pen (style hidden dashed pen 2): the dashes are drawn with that pen.
TEST(PlotterHiddenLines, TheHiddenPenDrawsTheDashes) {
  const hlr::test::TempDir dir(current_test_name());
  const std::string script =
      dir.write("pens.hls",
                std::string(kBox).replace(std::string(kBox).find("dashed\n"), 7, "dashed pen 2\n"))
          .string();
  const fs::path out = dir.path() / "pens.hpgl";
  const test::CliResult r = test::run({script, "-o", out.string(), "--plain"});
  ASSERT_EQ(r.code, 0) << r.err;
  const hlr::test::HpglReplay replay = hlr::test::read_hpgl(test::read_text(out));
  ASSERT_EQ(replay.error, "");
  int pen2 = 0;
  for (const hlr::test::HpglRun& run : replay.runs) pen2 += run.pen == 2;
  EXPECT_GT(pen2, 10);
}

// The incremental plotter's tape likewise: its header counts the strokes and the pen-down steps.
TEST(PlotterHiddenLines, TheStepTapeDrawsDashesToo) {
  const hlr::test::TempDir dir(current_test_name());
  const auto header = [&](const std::string& name, std::vector<std::string> extra) {
    const std::string text = render(dir, name, "dashed", std::move(extra));
    long down = 0, strokes = 0;
    const std::size_t at = text.find("pen-down steps");
    EXPECT_NE(at, std::string::npos) << text.substr(0, 400);
    long up = 0;
    std::sscanf(text.c_str() + text.rfind('#', at), "# %ld pen-down steps, %ld pen-up steps, %ld strokes",
                &down, &up, &strokes);
    return std::pair{down, strokes};
  };
  const auto [dashed_down, dashed_strokes] = header("dashed.steps", {});
  const auto [solid_down, solid_strokes] = header("solid.steps", {"--dash", "solid"});
  EXPECT_GE(dashed_strokes, solid_strokes + 30);  // the hidden edges as dozens of dashes
  EXPECT_LT(dashed_down, solid_down);             // with the pen up over the gaps
  EXPECT_GT(dashed_down, solid_down * 3 / 4);
}

}  // namespace
}  // namespace hlr::runtime
