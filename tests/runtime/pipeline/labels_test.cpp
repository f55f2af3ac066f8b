// `label TEXT at POINT [size: MM] [pen N]`: what the evaluator records, every mistake at its place, and
// what comes out — world labels hidden by the solids in front of them, upright on the page at the size
// asked, page labels where they are put, and neither moving the drawing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/runtime/cli_run.hpp"
#include "tests/runtime/runtime_test_support.hpp"
#include "tests/support/temp_dir.hpp"

namespace hlr::runtime {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string current_test_name() { return test::scratch_name("labels"); }

TEST(Labels, TheEvaluatorRecordsEachLabel) {
  const FrameScene scene = test::run_ok(
      "let n = 2\n"
      "label \"tower {n}\" at (1, 2, 3)\n"
      "label n * 21 at page (20, 15) size: 5 pen n\n");
  ASSERT_EQ(scene.labels.size(), 2U);
  const LabelSetting& a = scene.labels[0];
  EXPECT_EQ(a.text, "tower 2");
  EXPECT_FALSE(a.on_page);
  EXPECT_EQ(a.at.x, 1);
  EXPECT_EQ(a.at.z, 3);
  EXPECT_EQ(a.size_mm, kDefaultLabelSizeMm);
  EXPECT_EQ(a.pen, 1);
  const LabelSetting& b = scene.labels[1];
  EXPECT_EQ(b.text, "42");  // any value, as str() writes it
  EXPECT_TRUE(b.on_page);
  EXPECT_EQ(b.at.y, 15);
  EXPECT_EQ(b.size_mm, 5);
  EXPECT_EQ(b.pen, 2);
}

TEST(Labels, ALabelIsOnlyAKeywordWhereAStatementStarts) {
  const FrameScene scene = test::run_ok("let label = 3\nlet size = label + 1\nlabel \"x\" at (0, 0, size)\n");
  ASSERT_EQ(scene.labels.size(), 1U);
  EXPECT_EQ(scene.labels[0].at.z, 4);
}

struct Case {
  const char* script;
  const char* expected;
};

// clang-format off
const Case kErrors[] = {
  {"label \"a\" (0, 0, 0)", "1:20: expected 'at' and where the label goes, as in 'label \"bridge\" at (0, 0, 2)'"},
  {"label \"a\" at", "1:13: expected a point after 'at', as in 'label \"bridge\" at (0, 0, 2)' or 'at page (20, 15)'"},
  {"label at (0, 0, 0)", "1:7: expected the text after 'label', as in 'label \"bridge\" at (0, 0, 2)'"},
  {"label \"a\" at (0, 0, 0) size: ", "1:29: expected the letters' height in millimetres after 'size:', as in 'size: 4'"},
  {"label \"a\" at 3", "1:14: a label goes at a point, got a number"},
  {"label \"a\" at (0, 0, 0) size: 0", "1:30: the label's size is the height of its capitals in millimetres, above 0 and at most 500"},
  {"label \"a\" at (0, 0, 0) size: \"big\"", "1:30: the label's size is the height of its capitals in millimetres, above 0 and at most 500"},
  {"label \"a\" at page (-1, 5)", "1:19: a page point is (x, y) in millimetres from the page's top-left corner, both 0 or more"},
  {"label \"a\" at (0, 0, 0) pen 0", "1:28: the pen number must be a whole number from 1 to 255, got 0"},
};
// clang-format on

TEST(Labels, Errors) {
  for (const Case& c : kErrors) EXPECT_EQ(test::first_error(c.script), c.expected) << c.script;
}

// ---- through the command, read back from the JSON ----

// A 4-unit cube centred on the origin, seen from +x.
constexpr const char* kScene =
    "draw box(4, 4, 4) at translate(-2, -2, -2)\n"
    "camera main = lookat(eye: (10, 0, 0), target: (0, 0, 0), fov: 30)\n";

struct LabelPieces {
  int visible = 0, hidden = 0;
  double page_ymin = 1e9, page_ymax = -1e9;  // of the visible pieces, page mm (y down)
};

json render_json(const hlr::test::TempDir& dir, const std::string& text,
                 std::vector<std::string> extra = {}) {
  const std::string script = dir.write("labels.hls", text).string();
  const fs::path out = dir.path() / "labels.json";
  std::vector<std::string> args{script, "-o", out.string(), "--hidden", "dashed"};
  args.insert(args.end(), extra.begin(), extra.end());
  const test::CliResult r = test::run(args);
  EXPECT_EQ(r.code, 0) << r.err;
  return json::parse(test::read_text(out))["frames"][0];
}

LabelPieces pieces_of(const json& frame, const std::string& object) {
  LabelPieces p;
  const double scale = frame["layout"]["mm_per_unit"];
  const double origin_y = frame["layout"]["origin_mm"][1];
  for (const json& s : frame["segments"]) {
    if (s["object"] != object) continue;
    if (s["hidden"]) {
      ++p.hidden;
      continue;
    }
    ++p.visible;
    for (const json& q : s["s"]) {
      const double y = origin_y - scale * q[1].get<double>();
      p.page_ymin = std::min(p.page_ymin, y);
      p.page_ymax = std::max(p.page_ymax, y);
    }
  }
  return p;
}

TEST(Labels, SolidsHideWhatIsBehindThem) {
  const hlr::test::TempDir dir(current_test_name());
  // The eye on +x: a label at x = 3 is in front of the cube, at x = -3 behind it, and one that starts at
  // the cube's middle and runs far past its edge on the page is partly behind.
  const json frame = render_json(dir, std::string(kScene) +
                                          "label \"FRONT\" at (3, 0, 0)\n"
                                          "label \"BACK\" at (-3, 0, 0)\n"
                                          "label \"HALF HIDDEN LABEL\" at (-3, 0, 0.5) size: 12\n");
  const LabelPieces front = pieces_of(frame, "label 1"), back = pieces_of(frame, "label 2"),
                    half = pieces_of(frame, "label 3");
  EXPECT_GT(front.visible, 10);
  EXPECT_EQ(front.hidden, 0);
  EXPECT_EQ(back.visible, 0);
  EXPECT_GT(back.hidden, 10);
  EXPECT_GT(half.visible, 5);
  EXPECT_GT(half.hidden, 5);
}

TEST(Labels, WithAFrameCapitalsAreTheirSizeAndLabelsNeverMoveTheDrawing) {
  const hlr::test::TempDir dir(current_test_name());
  const std::string scene =
      "draw box(2, 2, 2)\ncamera main = lookat(eye: (10, 0, 0), target: (0, 0, 0), fov: 30, "
      "aspect: 1.4)\n";
  const json plain = render_json(dir, scene);
  const json labelled = render_json(dir, scene + "label \"HH\" at (2, 1, 1) size: 7\n");
  EXPECT_EQ(plain["layout"], labelled["layout"]);
  const LabelPieces hh = pieces_of(labelled, "label 1");
  ASSERT_EQ(hh.hidden, 0);
  ASSERT_GT(hh.visible, 0);
  EXPECT_NEAR(hh.page_ymax - hh.page_ymin, 7, 1e-6);
}

// Fitting the drawing (fit: "drawing"), without a frame, the page makes room for the labels too: a label
// far to the side of the solids is whole on the page, inside the margins, at its size.
TEST(Labels, WithoutAFrameThePageMakesRoomForTheLabels) {
  const hlr::test::TempDir dir(current_test_name());
  for (const char* camera :
       {"orbit(theta: 0, phi: 90, rho: 10, d: 30)", "lookat(eye: (10, 0, 0), target: (0, 0, 0), fov: 30)"}) {
    SCOPED_TRACE(camera);
    const std::string scene =
        std::string("paper A4 (fit: \"drawing\")\ndraw box(2, 2, 2)\ncamera main = ") + camera + "\n";
    const json frame = render_json(dir, scene + "label \"A LONG LABEL TO THE SIDE\" at (0, 6, 3) size: 7\n");
    const double scale = frame["layout"]["mm_per_unit"], ox = frame["layout"]["origin_mm"][0],
                 oy = frame["layout"]["origin_mm"][1];
    double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
    int pieces = 0;
    for (const json& s : frame["segments"]) {
      if (s["object"] != "label 1") continue;
      ++pieces;
      for (const json& q : s["s"]) {
        const double x = ox + scale * q[0].get<double>(), y = oy - scale * q[1].get<double>();
        xmin = std::min(xmin, x);
        xmax = std::max(xmax, x);
        ymin = std::min(ymin, y);
        ymax = std::max(ymax, y);
      }
    }
    ASSERT_GT(pieces, 50);
    EXPECT_GE(xmin, 12 - 0.01);  // the default 12 mm margins of A4 landscape
    EXPECT_LE(xmax, 297 - 12 + 0.01);
    EXPECT_GE(ymin, 12 - 0.01);
    EXPECT_LE(ymax, 210 - 12 + 0.01);
    EXPECT_NEAR(ymax - ymin, 7, 1e-6);  // capitals only
  }
}

TEST(Labels, PageLabelsAreStrokesWhereTheyArePut) {
  const hlr::test::TempDir dir(current_test_name());
  const json frame =
      render_json(dir, std::string(kScene) + "label \"NOTE\" at page (30, 20) size: 4 pen 3\n", {"--plain"});
  const json& strokes = frame["strokes"];
  const json& pens = frame["stroke_pens"];
  double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
  int count = 0;
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    if (pens[i] != 3) continue;
    ++count;
    for (const json& p : strokes[i]) {
      xmin = std::min(xmin, p[0].get<double>());
      xmax = std::max(xmax, p[0].get<double>());
      ymin = std::min(ymin, p[1].get<double>());
      ymax = std::max(ymax, p[1].get<double>());
    }
  }
  ASSERT_GT(count, 0);
  EXPECT_NEAR(ymax, 20, 0.03);  // the baseline (no descenders in NOTE), on the plan's 0.025 mm grid
  EXPECT_NEAR(ymax - ymin, 4, 0.05);
  EXPECT_GT(xmin, 30);  // N's left bearing
  EXPECT_LT(xmin, 31);
  EXPECT_GT(xmax, 40);
}

