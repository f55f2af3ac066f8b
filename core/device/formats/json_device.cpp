#include "core/device/formats/json_device.hpp"

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string_view>

#include "core/device/formats/json_text.hpp"
#include "core/device/page/atomic_file.hpp"
#include "core/device/page/page_layout.hpp"

namespace hlr {
namespace {

// Appends JSON text in the layout of the schema: with `pretty`, the document's containers open one
// member a line, indented, while each leaf value — a segment, a stroke, a point, the layout, the stats —
// stays on one line without spaces, so large frames read and diff line by line; without, one line.
class JsonWriter {
 public:
  JsonWriter(std::string& out, bool pretty, std::string where)
      : out_(out), pretty_(pretty), where_(std::move(where)) {}

  std::string& out() { return out_; }
  const std::string& where() const { return where_; }

  // The member `key` of an expanded object at `indent`: a comma unless it is the first, the line break
  // and indentation when pretty, the quoted key.
  void member(const char* key, int indent, bool first) {
    if (!first) out_ += ',';
    line(indent);
    out_ += '"';
    out_ += key;
    out_ += pretty_ ? "\": " : "\":";
  }
  // A member inside a leaf (always compact).
  void leaf_member(const char* key, bool first) {
    if (!first) out_ += ',';
    out_ += '"';
    out_ += key;
    out_ += "\":";
  }
  void line(int indent) {
    if (!pretty_) return;
    out_ += '\n';
    out_.append(static_cast<std::size_t>(indent), ' ');
  }

  void number(double v, std::string_view what) {
    if (!std::isfinite(v))
      throw DeviceError(where_ + "non-finite " + std::string(what) + " cannot be written");
    append_json_number(out_, v);
  }
  void integer(long long v) { append_json_integer(out_, v); }
  void boolean(bool v) { out_ += v ? "true" : "false"; }
  void string(std::string_view s, std::string_view what) {
    if (!append_json_string(out_, s))
      throw DeviceError(where_ + "cannot encode JSON: " + std::string(what) + " is not valid UTF-8");
  }
  void point(Point2 p, std::string_view what) {
    out_ += '[';
    number(p.x, what);
    out_ += ',';
    number(p.y, what);
    out_ += ']';
  }
  void point(double x, double y, double z, std::string_view what) {
    out_ += '[';
    number(x, what);
    out_ += ',';
    number(y, what);
    out_ += ',';
    number(z, what);
    out_ += ']';
  }

 private:
  std::string& out_;
  bool pretty_;
  std::string where_;
};

void write_page(JsonWriter& w, const PlotPage& page) {
  // A non-finite or roomless page would print as nonsense or describe no drawable area.
  check_page_spec({{page.width_mm, page.height_mm}, page.margin_mm});
  std::string& out = w.out();
  out += '{';
  w.leaf_member("width_mm", true);
  w.number(page.width_mm, "page width");
  w.leaf_member("height_mm", false);
  w.number(page.height_mm, "page height");
  w.leaf_member("margin_mm", false);
  w.number(page.margin_mm, "page margin");
  out += ",\"origin\":\"top-left\",\"y\":\"down\"}";
}

// The document's keys before "frames" (or, in JSON Lines, before each frame's own), at `indent`.
void write_head_members(JsonWriter& w, const PlotPage& page, const JsonOptions& o, int indent) {
  w.member("format", indent, true);
  w.out() += '"';
  w.out() += kJsonLinesFormat;
  w.out() += '"';
  if (!o.title.empty()) {
    w.member("title", indent, false);
    w.string(o.title, "the title");
  }
  w.member("page", indent, false);
  write_page(w, page);
}

// One frame's members, in schema order.
class FrameText {
 public:
  FrameText(JsonWriter& w, const JsonFrame& frame, const JsonOptions& options)
      : w_(w), f_(frame), o_(options) {}

