#include "core/device/formats/hpgl_device.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/device/page/atomic_file.hpp"
#include "tests/support/hpgl_reader.hpp"

namespace hlr {
namespace {

using test::HpglPos;
using test::HpglReplay;
using test::read_hpgl;

const HpglProfile& builtin(const std::string& name) {
  for (const HpglProfile& p : builtin_hpgl_profiles())
    if (p.name == name) return p;
  throw std::runtime_error("no built-in profile " + name);
}

PlotPage page(double w, double h, std::vector<PlotStroke> strokes = {}) {
  PlotPage p;
  p.width_mm = w;
  p.height_mm = h;
  p.strokes = std::move(strokes);
  return p;
}

std::string error_of(const PlotPage& pg, const HpglProfile& pr, const HpglOptions& o = {}) {
  try {
    to_hpgl(pg, pr, o);
  } catch (const DeviceError& e) {
    return e.what();
  }
  return "";
}

long snap(double v) { return static_cast<long>(std::floor(v + 0.5)); }

// Written independently of the device: the 7475A's A4 sheet loaded landscape, plotter (0, 0) 10 mm from
// the left edge and 4 mm above the bottom edge, 0.02488 mm units, y up.
HpglPos a4_landscape(Point2 p) { return {snap((p.x - 10) / 0.02488), snap((210 - p.y - 4) / 0.02488)}; }
// A portrait A4 page turned 90° counter-clockwise onto that sheet: page top along the sheet's left edge.
HpglPos a4_portrait(Point2 p) { return {snap((p.y - 10) / 0.02488), snap((p.x - 4) / 0.02488)}; }

std::vector<HpglPos> expected_run(const std::vector<Point2>& pts, HpglPos (*map)(Point2)) {
  std::vector<HpglPos> out;
  for (Point2 p : pts)
    if (out.empty() || !(out.back() == map(p))) out.push_back(map(p));
  return out;
}

std::vector<PlotStroke> random_strokes(unsigned seed, int count, Rect2 area, int max_pen) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(area.xmin, area.xmax), uy(area.ymin, area.ymax);
  std::uniform_int_distribution<int> n(2, 40), pen(1, max_pen);
  std::vector<PlotStroke> out;
  for (int i = 0; i < count; ++i) {
    PlotStroke s;
    s.pen = pen(rng);
    for (int k = n(rng); k > 0; --k) s.points.push_back({ux(rng), uy(rng)});
    out.push_back(s);
  }
  return out;
}

TEST(HpglDevice, WellFormedHeaderAndFooter) {
  const PlotPage pg = page(297, 210, {{{{50, 50}, {100, 60}}, 1}, {{{60, 100}, {70, 120}}, 2}});
  const std::string text = to_hpgl(pg, builtin("hp7475a"));
  EXPECT_EQ(text.rfind("IN;PU;SP1;PU", 0), 0u) << text;
  EXPECT_EQ(text.substr(text.size() - 12), ";PU;PA;SP0;\n");
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1);
  const test::HpglParse parsed = test::parse_hpgl(text);
  ASSERT_EQ(parsed.error, "");
  const HpglReplay r = test::replay_hpgl(parsed.commands);
  ASSERT_EQ(r.error, "");
  EXPECT_TRUE(r.absolute_at_end);
  EXPECT_TRUE(r.pen_up_at_end);
  EXPECT_EQ(r.pens_selected, (std::vector<int>{1, 2, 0}));
  ASSERT_EQ(r.runs.size(), 2u);
  EXPECT_EQ(r.runs[0].points, (std::vector<HpglPos>{a4_landscape({50, 50}), a4_landscape({100, 60})}));
  EXPECT_EQ(r.runs[1].pen, 2);
  // IN leaves the plotter in PA: the first move is absolute, then PR; every later move relative.
  EXPECT_NE(text.find("PU" + std::to_string(a4_landscape({50, 50}).x) + "," +
                      std::to_string(a4_landscape({50, 50}).y) + ";PR;PD"),
            std::string::npos);
  // The generic profile ends every command with a newline.
  const std::string g = to_hpgl(page(297, 210, pg.strokes), builtin("generic"));
  EXPECT_EQ(g.rfind("IN;\nPU;\nSP1;\nPU", 0), 0u);
  EXPECT_EQ(std::count(g.begin(), g.end(), '\n'), std::count(g.begin(), g.end(), ';'));
  EXPECT_EQ(read_hpgl(g).error, "");
}

