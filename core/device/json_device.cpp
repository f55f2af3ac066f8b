#include "core/device/json_device.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "core/device/atomic_file.hpp"
#include "core/device/page_layout.hpp"

namespace hlr {
namespace {

// Keys keep the schema's order (ordered_json), so the text reads like the documentation and is stable.
using Json = nlohmann::ordered_json;

// One frame's conversion; `where` prefixes every error so the caller can find the offending frame.
class FrameWriter {
 public:
  FrameWriter(const JsonFrame& frame, const JsonOptions& options)
      : f_(frame),
        o_(options),
        where_("frame " + std::to_string(frame.frame) + ": "),
        layout_(frame.plot.layout) {}

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
    j["strokes"] = strokes_json(StrokeLayer::Visible);
    j["stroke_pens"] = pens_json(StrokeLayer::Visible);
    if (o_.include_hidden) {
      j["hidden_strokes"] = strokes_json(StrokeLayer::Hidden);
      j["hidden_stroke_pens"] = pens_json(StrokeLayer::Hidden);
    }
    j["stats"] = stats(visible);
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

  Json strokes_json(StrokeLayer layer) const {
    Json out = Json::array();
    for (const PlotStroke& stroke : f_.plot.page.strokes) {
      if (stroke.layer != layer) continue;
      Json j = Json::array();
      for (const Point2 p : stroke.points) j.push_back(point(p, "stroke point"));
      out.push_back(std::move(j));
    }
    return out;
  }

  Json pens_json(StrokeLayer layer) const {
    Json out = Json::array();
    for (const PlotStroke& stroke : f_.plot.page.strokes)
      if (stroke.layer == layer) out.push_back(stroke.pen);
    return out;
  }

  Json stats(std::size_t visible) const {
    const PlanStats& s = f_.plot.stats;
    Json j;
    j["segments"] = visible;
    j["pen_down_mm"] = number(s.pen_down_mm, "pen-down length");
    j["pen_up_mm"] = number(s.pen_up_mm, "pen-up travel");
    j["pen_up_mean_mm"] = number(s.pen_up_mean_mm, "pen-up mean");
    j["pen_up_median_mm"] = number(s.pen_up_median_mm, "pen-up median");
    j["lifts"] = s.lifts;
    j["lift_lower_bound"] = s.lift_lower_bound;
    j["plot_seconds"] = number(s.plot_seconds, "plotting time");
    j["pen_order"] = o_.pen_order;
    return j;
  }

  const JsonFrame& f_;
  const JsonOptions& o_;
  std::string where_;
  const PageLayout& layout_;
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

namespace {

Json document_head(const PlotPage& page, const JsonOptions& options) {
  Json doc;
  doc["format"] = kJsonLinesFormat;
  if (!options.title.empty()) doc["title"] = options.title;
  // A non-finite or roomless page would print as null or describe no drawable area.
  check_page_spec({{page.width_mm, page.height_mm}, page.margin_mm});
  doc["page"] = {{"width_mm", page.width_mm},
                 {"height_mm", page.height_mm},
                 {"margin_mm", page.margin_mm},
                 {"origin", "top-left"},
                 {"y", "down"}};
  return doc;
}

// Invalid UTF-8 in a name or title throws here rather than writing a file no reader accepts.
std::string encode(const Json& v, bool pretty, int indent) {
  std::string text;
  try {
    if (pretty)
      write_pretty(v, indent, text);
    else
      text = v.dump();
  } catch (const nlohmann::json::exception& e) {
    throw DeviceError(std::string("cannot encode JSON: ") + e.what());
  }
  return text;
}

}  // namespace

// The document is written in pieces so that frames can be encoded apart and streamed: the head (every
// key before "frames", which comes last), each frame, the tail. Joined, they are exactly the text
// write_pretty() or dump() gives for the whole document.
std::string json_document_head(const PlotPage& first_page, const JsonOptions& options) {
  std::string text = encode(document_head(first_page, options), options.pretty, 0);
  text.pop_back();  // the closing brace
  if (options.pretty) {
    text.pop_back();  // and the newline before it
    return text + ",\n  \"frames\": [";
  }
  return text + ",\"frames\":[";
}

std::string json_frame_text(const JsonFrame& frame, const JsonOptions& options) {
  return encode(FrameWriter(frame, options).build(), options.pretty, 4);
}

std::string json_frame_separator(bool first, const JsonOptions& options) {
  if (options.pretty) return first ? "\n    " : ",\n    ";
  return first ? "" : ",";
}

std::string json_document_tail(std::size_t frames, const JsonOptions& options) {
  if (!options.pretty) return "]}\n";
  return frames == 0 ? "]\n}\n" : "\n  ]\n}\n";
}

std::string to_json_text(const std::vector<JsonFrame>& frames, const JsonOptions& options) {
  // Every frame of one file shares the page (the runtime groups frames by file and paper); without a
  // frame the default page is reported.
  const PlotPage default_page;
  std::string text = json_document_head(frames.empty() ? default_page : frames.front().plot.page, options);
  for (std::size_t i = 0; i < frames.size(); ++i)
    text += json_frame_separator(i == 0, options) + json_frame_text(frames[i], options);
  return text + json_document_tail(frames.size(), options);
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