  // The frame's members at `indent`; `first` when nothing precedes them in the object.
  void members(int indent, bool first) {
    w_.member("frame", indent, first);
    w_.integer(f_.frame);
    w_.member("time", indent, false);
    w_.number(f_.time, "time");
    if (!f_.views.empty()) {
      if (o_.parts.camera || o_.parts.layout) {
        w_.member("views", indent, false);
        views(indent);
      }
    } else {
      if (o_.parts.camera) {
        w_.member("camera", indent, false);
        camera(f_.camera, indent);
      }
      if (o_.parts.layout) {
        w_.member("layout", indent, false);
        layout(f_.plot.layout);
      }
    }
    if (o_.parts.segments) {
      w_.member("segments", indent, false);
      segments(indent);
    }
    if (o_.parts.strokes) {
      w_.member("strokes", indent, false);
      strokes(StrokeLayer::Visible, indent);
      w_.member("stroke_pens", indent, false);
      pens(StrokeLayer::Visible);
      if (has_hatch()) {  // only when there is hatching: frames without keep the schema they had
        w_.member("hatch_strokes", indent, false);
        strokes(StrokeLayer::Hatch, indent);
        w_.member("hatch_stroke_pens", indent, false);
        pens(StrokeLayer::Hatch);
      }
      if (o_.include_hidden) {
        w_.member("hidden_strokes", indent, false);
        strokes(StrokeLayer::Hidden, indent);
        w_.member("hidden_stroke_pens", indent, false);
        pens(StrokeLayer::Hidden);
        if (o_.levels) {
          w_.member("hidden_stroke_levels", indent, false);
          levels();
        }
      }
    }
    if (o_.parts.stats) {
      w_.member("stats", indent, false);
      stats();
    }
  }

 private:
  // A sheet's views, each {"name", "label", "camera", "layout"} as the parts ask.
  void views(int indent) {
    std::string& out = w_.out();
    out += '[';
    for (std::size_t i = 0; i < f_.views.size(); ++i) {
      const SheetView& v = f_.views[i];
      if (i > 0) out += ',';
      w_.line(indent + 2);
      out += '{';
      w_.member("name", indent + 4, true);
      w_.string(v.name, "a view's name");
      w_.member("label", indent + 4, false);
      w_.string(v.label, "a view's label");
      w_.member("mm_per_world_unit", indent + 4, false);
      w_.number(v.mm_per_world_unit, "a view's scale");
      if (o_.parts.camera) {
        w_.member("camera", indent + 4, false);
        camera(v.camera, indent + 4);
      }
      if (o_.parts.layout) {
        w_.member("layout", indent + 4, false);
        layout(v.layout);
      }
      w_.line(indent + 2);
      out += '}';
    }
    w_.line(indent);
    out += ']';
  }

  void camera(const Camera& c, int indent) {
    Point3 eye;
    Vector3 direction;
    try {
      eye = c.eye_world();
      direction = c.direction_world();
    } catch (const std::domain_error& e) {
      throw DeviceError(w_.where() + "camera has a singular view transform (" + e.what() + ")");
    }
    std::string& out = w_.out();
    const int in = indent + 2;
    out += '{';
    w_.member("kind", in, true);
    out += c.projection == Projection::Perspective ? "\"perspective\"" : "\"orthographic\"";
    w_.member("constructor", in, false);
    w_.string(c.kind, "the camera's constructor");
    w_.member("eye", in, false);
    w_.point(eye.x, eye.y, eye.z, "camera eye");
    w_.member("direction", in, false);
    w_.point(direction.x, direction.y, direction.z, "camera direction");
    w_.member("focal", in, false);
    w_.number(c.focal, "camera focal");
    w_.member("offset", in, false);
    w_.point(Point2{c.offset.x, c.offset.y}, "camera offset");
    if (c.projection == Projection::Perspective) {
      w_.member("near_depth", in, false);
      w_.number(c.near_depth, "camera near_depth");
    }
    if (c.frame) {
      const Rect2& r = *c.frame;
      w_.member("frame", in, false);
      out += '[';
      w_.number(r.xmin, "camera frame");
      out += ',';
      w_.number(r.ymin, "camera frame");
      out += ',';
      w_.number(r.xmax, "camera frame");
      out += ',';
      w_.number(r.ymax, "camera frame");
      out += ']';
    }
    w_.member("view_from_world", in, false);
    out += "{\"m\":[";
    for (int i = 0; i < 3; ++i) {
      if (i > 0) out += ',';
      const Vector3 row = c.viewFromWorld.row(i);
      w_.point(row.x, row.y, row.z, "camera view_from_world");
    }
    out += "],\"t\":";
    const Vector3 t = c.viewFromWorld.t;
    w_.point(t.x, t.y, t.z, "camera view_from_world");
    out += '}';
    w_.line(indent);
    out += '}';
  }

