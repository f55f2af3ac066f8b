// The devices against each other through run_cli (tracker issue 4): one frame's strokes in JSON, in the
// generic profile's HPGL (read back by tests/support/hpgl_reader.hpp) and in SVG are the same, in the
// documented plotting order; the PNG shows each pen's colour where its strokes run; and the three pen
// orders draw the same lines, greedy and optimized with the fewest lifts. Every example on every plotter:
// devices_test.cpp.
#include <cairo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <tuple>

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

const fs::path kExamplesDir = fs::path(HLR_TEST_DATA_DIR).parent_path().parent_path() / "examples";

std::string current_test_name() { return test::scratch_name("devagree"); }

// ---- the same strokes on every device ----

constexpr double kUnit = 0.025;  // the generic profile's plotter unit and the JSON plan's grid, mm

struct GridPoint {
  long x = 0, y = 0;
  auto operator<=>(const GridPoint&) const = default;
};

// A drawn stroke in grid units of page mm (y down), with its pen and layer.
struct GridStroke {
  int pen = 1;
  bool hidden = false;
  std::vector<GridPoint> points;
};

struct JsonPlot {
  std::vector<GridStroke> strokes;  // visible, then hidden, each in the file's order
  nlohmann::json stats;
  double page_w = 0, page_h = 0;
};

// A page coordinate in mm as whole grid units; a test failure when it is not one (within 1e-6 mm).
long grid(double mm) {
  const long g = std::lround(mm / kUnit);
  EXPECT_NEAR(g * kUnit, mm, 1e-6) << mm << " mm is not on the 0.025 mm grid";
  return g;
}

JsonPlot json_plot(const fs::path& file, std::size_t frame = 0) {
  JsonPlot out;
  const nlohmann::json doc = nlohmann::json::parse(read_text(file));
  out.page_w = doc["page"]["width_mm"];
  out.page_h = doc["page"]["height_mm"];
  const nlohmann::json& f = doc["frames"].at(frame);
  out.stats = f["stats"];
  for (const bool hidden : {false, true}) {
    const char* key = hidden ? "hidden_strokes" : "strokes";
    const char* pens = hidden ? "hidden_stroke_pens" : "stroke_pens";
    if (!f.contains(key)) continue;
    EXPECT_EQ(f[key].size(), f[pens].size());
    for (std::size_t i = 0; i < f[key].size(); ++i) {
      GridStroke s{f[pens][i].get<int>(), hidden, {}};
      for (const nlohmann::json& p : f[key][i]) s.points.push_back({grid(p[0]), grid(p[1])});
      out.strokes.push_back(std::move(s));
    }
  }
  return out;
}

// The generic profile's HPGL read back to page grid units: origin at the page's bottom-left, y up.
std::vector<GridStroke> hpgl_strokes(const fs::path& file, double page_h_mm) {
  const hlr::test::HpglReplay replay = hlr::test::read_hpgl(read_text(file));
  EXPECT_EQ(replay.error, "");
  const long h = std::lround(page_h_mm / kUnit);
  std::vector<GridStroke> out;
  for (const hlr::test::HpglRun& run : replay.runs) {
    GridStroke s{run.pen, false, {}};
    for (const hlr::test::HpglPos& p : run.points) s.points.push_back({p.x, h - p.y});
    out.push_back(std::move(s));
  }
  return out;
}

// The plotting order the documentation promises: pen by pen in increasing number, within a pen the
// visible layer before the hidden one, each layer's strokes in the order JSON lists them.
std::vector<GridStroke> plotting_order(const std::vector<GridStroke>& strokes) {
  std::vector<GridStroke> out = strokes;
  std::stable_sort(out.begin(), out.end(), [](const GridStroke& a, const GridStroke& b) {
    return std::pair(a.pen, a.hidden) < std::pair(b.pen, b.hidden);
  });
  return out;
}

// Segments as an orientation-free multiset, each split at every stroke point (of either drawing) that
// lies exactly on it: two drawings of the same lines give the same list, however their strokes run.
using Segment = std::tuple<int, bool, GridPoint, GridPoint>;  // pen, hidden, lower end, upper end

