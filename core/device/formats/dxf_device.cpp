// The DXF writer (dxf_device.hpp): group code / value pairs, one to a line each.
#include "core/device/formats/dxf_device.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include "core/device/page/atomic_file.hpp"
#include "core/device/page/page_style.hpp"
#include "core/format_number.hpp"

namespace hlr {
namespace {

class DxfText {
 public:
  void pair(int code, const std::string& value) {
    out_ += std::to_string(code);
    out_ += '\n';
    out_ += value;
    out_ += '\n';
  }
  void pair(int code, int value) { pair(code, std::to_string(value)); }
  // Millimetres to 0.0001, never "-0.0000".
  void number(int code, double value) {
    char text[48];
    std::snprintf(text, sizeof text, "%.4f", value);
    std::string s = text;
    if (s.find_first_not_of("-0.") == std::string::npos) s = "0.0000";
    pair(code, s);
  }
  void point(int code, double x, double y) {
    number(code, x);
    number(code + 10, y);
    number(code + 20, 0);
  }
  std::string& out() { return out_; }

 private:
  std::string out_;
};

// The AutoCAD colour index (ACI) as RGB, 0–255. 1–9 are named colours (7 is drawn black on a white sheet,
// white on a dark screen: black here); 10–249 are 24 hues 15° apart, each at five values (255, 165, 127,
// 76, 38) fully and half saturated — the index's regular construction; AutoCAD's own table strays from it
// in a few dark entries, by less than the gap between neighbouring entries; 250–255 greys.
struct IndexColour {
  int index;
  double r, g, b;
};

std::vector<IndexColour> index_colours() {
  std::vector<IndexColour> out = {{1, 255, 0, 0},   {2, 255, 255, 0},   {3, 0, 255, 0},
                                  {4, 0, 255, 255}, {5, 0, 0, 255},     {6, 255, 0, 255},
                                  {7, 0, 0, 0},     {8, 128, 128, 128}, {9, 192, 192, 192}};
  constexpr double kValues[] = {255, 165, 127, 76, 38};
  for (int i = 10; i < 250; ++i) {
    const int hue = (i - 10) / 10, k = (i - 10) % 10;
    const double v = kValues[k / 2], saturation = k % 2 ? 0.5 : 1;
    // HSV to RGB, truncated as the table is: the hue's sector and how far into it.
    const int sector = hue / 4;
    const double f = (hue % 4) / 4.0;
    const double low = std::floor(v * (1 - saturation)), falling = std::floor(v * (1 - saturation * f)),
                 rising = std::floor(v * (1 - saturation * (1 - f)));
    const double by_sector[6][3] = {{v, rising, low},  {falling, v, low}, {low, v, rising},
                                    {low, falling, v}, {rising, low, v},  {v, low, falling}};
    const double* c = by_sector[sector];
    out.push_back({i, c[0], c[1], c[2]});
  }
  constexpr double kGreys[] = {0, 101, 102, 153, 204, 255};
  for (int i = 250; i < 256; ++i) out.push_back({i, kGreys[i - 250], kGreys[i - 250], kGreys[i - 250]});
  return out;
}

struct LayerKey {
  int pen;
  StrokeLayer layer;
  int level;
  auto tuple() const { return std::tie(pen, layer, level); }
  bool operator<(const LayerKey& o) const { return tuple() < o.tuple(); }
};

LayerKey key_of(const PlotStroke& s) {
  return {s.pen, s.layer,
          s.layer == StrokeLayer::Hidden ? std::max(s.level, 1) : 0};  // plain dashed as level 1
}

// The linetype of hidden strokes at `level` (0: plain dashed, as level 1).
std::string hidden_linetype(int level) { return level <= 1 ? "HIDDEN" : "HIDDEN" + std::to_string(level); }

void linetype(DxfText& d, const std::string& name, const std::string& description, double dash, double gap) {
  d.pair(0, "LTYPE");
  d.pair(2, name);
  d.pair(70, 0);
  d.pair(3, description);
  d.pair(72, 65);  // 'A': alignment, always
  if (dash <= 0) {
    d.pair(73, 0);
    d.number(40, 0);
    return;
  }
  d.pair(73, 2);
  d.number(40, dash + gap);
  d.number(49, dash);
  d.number(49, -gap);
}

}  // namespace

std::string dxf_layer_name(const PlotStroke& stroke) {
  std::string name = "PEN" + std::to_string(stroke.pen);
  if (stroke.layer == StrokeLayer::Hidden) {
    name += "_HIDDEN";
    if (stroke.level > 1) name += "_" + std::to_string(stroke.level);
  } else if (stroke.layer == StrokeLayer::Hatch) {
    name += "_HATCH";
  }
  return name;
}

int dxf_colour_index(const PenStyle& style) {
  static const std::vector<IndexColour> colours = index_colours();
  int best = 7;
  double best_distance = INFINITY;
  // The first nearest: a named colour before a hue or grey that matches it as well.
  for (const IndexColour& c : colours) {
    const double r = style.r * 255 - c.r, g = style.g * 255 - c.g, b = style.b * 255 - c.b;
    const double d = r * r + g * g + b * b;
    if (d < best_distance) {
      best_distance = d;
      best = c.index;
    }
  }
  return best;
}

std::string to_dxf(const PlotPage& page, const DxfOptions& options) {
  if (!(std::isfinite(page.width_mm) && page.width_mm > 0 && std::isfinite(page.height_mm) &&
        page.height_mm > 0))
    throw DeviceError("DXF: the page must be finite and positive, got " +
                      format_mm_for_message(page.width_mm) + " × " + format_mm_for_message(page.height_mm) +
                      " mm");
  std::map<LayerKey, std::string> layers;  // in pen order, visible, hidden by level, hatch
  std::set<int> hidden_levels;
  for (const PlotStroke& s : page.strokes) {
    for (const Point2& p : s.points)
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw DeviceError("DXF: a stroke point is not finite");
    layers.emplace(key_of(s), dxf_layer_name(s));
    if (s.layer == StrokeLayer::Hidden) hidden_levels.insert(std::max(s.level, 1));
  }

  DxfText d;
  d.out().reserve(512 + 120 * page.strokes.size());
  d.pair(999, "hlrscript: exact hidden-line drawing, page millimetres, origin at the bottom-left");
  d.pair(0, "SECTION");
  d.pair(2, "HEADER");
  d.pair(9, "$ACADVER");
  d.pair(1, "AC1009");
  d.pair(9, "$INSUNITS");
  d.pair(70, 4);  // millimetres
  d.pair(9, "$MEASUREMENT");
  d.pair(70, 1);  // metric
  d.pair(9, "$EXTMIN");
  d.point(10, 0, 0);
  d.pair(9, "$EXTMAX");
  d.point(10, page.width_mm, page.height_mm);
  d.pair(9, "$LIMMIN");
  d.number(10, 0);
  d.number(20, 0);
  d.pair(9, "$LIMMAX");
  d.number(10, page.width_mm);
  d.number(20, page.height_mm);
  d.pair(0, "ENDSEC");

  d.pair(0, "SECTION");
  d.pair(2, "TABLES");
  d.pair(0, "TABLE");
  d.pair(2, "LTYPE");
  d.pair(70, static_cast<int>(1 + hidden_levels.size()));
  linetype(d, "CONTINUOUS", "Solid line", 0, 0);
  for (const int level : hidden_levels)
    linetype(d, hidden_linetype(level), "Hidden, level " + std::to_string(level), level_dash_mm(level),
             level_gap_mm(level));
  d.pair(0, "ENDTAB");
  d.pair(0, "TABLE");
  d.pair(2, "LAYER");
  d.pair(70, static_cast<int>(layers.size() + 1));
  d.pair(0, "LAYER");  // every DXF has layer 0
  d.pair(2, "0");
  d.pair(70, 0);
  d.pair(62, 7);
  d.pair(6, "CONTINUOUS");
  for (const auto& [key, name] : layers) {
    d.pair(0, "LAYER");
    d.pair(2, name);
    d.pair(70, 0);
    d.pair(62, dxf_colour_index(options.pens.style(key.pen)));
    d.pair(6, key.layer == StrokeLayer::Hidden ? hidden_linetype(key.level) : "CONTINUOUS");
  }
  d.pair(0, "ENDTAB");
  d.pair(0, "ENDSEC");

  d.pair(0, "SECTION");
  d.pair(2, "ENTITIES");
  const double h = page.height_mm;
  for (const PlotStroke& s : page.strokes) {
    const std::string& layer = layers.at(key_of(s));
    if (s.points.size() == 2) {
      d.pair(0, "LINE");
      d.pair(8, layer);
      d.point(10, s.points[0].x, h - s.points[0].y);
      d.point(11, s.points[1].x, h - s.points[1].y);
      continue;
    }
    const bool closed = s.points.size() > 3 && s.points.front() == s.points.back();
    d.pair(0, "POLYLINE");
    d.pair(8, layer);
    d.pair(66, 1);  // vertices follow
    d.point(10, 0, 0);
    d.pair(70, closed ? 1 : 0);
    const std::size_t n = closed ? s.points.size() - 1 : s.points.size();
    for (std::size_t i = 0; i < n; ++i) {
      d.pair(0, "VERTEX");
      d.pair(8, layer);
      d.point(10, s.points[i].x, h - s.points[i].y);
    }
    d.pair(0, "SEQEND");
    d.pair(8, layer);
  }
  d.pair(0, "ENDSEC");
  d.pair(0, "EOF");
  return std::move(d.out());
}

}  // namespace hlr