  void layout(const PageLayout& layout) {
    w_.out() += '{';
    w_.leaf_member("mm_per_unit", true);
    w_.number(layout.scale, "layout scale");
    w_.leaf_member("origin_mm", false);
    w_.point(layout.origin(), "layout origin");
    w_.out() += '}';
  }

  // The object names, quoted and escaped once for every segment that names them.
  const std::string& quoted_name(std::uint32_t object) {
    if (object >= f_.object_names.size())
      throw DeviceError(w_.where() + "segment refers to object " + std::to_string(object) + " but only " +
                        std::to_string(f_.object_names.size()) + " object names were given");
    if (names_.empty()) names_.resize(f_.object_names.size());
    std::string& q = names_[object];
    if (q.empty() && !append_json_string(q, f_.object_names[object]))
      throw DeviceError(w_.where() + "cannot encode JSON: object name is not valid UTF-8");
    return q;
  }

  void segments(int indent) {
    std::string& out = w_.out();
    out += '[';
    bool first = true;
    std::size_t view = 0;
    for (std::size_t i = 0; i < f_.segments.size(); ++i) {
      const VisibleSegment& s = f_.segments[i];
      while (view + 1 < f_.views.size() && i >= f_.views[view].end_segment) ++view;
      if (s.hidden && !o_.include_hidden) continue;
      if (!first) out += ',';
      first = false;
      w_.line(indent + 2);
      out += "{\"p\":[";
      w_.point(s.p0.x, s.p0.y, s.p0.z, "segment end point");
      out += ',';
      w_.point(s.p1.x, s.p1.y, s.p1.z, "segment end point");
      out += "],\"s\":[";
      w_.point(s.s0, "segment picture point");
      out += ',';
      w_.point(s.s1, "segment picture point");
      out += "],\"object\":";
      out += quoted_name(s.object);
      if (s.source == SegmentSource::Intersection) {
        out += ",\"other\":";
        out += quoted_name(s.other);
      } else if (s.source == SegmentSource::Contour) {  // the smooth contour across this face
        out += ",\"contour\":";
        w_.integer(s.edge);
      } else {
        out += ",\"edge\":";
        w_.integer(s.edge);
        if (s.hatch) out += ",\"hatch\":true";
      }
      out += s.hidden ? ",\"hidden\":true" : ",\"hidden\":false";
      if (!f_.views.empty()) {
        out += ",\"view\":";
        w_.integer(static_cast<long long>(view));
      }
      if (s.hidden && o_.levels) {
        out += ",\"level\":";
        w_.integer(s.level);
      }
      out += '}';
    }
    if (!first) w_.line(indent);
    out += ']';
  }

  bool has_hatch() const {
    for (const PlotStroke& stroke : f_.plot.page.strokes)
      if (stroke.layer == StrokeLayer::Hatch) return true;
    return false;
  }

  void strokes(StrokeLayer layer, int indent) {
    std::string& out = w_.out();
    out += '[';
    bool first = true;
    for (const PlotStroke& stroke : f_.plot.page.strokes) {
      if (stroke.layer != layer) continue;
      if (!first) out += ',';
      first = false;
      w_.line(indent + 2);
      out += '[';
      for (std::size_t i = 0; i < stroke.points.size(); ++i) {
        if (i > 0) out += ',';
        w_.point(stroke.points[i], "stroke point");
      }
      out += ']';
    }
    if (!first) w_.line(indent);
    out += ']';
  }

  void pens(StrokeLayer layer) {
    std::string& out = w_.out();
    out += '[';
    bool first = true;
    for (const PlotStroke& stroke : f_.plot.page.strokes) {
      if (stroke.layer != layer) continue;
      if (!first) out += ',';
      first = false;
      w_.integer(stroke.pen);
    }
    out += ']';
  }