std::vector<Segment> unit_segments(const std::vector<GridStroke>& strokes,
                                   const std::vector<GridPoint>& vertices) {
  std::vector<Segment> out;
  for (const GridStroke& s : strokes) {
    for (std::size_t i = 1; i < s.points.size(); ++i) {
      const GridPoint a = s.points[i - 1], b = s.points[i];
      if (a == b) continue;
      std::vector<GridPoint> on = {a, b};
      const long xlo = std::min(a.x, b.x), xhi = std::max(a.x, b.x);
      const long ylo = std::min(a.y, b.y), yhi = std::max(a.y, b.y);
      for (auto it = std::lower_bound(vertices.begin(), vertices.end(), GridPoint{xlo, -(1L << 40)});
           it != vertices.end() && it->x <= xhi; ++it) {
        const GridPoint v = *it;
        if (v.y < ylo || v.y > yhi || v == a || v == b) continue;
        if ((b.x - a.x) * (v.y - a.y) - (b.y - a.y) * (v.x - a.x) == 0) on.push_back(v);
      }
      std::sort(on.begin(), on.end(), [&](GridPoint p, GridPoint q) {
        return (p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y) <
               (q.x - a.x) * (b.x - a.x) + (q.y - a.y) * (b.y - a.y);
      });
      for (std::size_t k = 1; k < on.size(); ++k)
        out.emplace_back(s.pen, s.hidden, std::min(on[k - 1], on[k]), std::max(on[k - 1], on[k]));
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<GridPoint> vertices_of(const std::vector<std::vector<GridStroke>>& drawings) {
  std::vector<GridPoint> v;
  for (const auto& d : drawings)
    for (const GridStroke& s : d) v.insert(v.end(), s.points.begin(), s.points.end());
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

// Three pens declared (one for the hidden layer), one left at its carousel default; boxes in front of
// boxes, so there are hidden lines and T-junctions.
const char* kPenScene =
    "pen 2 (colour: \"#ff0000\", width: 0.5)\n"
    "pen 3 (colour: \"blue\", width: 0.35)\n"
    "pen 4 (colour: \"#00ffff\", width: 0.2)\n"
    "style hidden dashed pen 4\n"
    "draw box(4, 3, 2)\n"
    "draw box(2, 2, 4) at translate(3, -2, 0) pen 2\n"
    "draw cube(2) at translate(-1, -3, 1) pen 3\n"
    "camera main = lookat(eye: (14, -16, 11), target: (2, 0, 1))\n";

TEST(DevicesAgree, JsonAndHpglDrawTheSameStrokes) {
  const test::TempDir dir(current_test_name());
  const std::string script = dir.write("pens.hls", kPenScene).string();
  // Both orders draw the same segments, the caption's single-stroke letters included (a plotter's default,
  // --text stroke for JSON). With `none` both devices keep the pieces in file order, so the
  // strokes correspond one to one; `optimized` plans HPGL from the plotter's home (the generic profile's
  // origin, the page's bottom-left corner) and JSON from the page's top-left, so only the lines agree.
  for (const std::string order : {"none", "optimized"}) {
    SCOPED_TRACE(order);
    const fs::path json = dir.path() / (order + ".json"), hpgl = dir.path() / (order + ".hpgl");
    ASSERT_EQ(run({script, "-o", json.string(), "--pen-order", order, "--text", "stroke"}).code, 0);
    // The hidden layer whole (--dash solid), so that its strokes too correspond one to one
    // (tests/runtime/pipeline/plotter_hidden_lines_test.cpp checks the dashes).
    const Result r =
        run({script, "-o", hpgl.string(), "--plotter", "generic", "--pen-order", order, "--dash", "solid"});
    ASSERT_EQ(r.code, 0) << r.err;
    const JsonPlot j = json_plot(json);
    EXPECT_EQ(j.page_w, 297);
    EXPECT_EQ(j.page_h, 210);
    const std::vector<GridStroke> from_json = plotting_order(j.strokes);
    const std::vector<GridStroke> from_hpgl = hpgl_strokes(hpgl, j.page_h);
    ASSERT_GT(from_json.size(), 10U);
    EXPECT_TRUE(
        std::any_of(from_json.begin(), from_json.end(), [](const GridStroke& s) { return s.hidden; }));
    std::map<int, int> pens;
    for (const GridStroke& s : from_json) ++pens[s.pen];
    EXPECT_EQ(pens.size(), 4U);  // 1, 2, 3 and the hidden layer's 4
    // Same multiset of segments; pens must agree; the hidden layer is plotted with its pen like any other.
    std::vector<GridStroke> json_as_plotted = from_json;
    for (GridStroke& s : json_as_plotted) s.hidden = false;
    const std::vector<GridPoint> v = vertices_of({json_as_plotted, from_hpgl});
    EXPECT_EQ(unit_segments(json_as_plotted, v), unit_segments(from_hpgl, v));
    if (order != "none") continue;
    ASSERT_EQ(from_hpgl.size(), from_json.size());
    for (std::size_t i = 0; i < from_json.size(); ++i) {
      EXPECT_EQ(from_hpgl[i].pen, from_json[i].pen) << "stroke " << i;
      ASSERT_EQ(from_hpgl[i].points.size(), from_json[i].points.size()) << "stroke " << i;
      for (std::size_t k = 0; k < from_json[i].points.size(); ++k) {  // within one plotter unit
        EXPECT_LE(std::labs(from_hpgl[i].points[k].x - from_json[i].points[k].x), 1) << i << "/" << k;
        EXPECT_LE(std::labs(from_hpgl[i].points[k].y - from_json[i].points[k].y), 1) << i << "/" << k;
      }
    }
  }
}

// One SVG <path> per run of strokes of one pen and layer; its subpaths are the JSON strokes, in order.
struct SvgPath {
  std::map<std::string, std::string> style;
  std::vector<std::vector<Point2>> subpaths;
};

std::vector<SvgPath> svg_paths(const std::string& svg) {
  std::vector<SvgPath> out;
  const std::regex path_re(R"re(<path style="([^"]*)" d="([^"]*)"\s*/>)re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path_re); it != std::sregex_iterator(); ++it) {
    SvgPath p;
    std::istringstream style((*it)[1].str());
    for (std::string item; std::getline(style, item, ';');) {
      const std::size_t colon = item.find(':');
      if (colon != std::string::npos) p.style[item.substr(0, colon)] = item.substr(colon + 1);
    }
    std::istringstream d((*it)[2].str());
    for (std::string op; d >> op;) {
      if (op == "Z") continue;
      double x = 0, y = 0;
      d >> x >> y;
      if (op == "M") p.subpaths.emplace_back();
      EXPECT_TRUE(op == "M" || op == "L") << "unexpected path command " << op;
      if (!p.subpaths.empty()) p.subpaths.back().push_back({x, y});
    }
    out.push_back(std::move(p));
  }
  return out;
}

TEST(DevicesAgree, SvgPathsArePenGroupsOfTheJsonStrokes) {
  const test::TempDir dir(current_test_name());
  const std::string script = dir.write("pens.hls", kPenScene).string();
  const fs::path json = dir.path() / "x.json", svg = dir.path() / "x.svg";
  ASSERT_EQ(run({script, "-o", json.string()}).code, 0);
  ASSERT_EQ(run({script, "-o", svg.string(), "--plain"}).code, 0);
  const std::vector<GridStroke> strokes = plotting_order(json_plot(json).strokes);
  const std::vector<SvgPath> paths = svg_paths(read_text(svg));
  // Pen 1 is the carousel's black at the default 0.25 mm; hidden lines are 2 mm dashes and 1.2 mm gaps
  // as seen, the round caps included: dash 2 − w, gap 1.2 + w for the 0.2 mm pen 4.
  struct Group {
    int pen;
    bool hidden;
    const char* colour;
    const char* width;
  };
  const Group groups[] = {{1, false, "rgb(0%,0%,0%)", "0.25"},
                          {2, false, "rgb(100%,0%,0%)", "0.5"},
                          {3, false, "rgb(0%,0%,100%)", "0.35"},
                          {4, true, "rgb(0%,100%,100%)", "0.2"}};
  ASSERT_EQ(paths.size(), 4U);
  std::size_t next = 0;
  for (std::size_t g = 0; g < 4; ++g) {
    SCOPED_TRACE("pen " + std::to_string(groups[g].pen));
    const SvgPath& p = paths[g];
    EXPECT_EQ(p.style.at("stroke"), groups[g].colour);
    EXPECT_EQ(p.style.at("stroke-width"), groups[g].width);
    EXPECT_EQ(p.style.at("stroke-linecap"), "round");
    if (groups[g].hidden) {
      ASSERT_TRUE(p.style.count("stroke-dasharray"));
      double dash = 0, gap = 0;
      char comma = 0;
      std::istringstream(p.style.at("stroke-dasharray")) >> dash >> comma >> gap;
      EXPECT_NEAR(dash, 1.8, 1e-6);
      EXPECT_NEAR(gap, 1.4, 1e-6);
    } else {
      EXPECT_FALSE(p.style.count("stroke-dasharray"));
    }
    for (const std::vector<Point2>& sub : p.subpaths) {
      ASSERT_LT(next, strokes.size());
      const GridStroke& s = strokes[next++];
      EXPECT_EQ(s.pen, groups[g].pen);
      EXPECT_EQ(s.hidden, groups[g].hidden);
      ASSERT_EQ(sub.size(), s.points.size()) << "stroke " << next - 1;
      for (std::size_t k = 0; k < sub.size(); ++k) {  // cairo writes 1/256 user units
        EXPECT_NEAR(sub[k].x, s.points[k].x * kUnit, 0.005);
        EXPECT_NEAR(sub[k].y, s.points[k].y * kUnit, 0.005);
      }
    }
  }
  EXPECT_EQ(next, strokes.size());
}

// The PNG shows each pen in its colour where JSON says its strokes run.
TEST(DevicesAgree, PngShowsThePenColoursWhereTheStrokesAre) {
  const test::TempDir dir(current_test_name());
  const std::string script = dir.write("pens.hls", kPenScene).string();
  const fs::path json = dir.path() / "x.json", png = dir.path() / "x.png";
  ASSERT_EQ(run({script, "-o", json.string()}).code, 0);
  ASSERT_EQ(run({script, "-o", png.string(), "--plain", "--dpi", "200"}).code, 0);
  cairo_surface_t* s = cairo_image_surface_create_from_png(png.c_str());
  ASSERT_EQ(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
  const int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
  const int stride = cairo_image_surface_get_stride(s);
  const unsigned char* data = cairo_image_surface_get_data(s);
  // Which colour is within 1 px of (x, y): 'k' black, 'r' red, 'b' blue, 'c' cyan.
  const auto colours_near = [&](double x, double y) {
    std::string found;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int px = static_cast<int>(x) + dx, py = static_cast<int>(y) + dy;
        if (px < 0 || py < 0 || px >= w || py >= h) continue;
        const std::uint32_t v = *reinterpret_cast<const std::uint32_t*>(data + py * stride + 4 * px);
        const int r = (v >> 16) & 0xff, g = (v >> 8) & 0xff, b = v & 0xff;
        if (r < 80 && g < 80 && b < 80) found += 'k';
        if (r > 200 && g < 80 && b < 80) found += 'r';
        if (r < 80 && g < 80 && b > 200) found += 'b';
        if (r < 80 && g > 200 && b > 200) found += 'c';
      }
    return found;
  };
  const char expected[] = {'?', 'k', 'r', 'b', 'c'};
  std::map<int, std::pair<int, int>> hits;  // pen → (midpoints showing the pen's colour, midpoints tested)
  const double px_per_unit = 200 / 25.4 * kUnit;
  for (const GridStroke& st : json_plot(json).strokes) {
    for (std::size_t i = 1; i < st.points.size(); ++i) {
      const GridPoint a = st.points[i - 1], b = st.points[i];
      if (std::hypot(b.x - a.x, b.y - a.y) * px_per_unit < 12) continue;  // too short to find a dash on
      auto& [shown, tested] = hits[st.pen];
      ++tested;
      // A dashed line may have a gap at the midpoint: look at points a tenth of the way on either side too.
      bool seen = false;
      for (const double t : {0.4, 0.5, 0.6}) {
        const double x = (a.x + t * (b.x - a.x)) * px_per_unit, y = (a.y + t * (b.y - a.y)) * px_per_unit;
        seen = seen || colours_near(x, y).find(expected[st.pen]) != std::string::npos;
      }
      shown += seen ? 1 : 0;
    }
  }
  cairo_surface_destroy(s);
  ASSERT_EQ(hits.size(), 4U);
  for (const auto& [pen, count] : hits) {
    EXPECT_GT(count.second, 3) << "pen " << pen;
    EXPECT_GE(count.first, 0.9 * count.second) << "pen " << pen;
  }
}

// ---- pen orders: the same lines, differently ordered ----

// The largest distance (grid units) from a point of `a`'s strokes (every 2 units along them) to the
// nearest segment of `b`'s with the same pen and layer.
double farthest_from(const std::vector<GridStroke>& a, const std::vector<GridStroke>& b) {
  struct Seg {
    int pen;
    bool hidden;
    double ax, ay, bx, by;
  };
  constexpr double kCell = 64;
  std::map<std::pair<long, long>, std::vector<Seg>> cells;
  for (const GridStroke& s : b)
    for (std::size_t i = 1; i < s.points.size(); ++i) {
      const Seg g{s.pen,
                  s.hidden,
                  double(s.points[i - 1].x),
                  double(s.points[i - 1].y),
                  double(s.points[i].x),
                  double(s.points[i].y)};
      for (long cx = std::lround(std::floor(std::min(g.ax, g.bx) / kCell));
           cx <= std::lround(std::floor(std::max(g.ax, g.bx) / kCell)); ++cx)
        for (long cy = std::lround(std::floor(std::min(g.ay, g.by) / kCell));
             cy <= std::lround(std::floor(std::max(g.ay, g.by) / kCell)); ++cy)
          cells[{cx, cy}].push_back(g);
    }
  const auto distance = [](double px, double py, const Seg& g) {
    const double dx = g.bx - g.ax, dy = g.by - g.ay, l = dx * dx + dy * dy;
    const double t = l == 0 ? 0 : std::clamp(((px - g.ax) * dx + (py - g.ay) * dy) / l, 0.0, 1.0);
    return std::hypot(px - g.ax - t * dx, py - g.ay - t * dy);
  };
  double worst = 0;
  for (const GridStroke& s : a)
    for (std::size_t i = 1; i < s.points.size(); ++i) {
      const double ax = s.points[i - 1].x, ay = s.points[i - 1].y, bx = s.points[i].x, by = s.points[i].y;
      const int n = std::max(1, static_cast<int>(std::hypot(bx - ax, by - ay) / 2));
      for (int k = 0; k <= n; ++k) {
        const double px = ax + (bx - ax) * k / n, py = ay + (by - ay) * k / n;
        double best = 1e9;
        const long cx = std::lround(std::floor(px / kCell)), cy = std::lround(std::floor(py / kCell));
        for (long x = cx - 1; x <= cx + 1; ++x)
          for (long y = cy - 1; y <= cy + 1; ++y) {
            const auto it = cells.find({x, y});
            if (it == cells.end()) continue;
            for (const Seg& g : it->second)
              if (g.pen == s.pen && g.hidden == s.hidden) best = std::min(best, distance(px, py, g));
          }
        worst = std::max(worst, best);
      }
    }
  return worst;
}

double pen_down_units(const std::vector<GridStroke>& strokes) {
  double sum = 0;
  for (const GridStroke& s : strokes)
    for (std::size_t i = 1; i < s.points.size(); ++i)
      sum += std::hypot(s.points[i].x - s.points[i - 1].x, s.points[i].y - s.points[i - 1].y);
  return sum;
}

class PenOrders : public ::testing::TestWithParam<std::string> {};

// greedy and optimized draw the same segments exactly (both merge the drawing graph the same way);
// none keeps the pieces as given, unmerged, so its lines may sit up to the planner's 1.5-unit T-junction
// tolerance away, with the same ink length.
TEST_P(PenOrders, DrawTheSameLines) {
  const test::TempDir dir(current_test_name());
  const bool own = GetParam() == "pens";
  const std::string script =
      own ? dir.write("pens.hls", kPenScene).string() : (kExamplesDir / GetParam()).string();
  std::map<std::string, JsonPlot> plots;
  for (const std::string order : {"none", "greedy", "optimized"}) {
    const fs::path json = dir.path() / (order + ".json");
    const Result r = run({script, "-o", json.string(), "--pen-order", order});
    ASSERT_EQ(r.code, 0) << r.err;
    plots[order] = json_plot(json);
    const nlohmann::json& st = plots[order].stats;
    EXPECT_EQ(st["pen_order"], order);
    EXPECT_GE(st["lifts"].get<int>(), st["lift_lower_bound"].get<int>()) << order;
    EXPECT_EQ(st["lifts"].get<std::size_t>(), plots[order].strokes.size()) << order;
    if (order != "none") {
      EXPECT_EQ(st["lifts"], st["lift_lower_bound"]) << order;
    }
  }
  EXPECT_EQ(plots["none"].stats["lift_lower_bound"], plots["greedy"].stats["lift_lower_bound"]);
  EXPECT_EQ(plots["optimized"].stats["lift_lower_bound"], plots["greedy"].stats["lift_lower_bound"]);
  const auto& none = plots["none"].strokes;
  const auto& greedy = plots["greedy"].strokes;
  const auto& optimized = plots["optimized"].strokes;
  const std::vector<GridPoint> v = vertices_of({greedy, optimized});
  const std::vector<Segment> g = unit_segments(greedy, v);
  EXPECT_EQ(g, unit_segments(optimized, v));
  EXPECT_TRUE(std::adjacent_find(g.begin(), g.end()) == g.end()) << "a segment drawn twice";
  EXPECT_LE(farthest_from(none, greedy), 1.5);
  EXPECT_LE(farthest_from(greedy, none), 1.5);
  EXPECT_NEAR(pen_down_units(none), pen_down_units(greedy), 2 + 1e-5 * pen_down_units(none));
}

INSTANTIATE_TEST_SUITE_P(Devices, PenOrders,
                         ::testing::Values("pens", "showcase/gear.hls", "desens/carrier-2.hls",
                                           "showcase/pens-and-plotter.hls"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace hlr::runtime