TEST(HpglDevice, EmptyPage) {
  EXPECT_EQ(to_hpgl(page(297, 210), builtin("hp7475a")), "IN;PU;SP0;\n");
  HpglOptions o;
  o.velocity_cm_s = 20;
  EXPECT_EQ(to_hpgl(page(297, 210), builtin("hp7475a"), o), "IN;VS20;PU;SP0;\n");
}

// Snap first, then difference: summing the relative moves lands exactly on each snapped point, however
// many moves there are, and absolute mode draws the very same runs.
TEST(HpglDevice, RelativeMovesSumToSnappedPoints) {
  std::vector<PlotStroke> strokes = random_strokes(7, 60, {15, 15, 282, 195}, 6);
  PlotStroke creep;  // 4000 steps of 0.0301 mm: rounding each delta instead would drift by many units
  for (int i = 0; i < 4000; ++i) creep.points.push_back({20 + 0.0301 * i, 30 + 0.0173 * i});
  strokes.push_back(creep);
  const PlotPage pg = page(297, 210, strokes);
  const HpglReplay rel = read_hpgl(to_hpgl(pg, builtin("hp7475a")));
  ASSERT_EQ(rel.error, "");
  ASSERT_EQ(rel.runs.size(), strokes.size());
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    EXPECT_EQ(rel.runs[i].pen, strokes[i].pen);
    EXPECT_EQ(rel.runs[i].points, expected_run(strokes[i].points, a4_landscape)) << "stroke " << i;
  }
  EXPECT_EQ(rel.runs.back().points.back(), a4_landscape(creep.points.back()));
  HpglOptions abs;
  abs.relative = false;
  const std::string abs_text = to_hpgl(pg, builtin("hp7475a"), abs);
  EXPECT_EQ(abs_text.find("PR"), std::string::npos);
  const HpglReplay a = read_hpgl(abs_text);
  ASSERT_EQ(a.error, "");
  ASSERT_EQ(a.runs.size(), rel.runs.size());
  for (std::size_t i = 0; i < a.runs.size(); ++i) EXPECT_EQ(a.runs[i].points, rel.runs[i].points);
}

TEST(HpglDevice, PairsPerCommandAreCapped) {
  PlotStroke zigzag;
  for (int i = 0; i < 500; ++i) zigzag.points.push_back({20 + 0.5 * i, i % 2 ? 50.0 : 60.0});
  const PlotPage pg = page(297, 210, {zigzag, {{{200, 150}, {210, 150}}, 1}});
  const auto max_pairs = [](const std::string& text) {
    std::size_t most = 0;
    for (const test::HpglCommand& c : test::parse_hpgl(text).commands)
      if (c.mnemonic == "PU" || c.mnemonic == "PD") most = std::max(most, c.params.size() / 2);
    return most;
  };
  const std::string def = to_hpgl(pg, builtin("hp7475a"));
  EXPECT_EQ(max_pairs(def), 32u);
  HpglOptions o;
  o.max_pairs_per_pd = 5;
  const std::string five = to_hpgl(pg, builtin("hp7475a"), o);
  EXPECT_EQ(max_pairs(five), 5u);
  EXPECT_EQ(read_hpgl(five).runs.size(), 2u);
  EXPECT_EQ(read_hpgl(five).runs[0].points, read_hpgl(def).runs[0].points);
  EXPECT_EQ(read_hpgl(def).runs[0].points.size(), 500u);
  o.max_pairs_per_pd = 0;
  EXPECT_NE(error_of(pg, builtin("hp7475a"), o).find("pair"), std::string::npos);
}