  // The occlusion level of each hidden stroke, parallel to hidden_strokes.
  void levels() {
    std::string& out = w_.out();
    out += '[';
    bool first = true;
    for (const PlotStroke& stroke : f_.plot.page.strokes) {
      if (stroke.layer != StrokeLayer::Hidden) continue;
      if (!first) out += ',';
      first = false;
      w_.integer(stroke.level);
    }
    out += ']';
  }

  void stats() {
    const PlanStats& s = f_.plot.stats;
    std::size_t visible = 0;
    for (const VisibleSegment& v : f_.segments) visible += !v.hidden;
    w_.out() += '{';
    w_.leaf_member("segments", true);
    w_.integer(static_cast<long long>(visible));
    w_.leaf_member("pen_down_mm", false);
    w_.number(s.pen_down_mm, "pen-down length");
    w_.leaf_member("pen_up_mm", false);
    w_.number(s.pen_up_mm, "pen-up travel");
    w_.leaf_member("pen_up_mean_mm", false);
    w_.number(s.pen_up_mean_mm, "pen-up mean");
    w_.leaf_member("pen_up_median_mm", false);
    w_.number(s.pen_up_median_mm, "pen-up median");
    w_.leaf_member("lifts", false);
    w_.integer(static_cast<long long>(s.lifts));
    w_.leaf_member("lift_lower_bound", false);
    w_.integer(static_cast<long long>(s.lift_lower_bound));
    w_.leaf_member("plot_seconds", false);
    w_.number(s.plot_seconds, "plotting time");
    w_.leaf_member("pen_order", false);
    w_.string(o_.pen_order, "the pen order");
    w_.out() += '}';
  }

  JsonWriter& w_;
  const JsonFrame& f_;
  const JsonOptions& o_;
  std::vector<std::string> names_;
};

// About what a frame's text takes, so that the string grows once or twice rather than twenty times.
std::size_t size_estimate(const JsonFrame& frame, const JsonOptions& o) {
  std::size_t points = 0;
  for (const PlotStroke& s : frame.plot.page.strokes) points += s.points.size();
  return 1024 + (o.parts.segments ? 200 * frame.segments.size() : 0) + (o.parts.strokes ? 40 * points : 0);
}

}  // namespace

std::string json_document_head(const PlotPage& first_page, const JsonOptions& options) {
  if (options.lines) return "";
  std::string text = "{";
  JsonWriter w(text, options.pretty, "");
  write_head_members(w, first_page, options, 2);
  w.member("frames", 2, false);
  text += '[';
  return text;
}

std::string json_frame_text(const JsonFrame& frame, const JsonOptions& options) {
  std::string text;
  text.reserve(size_estimate(frame, options));
  JsonWriter w(text, options.pretty && !options.lines, "frame " + std::to_string(frame.frame) + ": ");
  text += '{';
  if (options.lines) {
    // Every line whole in itself: a reader may start at any frame.
    write_head_members(w, frame.plot.page, options, 0);
    FrameText(w, frame, options).members(0, false);
    text += "}\n";
    return text;
  }
  FrameText(w, frame, options).members(6, true);
  w.line(4);
  text += '}';
  return text;
}

std::string json_frame_separator(bool first, const JsonOptions& options) {
  if (options.lines) return "";
  if (options.pretty) return first ? "\n    " : ",\n    ";
  return first ? "" : ",";
}

std::string json_document_tail(std::size_t frames, const JsonOptions& options) {
  if (options.lines) return "";
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

std::optional<JsonParts> parse_json_parts(std::string_view list) {
  JsonParts parts{false, false, false, false, false};
  if (list == "all") return JsonParts{};
  while (true) {
    const std::size_t comma = list.find(',');
    const std::string_view name = list.substr(0, comma);
    if (name == "camera")
      parts.camera = true;
    else if (name == "layout")
      parts.layout = true;
    else if (name == "segments")
      parts.segments = true;
    else if (name == "strokes")
      parts.strokes = true;
    else if (name == "stats")
      parts.stats = true;
    else
      return std::nullopt;
    if (comma == std::string_view::npos) return parts;
    list.remove_prefix(comma + 1);
  }
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
