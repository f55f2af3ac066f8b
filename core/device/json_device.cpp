#include "core/device/json_device.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "core/device/atomic_file.hpp"

namespace hlr {
namespace {

// Keys keep the schema's order (ordered_json), so the text reads like the documentation and is stable.
using Json = nlohmann::ordered_json;

// The grid strokes are snapped to before joining: far below any pen's resolution, far above rounding noise.
constexpr double kSnapPerMm = 1e6;

double snap(double mm) {
  // Beyond 1e15 mm a double's spacing already exceeds the grid, and the product could overflow.
  return std::fabs(mm) < 1e15 ? std::round(mm * kSnapPerMm) / kSnapPerMm : mm;
}

using Polyline = std::vector<Point2>;

double polyline_length(const Polyline& line) {
  double sum = 0;
  for (std::size_t i = 1; i < line.size(); ++i) sum += distance(line[i - 1], line[i]);
  return sum;
}

// One frame's conversion; `where` prefixes every error so the caller can find the offending frame.
class FrameWriter {
 public:
  FrameWriter(const JsonFrame& frame, const JsonOptions& options, const PageSpec& spec)
      : f_(frame), o_(options), where_("frame " + std::to_string(frame.frame) + ": ") {
    layout_ = fit_to_page(f_.camera.frame, f_.segments, spec);
  }

  Json build() const {
    Json j;
    j["frame"] = f_.frame;
    j["time"] = number(f_.time, "time");
    j["camera"] = camera();
    const Point2 origin = layout_.origin();
    j["layout"] = {
        {"mm_per_unit", number(layout_.scale, "layout scale")},
        {"origin_mm", Json::array({number(origin.x, "layout origin"), number(origin.y, "layout origin")})}};
    Json segments = Json::array();
    std::size_t visible = 0;
    for (const VisibleSegment& s : f_.segments) {
      if (!s.hidden) ++visible;
      if (s.hidden && !o_.include_hidden) continue;
      segments.push_back(segment(s));
    }
    j["segments"] = std::move(segments);
    const std::vector<Polyline> strokes = build_strokes(false);
    j["strokes"] = strokes_json(strokes);
    if (o_.include_hidden) j["hidden_strokes"] = strokes_json(build_strokes(true));
    j["stats"] = stats(strokes, visible);
    return j;
  }

 private:
  double number(double v, std::string_view what) const {
    if (!std::isfinite(v))
      throw DeviceError(where_ + "non-finite " + std::string(what) + " cannot be written");
    return v;
  }
  Json point(Point3 p, std::string_view what) const {
    return Json::array({number(p.x, what), number(p.y, what), number(p.z, what)});
  }
  Json vec(Vector3 v, std::string_view what) const {
    return Json::array({number(v.x, what), number(v.y, what), number(v.z, what)});
  }
  Json point(Point2 p, std::string_view what) const {
    return Json::array({number(p.x, what), number(p.y, what)});
  }

  const std::string& name(std::uint32_t object) const {
    if (object >= f_.object_names.size())
      throw DeviceError(where_ + "segment refers to object " + std::to_string(object) + " but only " +
                        std::to_string(f_.object_names.size()) + " object names were given");
    return f_.object_names[object];
  }

  Json camera() const {
    const Camera& c = f_.camera;
    Point3 eye;
    Vector3 direction;
    try {
      eye = c.eye_world();
      direction = c.direction_world();
    } catch (const std::domain_error& e) {
      throw DeviceError(where_ + "camera has a singular view transform (" + e.what() + ")");
    }
    Json j;
    j["kind"] = c.projection == Projection::Perspective ? "perspective" : "orthographic";
    j["constructor"] = c.kind;
    j["eye"] = point(eye, "camera eye");
    j["direction"] = vec(direction, "camera direction");
    j["focal"] = number(c.focal, "camera focal");
    j["offset"] = point(Point2{c.offset.x, c.offset.y}, "camera offset");
    if (c.projection == Projection::Perspective) j["near_depth"] = number(c.near_depth, "camera near_depth");
    if (c.frame) {
      const Rect2& r = *c.frame;
      j["frame"] = Json::array({number(r.xmin, "camera frame"), number(r.ymin, "camera frame"),
                                number(r.xmax, "camera frame"), number(r.ymax, "camera frame")});
    }
    Json m = Json::array();
    for (int i = 0; i < 3; ++i) m.push_back(vec(c.viewFromWorld.row(i), "camera view_from_world"));
    j["view_from_world"] = {{"m", std::move(m)}, {"t", vec(c.viewFromWorld.t, "camera view_from_world")}};
    return j;
  }

  Json segment(const VisibleSegment& s) const {
    Json j;
    j["p"] = Json::array({point(s.p0, "segment end point"), point(s.p1, "segment end point")});
    j["s"] = Json::array({point(s.s0, "segment picture point"), point(s.s1, "segment picture point")});
    j["object"] = name(s.object);
    if (s.source == SegmentSource::Intersection)
      j["other"] = name(s.other);
    else
      j["edge"] = s.edge;
    j["hidden"] = s.hidden;
    return j;
  }

