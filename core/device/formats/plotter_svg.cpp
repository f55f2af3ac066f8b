#include "core/device/formats/plotter_svg.hpp"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/device/page/atomic_file.hpp"
#include "core/device/page/page_style.hpp"
#include "core/format_number.hpp"
#include "core/geometry/clip2d.hpp"
#include "core/tolerance.hpp"

namespace hlr {
namespace {

// Millimetres to 0.001 mm, trailing zeros dropped, never "-0".
void append_mm(std::string& out, double v) {
  double rounded = std::round(v * 1000) / 1000;
  if (rounded == 0) rounded = 0;  // -0 → 0
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, rounded, std::chars_format::fixed, 3);
  std::size_t n = static_cast<std::size_t>(r.ptr - buf);
  while (n > 0 && buf[n - 1] == '0') --n;
  if (n > 0 && buf[n - 1] == '.') --n;
  out.append(buf, n);
}

std::string mm_text(double v) {
  std::string s;
  append_mm(s, v);
  return s;
}

// Text in an attribute or element: the five XML specials escaped, control characters dropped.
std::string xml_text(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        if (static_cast<unsigned char>(c) >= 0x20) out += c;
    }
  }
  return out;
}

// A layer: a pen, whether it holds that pen's hidden strokes, and their occlusion level (0: not counted).
// Visible layers come before hidden ones of the same pen, hidden ones by level: the plan's order.
using LayerKey = std::tuple<int, StrokeLayer, int>;  // (pen, layer, level)

// The pieces of one stroke to draw: itself, or with `clip` the parts on the page.
// `page` has a hair of slack for rounding in the layout; cuts are made at the page's exact edge, `cut`.
std::vector<std::vector<Point2>> pieces_on_page(const PlotStroke& stroke, const Rect2& page, const Rect2& cut,
                                                bool clip, std::size_t index) {
  for (const Point2& p : stroke.points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw DeviceError("plotter SVG: stroke " + std::to_string(index) + " has a point that is not finite");
  if (!clip) {
    for (const Point2& p : stroke.points)
      if (!page.contains(p))
        throw DeviceError("plotter SVG: the point (" + format_mm_for_message(p.x) + ", " +
                          format_mm_for_message(p.y) + ") mm lies off the " +
                          format_mm_for_message(page.xmax) + " × " + format_mm_for_message(page.ymax) +
                          " mm page; use a smaller scale or a bigger paper, or cut it with --clip");
    return {stroke.points};
  }
  std::vector<std::vector<Point2>> pieces;
  clip_polyline_to_rect(
      stroke.points, cut, [&](Point2 p) { pieces.push_back({p}); },
      [&](Point2 p) { pieces.back().push_back(p); });
  return pieces;
}

void append_path(std::string& out, const std::vector<Point2>& points, std::size_t id, std::size_t piece) {
  out += "    <path id=\"s";
  out += std::to_string(id);
  if (piece > 0) out += "-" + std::to_string(piece);
  out += "\" d=\"M";
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i == 1) out += " L";
    out += ' ';
    append_mm(out, points[i].x);
    out += ',';
    append_mm(out, points[i].y);
  }
  out += "\"/>\n";
}

}  // namespace

std::string plotter_svg_layer_label(int pen, const PenStyle& style, StrokeLayer layer, int level) {
  if (layer == StrokeLayer::Hidden)
    return std::to_string(pen) + " hidden" + (level > 0 ? " " + std::to_string(level) : "");
  if (layer == StrokeLayer::Hatch) return std::to_string(pen) + " hatch";
  return std::to_string(pen) + " " + colour_text({style.r, style.g, style.b});
}

std::string to_plotter_svg(const PlotPage& page, const PlotterSvgOptions& options) {
  if (!(std::isfinite(page.width_mm) && page.width_mm > 0 && std::isfinite(page.height_mm) &&
        page.height_mm > 0))
    throw DeviceError("plotter SVG: the page must be finite and positive, got " +
                      format_mm_for_message(page.width_mm) + " × " + format_mm_for_message(page.height_mm) +
                      " mm");
  // Points on the edge belong to the page; rounding in the layout may put them a hair beyond it.
  const double slack = Tolerance::kPageEdgeRelative * (page.width_mm + page.height_mm);
  const Rect2 sheet{-slack, -slack, page.width_mm + slack, page.height_mm + slack};

  // Each layer's paths, in planned order; the layers in pen order.
  std::map<LayerKey, std::string> layers;
  for (std::size_t i = 0; i < page.strokes.size(); ++i) {
    const PlotStroke& stroke = page.strokes[i];
    const bool hidden = stroke.layer == StrokeLayer::Hidden;
    std::string& paths = layers[{stroke.pen, stroke.layer, hidden ? stroke.level : 0}];
    const auto pieces = pieces_on_page(stroke, sheet, {0, 0, page.width_mm, page.height_mm}, options.clip, i);
    for (std::size_t k = 0; k < pieces.size(); ++k) append_path(paths, pieces[k], i, k);
  }

  std::string out;
  out.reserve(256 + 40 * page.strokes.size());
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";
  out +=
      "<svg xmlns=\"http://www.w3.org/2000/svg\" "
      "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" version=\"1.1\" width=\"";
  out += mm_text(page.width_mm) + "mm\" height=\"" + mm_text(page.height_mm) + "mm\" viewBox=\"0 0 " +
         mm_text(page.width_mm) + " " + mm_text(page.height_mm) + "\">\n";
  if (!options.title.empty()) out += "  <title>" + xml_text(options.title) + "</title>\n";
  for (const auto& [key, paths] : layers) {
    const auto [pen, layer, level] = key;
    const bool hidden = layer == StrokeLayer::Hidden;
    const PenStyle style = options.pens.style(pen);
    // The digits, not a name: SVG's names differ from ours for some colours (CSS green is half green).
    char hex[8];
    const auto byte = [](double v) { return static_cast<unsigned>(std::lround(v * 255)); };
    std::snprintf(hex, sizeof hex, "#%02x%02x%02x", byte(style.r), byte(style.g), byte(style.b));
    const std::string id = std::to_string(pen) + (hidden ? "-hidden" : "") +
                           (layer == StrokeLayer::Hatch ? "-hatch" : "") +
                           (level > 0 ? "-" + std::to_string(level) : std::string());
    out += "  <g inkscape:groupmode=\"layer\" id=\"layer-" + id + "\" inkscape:label=\"" +
           xml_text(plotter_svg_layer_label(pen, style, layer, level)) + "\" fill=\"none\" stroke=\"" +
           std::string(hex) + "\" stroke-width=\"" + mm_text(style.width_mm) +
           "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"";
    if (hidden) {
      out += " stroke-dasharray=\"";
      append_mm(out, dash_on_mm(style.width_mm, level));
      out += ' ';
      append_mm(out, dash_off_mm(style.width_mm, level));
      out += '"';
    }
    out += ">\n" + paths + "  </g>\n";
  }
  out += "</svg>\n";
  return out;
}

}  // namespace hlr