// `PU;SPn;` exactly when the pen changes; the run's pen is the stroke's.
TEST(HpglDevice, PenChangesArePrecededByPenUp) {
  const std::vector<int> pens{1, 1, 2, 1, 3, 3, 6};
  std::vector<PlotStroke> strokes;
  for (std::size_t i = 0; i < pens.size(); ++i)
    strokes.push_back({{{30.0 + 10 * i, 40}, {35.0 + 10 * i, 80}}, pens[i], StrokeLayer::Visible});
  strokes[2].layer = StrokeLayer::Hidden;  // hidden strokes are strokes with their own pen
  const std::string text = to_hpgl(page(297, 210, strokes), builtin("hp7475a"));
  const test::HpglParse p = test::parse_hpgl(text);
  ASSERT_EQ(p.error, "");
  std::vector<int> selected;
  for (std::size_t k = 0; k < p.commands.size(); ++k) {
    if (p.commands[k].mnemonic != "SP") continue;
    std::size_t before = k - 1;  // the last pen command before SP, past a closing PA
    while (before > 0 && p.commands[before].mnemonic == "PA") --before;
    EXPECT_EQ(p.commands[before].mnemonic, "PU");
    EXPECT_TRUE(p.commands[before].params.empty());
    selected.push_back(static_cast<int>(p.commands[k].params.at(0)));
  }
  EXPECT_EQ(selected, (std::vector<int>{1, 2, 1, 3, 6, 0}));
  const HpglReplay r = test::replay_hpgl(p.commands);
  ASSERT_EQ(r.runs.size(), pens.size());
  for (std::size_t i = 0; i < pens.size(); ++i) EXPECT_EQ(r.runs[i].pen, pens[i]);
}

TEST(HpglDevice, PensBeyondTheProfileAreRefused) {
  const PlotPage seven = page(297, 210, {{{{50, 50}, {60, 60}}, 7}});
  const std::string e = error_of(seven, builtin("hp7475a"));
  EXPECT_NE(e.find("pen 7"), std::string::npos) << e;
  EXPECT_NE(e.find("pens 1–6"), std::string::npos) << e;
  EXPECT_EQ(error_of(seven, builtin("hp7550")), "");
  EXPECT_NE(error_of(page(297, 210, {{{{50, 50}, {60, 60}}, 0}}), builtin("generic")).find("pen 0"),
            std::string::npos);
}

TEST(HpglDevice, PointsOutOfReachAreRefusedWithoutClip) {
  // 7475A A4: the pen reaches x 10–284.7 mm, y 13.9–206 mm of the page.
  const std::string left = error_of(page(297, 210, {{{{5, 100}, {100, 100}}, 1}}), builtin("hp7475a"));
  EXPECT_NE(left.find("stroke 1 reaches (5, 100) mm"), std::string::npos) << left;
  EXPECT_NE(left.find("x 10–284.7 mm, y 13.9–206 mm"), std::string::npos) << left;
  EXPECT_NE(left.find("margin of at least 14 mm"), std::string::npos) << left;
  EXPECT_NE(left.find("--clip"), std::string::npos) << left;
  EXPECT_NE(error_of(page(297, 210, {{{{100, 12}, {100, 100}}, 1}}), builtin("hp7475a")), "");
  EXPECT_EQ(error_of(page(297, 210, {{{{10, 14}, {284.6, 205.9}}, 1}}), builtin("hp7475a")), "");
  EXPECT_NE(error_of(page(297, 210, {{{{100, NAN}, {100, 100}}, 1}}), builtin("hp7475a")).find("finite"),
            std::string::npos);
  // Nothing is written when a check fails.
  const std::filesystem::path target =
      std::filesystem::temp_directory_path() / ("hlr-hpgl-refused-" + std::to_string(::getpid()) + ".hpgl");
  EXPECT_THROW(write_hpgl(target, page(297, 210, {{{{5, 100}, {100, 100}}, 1}}), builtin("hp7475a")),
               DeviceError);
  EXPECT_FALSE(std::filesystem::exists(target));
}