  Point2 page_point(Point2 picture) const {
    const Point2 mm = layout_.to_page_mm(picture);
    return {snap(number(mm.x, "page coordinate")), snap(number(mm.y, "page coordinate"))};
  }

  // Pieces in the engine's order; a piece continues the previous stroke only when it starts exactly where
  // that stroke ends on the snap grid (no reversal, no reordering: that is pen planning's job).
  std::vector<Polyline> build_strokes(bool hidden) const {
    std::vector<Polyline> strokes;
    for (const VisibleSegment& s : f_.segments) {
      if (s.hidden != hidden) continue;
      const Point2 a = page_point(s.s0), b = page_point(s.s1);
      if (a == b) continue;  // nothing to draw at this resolution
      if (!strokes.empty() && strokes.back().back() == a)
        strokes.back().push_back(b);
      else
        strokes.push_back({a, b});
    }
    return strokes;
  }

  Json strokes_json(const std::vector<Polyline>& strokes) const {
    Json out = Json::array();
    for (const Polyline& line : strokes) {
      Json j = Json::array();
      for (const Point2 p : line) j.push_back(Json::array({p.x, p.y}));
      out.push_back(std::move(j));
    }
    return out;
  }

  Json stats(const std::vector<Polyline>& strokes, std::size_t visible) const {
    double down = 0, up = 0;
    Point2 pen{0, 0};  // the page origin
    for (const Polyline& line : strokes) {
      up += distance(pen, line.front());
      down += polyline_length(line);
      pen = line.back();
    }
    if (!strokes.empty()) up += distance(pen, Point2{0, 0});
    Json j;
    j["segments"] = visible;
    j["pen_down_mm"] = number(down, "pen-down length");
    j["pen_up_mm"] = number(up, "pen-up travel");
    j["lifts"] = strokes.size();
    return j;
  }

  const JsonFrame& f_;
  const JsonOptions& o_;
  std::string where_;
  PageLayout layout_;
};

// Nesting depth: a scalar is 0, a container one more than its deepest member.
int depth(const Json& v) {
  if (!v.is_structured()) return 0;
  int d = 0;
  for (const Json& member : v) d = std::max(d, depth(member));
  return d + 1;
}

// Indented output with the leaves kept on one line: a segment object ({"p": [[..],[..]], ...}, depth 3)
// or a stroke ([[x,y], ...], depth 2) is one line, so large frames stay readable and diffable.
void write_pretty(const Json& v, int indent, std::string& out) {
  const bool leaf = indent > 0 && (v.is_object() ? depth(v) <= 3 : depth(v) <= 2);
  if (leaf || v.empty()) {
    out += v.dump();
    return;
  }
  const std::string inner(static_cast<std::size_t>(indent + 2), ' ');
  out += v.is_object() ? "{\n" : "[\n";
  bool first = true;
  for (auto it = v.begin(); it != v.end(); ++it) {
    if (!first) out += ",\n";
    first = false;
    out += inner;
    if (v.is_object()) out += Json(it.key()).dump() + ": ";
    write_pretty(*it, indent + 2, out);
  }
  out += '\n';
  out.append(static_cast<std::size_t>(indent), ' ');
  out += v.is_object() ? '}' : ']';
}

}  // namespace

std::string to_json_text(const std::vector<JsonFrame>& frames, const JsonOptions& options) {
  const PageSpec spec{options.paper, options.margin_mm};
  check_page_spec(spec);
  Json doc;
  doc["format"] = kJsonLinesFormat;
  if (!options.title.empty()) doc["title"] = options.title;
  doc["page"] = {{"width_mm", options.paper.width_mm},
                 {"height_mm", options.paper.height_mm},
                 {"margin_mm", options.margin_mm},
                 {"origin", "top-left"},
                 {"y", "down"}};
  Json list = Json::array();
  for (const JsonFrame& f : frames) list.push_back(FrameWriter(f, options, spec).build());
  doc["frames"] = std::move(list);
  std::string text;
  try {
    // Invalid UTF-8 in a name or title throws here rather than writing a file no reader accepts.
    if (options.pretty)
      write_pretty(doc, 0, text);
    else
      text = doc.dump();
  } catch (const nlohmann::json::exception& e) {
    throw DeviceError(std::string("cannot encode JSON: ") + e.what());
  }
  text += '\n';
  return text;
}

void write_json(const std::filesystem::path& target, const std::vector<JsonFrame>& frames,
                const JsonOptions& options) {
  // Encode first: a bad frame fails before any file is created.
  std::string text;
  try {
    text = to_json_text(frames, options);
  } catch (const DeviceError& e) {
    throw DeviceError("cannot write '" + target.string() + "': " + e.what());
  }
  write_atomically(target, [&](const std::filesystem::path& temp) {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot create '" + temp.string() + "'");
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) throw std::runtime_error("write to '" + temp.string() + "' failed");
  });
}

}  // namespace hlr