TEST(Labels, ALabelBehindTheEyeIsNotDrawn) {
  const hlr::test::TempDir dir(current_test_name());
  const json frame = render_json(dir, std::string(kScene) + "label \"AWAY\" at (20, 0, 0)\n");
  const LabelPieces away = pieces_of(frame, "label 1");
  EXPECT_EQ(away.visible + away.hidden, 0);
}

// UTF-8 as editors write it: a script saved with a byte-order mark, a label with umlauts, ß and a
// superscript draws every letter with no warning; a character the fonts lack is named once and drawn
// as a box.
TEST(Labels, AccentedLettersAreDrawnAndMissingOnesNamed) {
  const hlr::test::TempDir dir(current_test_name());
  const std::string text =
      "\xEF\xBB\xBF" + std::string(kScene) + "label \"Größe 1 m³\" at page (20, 20) size: 5\n";
  const std::string script = dir.write("utf8.hls", text).string();
  const fs::path out = dir.path() / "utf8.json";
  const test::CliResult r = test::run({script, "-o", out.string(), "--text", "stroke"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  const std::string bad =
      dir.write("bad.hls", std::string(kScene) + "label \"ok ✓ ✓\" at (0, 0, 1)\n").string();
  const test::CliResult w = test::run({bad, "-o", (dir.path() / "bad.json").string()});
  ASSERT_EQ(w.code, 0) << w.err;
  EXPECT_NE(
      w.err.find("bad.hls:3:7: warning: the label has characters with no single-stroke letter, drawn as "
                 "a box: U+2713 '✓'\n"),
      std::string::npos)
      << w.err;
  std::size_t count = 0;
  for (std::size_t at = w.err.find("U+2713"); at != std::string::npos; at = w.err.find("U+2713", at + 1))
    ++count;
  EXPECT_EQ(count, 1U);
}

}  // namespace
}  // namespace hlr::runtime