TEST(HpglDevice, ClipCutsAndSplitsStrokes) {
  HpglOptions clip;
  clip.clip = true;
  // Across the whole sheet at y = 100 mm: cut at the pen's reach, x 0…11040.
  const HpglReplay across =
      read_hpgl(to_hpgl(page(297, 210, {{{{1, 100}, {296, 100}}, 1}}), builtin("hp7475a"), clip));
  ASSERT_EQ(across.error, "");
  ASSERT_EQ(across.runs.size(), 1u);
  const long y = a4_landscape({0, 100}).y;
  EXPECT_EQ(across.runs[0].points, (std::vector<HpglPos>{{0, y}, {11040, y}}));
  // Out over the top edge (y < 13.9 mm) and back: two runs, split at y_max.
  const std::vector<Point2> hop{{50, 50}, {60, 5}, {70, 50}};
  const HpglReplay split = read_hpgl(to_hpgl(page(297, 210, {{hop, 2}}), builtin("hp7475a"), clip));
  ASSERT_EQ(split.error, "");
  ASSERT_EQ(split.runs.size(), 2u);
  EXPECT_EQ(split.runs[0].points.front(), a4_landscape(hop[0]));
  EXPECT_EQ(split.runs[0].points.back().y, 7721);
  EXPECT_EQ(split.runs[1].points.front().y, 7721);
  EXPECT_EQ(split.runs[1].points.back(), a4_landscape(hop[2]));
  EXPECT_EQ(split.runs[1].pen, 2);
  // Wholly out of reach: nothing drawn, and no pen selected for it.
  const HpglReplay none =
      read_hpgl(to_hpgl(page(297, 210, {{{{1, 1}, {296, 5}}, 3}}), builtin("hp7475a"), clip));
  EXPECT_TRUE(none.runs.empty());
  EXPECT_EQ(none.pens_selected, (std::vector<int>{0}));
  // Random strokes over the whole sheet stay within the limits.
  const std::vector<PlotStroke> wild = random_strokes(11, 80, {-20, -20, 320, 230}, 6);
  const HpglReplay r = read_hpgl(to_hpgl(page(297, 210, wild), builtin("hp7475a"), clip));
  ASSERT_EQ(r.error, "");
  EXPECT_GT(r.runs.size(), 40u);
  for (const HpglPos& v : r.visited) {
    EXPECT_TRUE(v.x >= 0 && v.x <= 11040 && v.y >= 0 && v.y <= 7721) << v.x << "," << v.y;
  }
}

// A portrait page on a plotter that takes the sheet landscape is turned 90° counter-clockwise.
TEST(HpglDevice, PortraitPageIsTurnedOntoTheSheet) {
  const std::vector<Point2> top{{50, 30}, {150, 30}, {150, 60}};  // along the top, then down
  const HpglReplay r = read_hpgl(to_hpgl(page(210, 297, {{top, 1}}), builtin("hp7475a")));
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.runs.size(), 1u);
  EXPECT_EQ(r.runs[0].points, expected_run(top, a4_portrait));
  // The page's top runs along plotter +y near x_min; going down the page goes along plotter +x.
  EXPECT_EQ(r.runs[0].points[0].x, r.runs[0].points[1].x);
  EXPECT_GT(r.runs[0].points[1].y, r.runs[0].points[0].y);
  EXPECT_GT(r.runs[0].points[2].x, r.runs[0].points[1].x);
  // Matching by name, either case, and refusing a page of another size.
  HpglOptions o;
  o.paper = "a4";
  EXPECT_EQ(read_hpgl(to_hpgl(page(210, 297, {{top, 1}}), builtin("hp7475a"), o)).runs[0].points,
            r.runs[0].points);
  o.paper = "A3";
  const std::string e = error_of(page(210, 297, {{top, 1}}), builtin("hp7475a"), o);
  EXPECT_NE(e.find("the page is 210 × 297 mm but plotter 'hp7475a' takes A3 (420 × 297 mm)"),
            std::string::npos)
      << e;
  o.paper = "B5";
  EXPECT_NE(error_of(page(210, 297), builtin("hp7475a"), o).find("has no paper 'B5'"), std::string::npos);
}

TEST(HpglDevice, PageSizeMustMatchARange) {
  const std::string e = error_of(page(200, 100), builtin("hp7475a"));
  EXPECT_NE(e.find("takes no 200 × 100 mm page"), std::string::npos) << e;
  EXPECT_NE(
      e.find("A4 (297 × 210 mm), A3 (420 × 297 mm), Letter (279.4 × 215.9 mm), Tabloid (431.8 × 279.4 mm)"),
      std::string::npos)
      << e;
  EXPECT_EQ(error_of(page(297.3, 209.8), builtin("hp7475a")), "");  // within 0.5 mm
  EXPECT_NE(error_of(page(0, 210), builtin("hp7475a")).find("page size"), std::string::npos);
}

// A drawing filling the page inside its margins stays within the limits on every built-in profile, every
// paper, both orientations. The margin is 12 mm, or the sheet's minimum when the pen reaches less.
TEST(HpglDevice, EveryProfileAndPaperStaysInRange) {
  for (const HpglProfile& p : builtin_hpgl_profiles()) {
    for (const HpglPaperRange& r : p.ranges) {
      const std::vector<std::pair<double, double>> sizes =
          r.any_size()
              ? std::vector<std::pair<double, double>>{{297, 210}, {210, 297}, {594, 420}, {819, 819}}
              : std::vector<std::pair<double, double>>{{r.width_mm, r.height_mm}, {r.height_mm, r.width_mm}};
      for (const auto& [w, h] : sizes) {
        SCOPED_TRACE(p.name + " " + r.paper + " " + std::to_string(w) + "×" + std::to_string(h));
        const double need = hpgl_min_margin_mm(p, w, h);
        const double m = std::max(12.0, std::ceil(need * 10) / 10);
        std::vector<PlotStroke> strokes{{{{m, m}, {w - m, m}, {w - m, h - m}, {m, h - m}, {m, m}}, 1},
                                        {{{m, m}, {w - m, h - m}}, 2},
                                        {{{w - m, m}, {m, h - m}}, 3}};
        for (const PlotStroke& s : random_strokes(3, 30, {m, m, w - m, h - m}, std::min(6, p.pen_count)))
          strokes.push_back(s);
        const std::string text = to_hpgl(page(w, h, strokes), p);
        const HpglReplay rep = read_hpgl(text);
        ASSERT_EQ(rep.error, "");
        ASSERT_EQ(rep.runs.size(), strokes.size());
        long x0 = 1L << 40, x1 = -x0, y0 = x0, y1 = -x0;
        for (const HpglPos& v : rep.visited) {
          ASSERT_TRUE(v.x >= r.x_min && v.x <= r.x_max && v.y >= r.y_min && v.y <= r.y_max)
              << v.x << "," << v.y;
          x0 = std::min(x0, v.x), x1 = std::max(x1, v.x), y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
        }
        const bool turned = !r.any_size() && std::fabs(w - r.width_mm) > 0.5;
        const double span_x = (turned ? h : w) - 2 * m, span_y = (turned ? w : h) - 2 * m;
        EXPECT_NEAR(x1 - x0, span_x / p.unit_mm, 1.01);
        EXPECT_NEAR(y1 - y0, span_y / p.unit_mm, 1.01);
        if (need <= 12) {
          EXPECT_EQ(m, 12);
        }
      }
    }
  }
}

TEST(HpglDevice, DotsAndDroppedPoints) {
  // Every point of the first stroke snaps to one unit: a dot. The second repeats snapped points.
  const double x0 = 10 + 3617 * 0.02488;  // on a plotter unit
  const PlotPage pg = page(297, 210,
                           {{{{x0, 100}, {x0 + 0.004, 100.003}}, 1},
                            {{{120, 100}, {120.001, 100}, {130, 100}, {130.002, 100.001}, {130, 110}}, 1}});
  const std::string text = to_hpgl(pg, builtin("hp7475a"));
  EXPECT_NE(text.find(";PD;PU"), std::string::npos) << text;
  const HpglReplay r = read_hpgl(text);
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.runs.size(), 2u);
  EXPECT_EQ(r.runs[0].points, (std::vector<HpglPos>{a4_landscape({x0, 100})}));
  EXPECT_EQ(r.runs[1].points, (std::vector<HpglPos>{a4_landscape({120, 100}), a4_landscape({130, 100}),
                                                    a4_landscape({130, 110})}));
  HpglOptions abs;
  abs.relative = false;
  EXPECT_EQ(read_hpgl(to_hpgl(pg, builtin("hp7475a"), abs)).runs[0].points, r.runs[0].points);
}

TEST(HpglDevice, VelocityAndOverrides) {
  HpglProfile p = builtin("hp7475a");
  p.velocity_cm_s = 10;
  const PlotPage pg = page(297, 210, {{{{50, 50}, {60, 60}}, 1}});
  EXPECT_EQ(to_hpgl(pg, p).rfind("IN;VS10;PU;SP1;", 0), 0u);
  HpglOptions o;
  o.velocity_cm_s = 25.5;
  EXPECT_EQ(to_hpgl(pg, p, o).rfind("IN;VS25.5;", 0), 0u);
  EXPECT_EQ(read_hpgl(to_hpgl(pg, p, o)).velocity, 25.5);
  o.velocity_cm_s = 0;
  EXPECT_EQ(to_hpgl(pg, p, o).find("VS"), std::string::npos);
  o.velocity_cm_s = -1;
  EXPECT_NE(error_of(pg, p, o).find("velocity"), std::string::npos);
  o = {};
  o.newline = true;
  const std::string nl = to_hpgl(pg, p, o);
  EXPECT_EQ(std::count(nl.begin(), nl.end(), '\n'), std::count(nl.begin(), nl.end(), ';'));
  EXPECT_EQ(read_hpgl(nl).runs[0].points, read_hpgl(to_hpgl(pg, p)).runs[0].points);
}

// A range wider than 32767 units: relative moves are split so that every number stays within ±32767.
TEST(HpglDevice, LongRelativeMovesAreSplit) {
  HpglProfile wide;
  wide.name = "wide";
  wide.unit_mm = 0.025;
  wide.ranges = {{"huge", 1500, 1500, -30000, 30000, -30000, 30000, 750, 750}};
  const std::vector<Point2> diag{{1, 1499}, {1499, 1}, {1, 1}};
  const PlotPage pg = page(1500, 1500, {{diag, 1}, {{{1499, 1499}, {1498, 1499}}, 2}});
  const std::string text = to_hpgl(pg, wide);
  const HpglReplay r = read_hpgl(text);
  ASSERT_EQ(r.error, "");  // the reader refuses numbers beyond ±32767
  ASSERT_EQ(r.runs.size(), 2u);
  EXPECT_EQ(r.runs[0].points.front(), (HpglPos{-29960, -29960}));
  EXPECT_EQ(r.runs[0].points.back(), (HpglPos{-29960, 29960}));
  EXPECT_TRUE(std::find(r.runs[0].points.begin(), r.runs[0].points.end(), HpglPos{29960, 29960}) !=
              r.runs[0].points.end());
  EXPECT_EQ(r.runs[1].points.front(), (HpglPos{29960, -29960}));
  for (std::size_t i = 1; i < r.runs[0].points.size(); ++i) {  // the split steps stay on the segment
    const HpglPos a = r.runs[0].points[i - 1], b = r.runs[0].points[i];
    EXPECT_LE(std::labs(b.x - a.x), 32000);
    EXPECT_LE(std::labs(b.y - a.y), 32000);
  }
}

// rotate_180 and a y axis that grows down, on a custom profile.
TEST(HpglDevice, RotationAndYDirection) {
  HpglProfile p;
  p.name = "custom";
  p.unit_mm = 0.1;
  p.ranges = {{"card", 200, 100, 0, 2000, 0, 1000, 0, 0}};
  const PlotPage pg = page(200, 100, {{{{10, 20}, {30, 40}}, 1}});
  EXPECT_EQ(read_hpgl(to_hpgl(pg, p)).runs[0].points, (std::vector<HpglPos>{{100, 800}, {300, 600}}));
  p.y_axis_up = false;
  EXPECT_EQ(read_hpgl(to_hpgl(pg, p)).runs[0].points, (std::vector<HpglPos>{{100, 200}, {300, 400}}));
  p.y_axis_up = true;
  p.rotate_180 = true;
  EXPECT_EQ(read_hpgl(to_hpgl(pg, p)).runs[0].points, (std::vector<HpglPos>{{1900, 200}, {1700, 400}}));
  // Portrait card on the landscape sheet, turned counter-clockwise: page (x, y) → sheet (y, 100 − x), y down.
  const PlotPage tall = page(100, 200, {{{{10, 20}, {30, 40}}, 1}});
  p.rotate_180 = false;
  EXPECT_EQ(read_hpgl(to_hpgl(tall, p)).runs[0].points, (std::vector<HpglPos>{{200, 100}, {400, 300}}));
}

TEST(HpglDevice, GenericTakesAnyPageFromItsBottomLeftCorner) {
  const PlotPage pg = page(100, 50, {{{{0, 0}, {100, 50}}, 8}});
  const HpglReplay r = read_hpgl(to_hpgl(pg, builtin("generic")));
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.runs[0].points, (std::vector<HpglPos>{{0, 2000}, {4000, 0}}));
  // 900 mm is beyond 32767 units: refused, or clipped at 819.175 mm.
  const PlotPage big = page(900, 100, {{{{10, 50}, {890, 50}}, 1}});
  EXPECT_NE(error_of(big, builtin("generic")).find("outside"), std::string::npos);
  HpglOptions clip;
  clip.clip = true;
  EXPECT_EQ(read_hpgl(to_hpgl(big, builtin("generic"), clip)).runs[0].points.back(), (HpglPos{32767, 2000}));
}

// Far-away points: refused with a readable figure, or clipped to the reach (a thousand km away: beyond
// that, Liang–Barsky's parameter cannot resolve the 275 mm of reach and the stroke is dropped).
TEST(HpglDevice, ExtremeCoordinates) {
  const PlotPage far = page(297, 210, {{{{-1e300, 100}, {1e300, 100}}, 1}});
  const std::string e = error_of(far, builtin("hp7475a"));
  EXPECT_NE(e.find("reaches (-1e+300, 100) mm"), std::string::npos) << e;
  HpglOptions clip;
  clip.clip = true;
  const HpglReplay r =
      read_hpgl(to_hpgl(page(297, 210, {{{{-1e9, 100}, {1e9, 100}}, 1}}), builtin("hp7475a"), clip));
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.runs.size(), 1u);
  EXPECT_EQ(r.runs[0].points,
            (std::vector<HpglPos>{{0, a4_landscape({0, 100}).y}, {11040, a4_landscape({0, 100}).y}}));
  EXPECT_NE(error_of(page(1e300, 210), builtin("hp7475a")).find("takes no 1e+300 × 210 mm page"),
            std::string::npos);
  HpglOptions fast;
  fast.velocity_cm_s = 5000;
  EXPECT_NE(error_of(far, builtin("hp7475a"), fast).find("0.01…1000 cm/s"), std::string::npos);
}

TEST(HpglDevice, WriteHpglIsAtomic) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("hlr-hpgl-write-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const PlotPage pg = page(297, 210, {{{{50, 50}, {100, 60}}, 1}});
  write_hpgl(dir / "out.hpgl", pg, builtin("hp7475a"));
  std::ifstream in(dir / "out.hpgl", std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  EXPECT_EQ(s.str(), to_hpgl(pg, builtin("hp7475a")));
  EXPECT_THROW(write_hpgl(dir / "missing" / "out.hpgl", pg, builtin("hp7475a")), DeviceError);
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hlr
