// Wavefront OBJ: vertices, polygon faces and polylines; everything about materials, texture and
// grouping is irrelevant to a line drawing and skipped.
#include <cstdint>
#include <limits>
#include <set>

#include "stdlib/mesh_detail.hpp"

namespace hlr::stdlib {

using namespace mesh_detail;

namespace {

constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min();
constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
constexpr const char* kIndexHint =
    "OBJ vertex indices count from 1; negative ones count back from the last vertex";

bool one_of(std::string_view word, std::initializer_list<std::string_view> words) {
  for (std::string_view w : words)
    if (word == w) return true;
  return false;
}

// A positive index beyond the vertices read so far, checked once the whole file is read.
struct ForwardReference {
  std::int64_t index;
  int line, column;
};

class ObjReader {
 public:
  ObjReader(const std::string& name, RawMesh& raw) : name_(name), raw_(raw) {}

  // "i", "i/t", "i//n" or "i/t/n" → 0-based vertex index.
  std::uint32_t reference(const Token& tok, const LineContext& ctx) {
    const std::string_view s = tok.text;
    const std::size_t slash = s.find('/');
    if (slash != std::string_view::npos) {
      std::string_view rest = s.substr(slash + 1);
      for (int part = 0; part < 2 && !rest.empty(); ++part) {
        const std::size_t next = rest.find('/');
        const std::string_view item = rest.substr(0, next);
        std::int64_t ignored = 0;
        if ((!item.empty() && !parse_integer(item, ignored)) || (next != std::string_view::npos && part == 1))
          ctx.fail(tok.column, "bad vertex reference " + quoted(s),
                   "write v, v/vt, v//vn or v/vt/vn with integers");
        rest = next == std::string_view::npos ? std::string_view{} : rest.substr(next + 1);
      }
    }
    const std::string_view vertex = s.substr(0, slash);
    if (vertex.empty())
      ctx.fail(tok.column, "vertex reference " + quoted(s) + " has no vertex index", kIndexHint);
    const std::int64_t i = ctx.integer({vertex, tok.column}, "a vertex index", kMin, kMax);
    const auto defined = static_cast<std::int64_t>(raw_.vertices.size());
    if (i == 0) ctx.fail(tok.column, "vertex index 0 is invalid", kIndexHint);
    if (i < 0) {
      if (-i > defined)
        ctx.fail(tok.column,
                 "relative vertex index " + std::to_string(i) + " reaches before the first vertex (" +
                     std::to_string(defined) + " defined so far)",
                 kIndexHint);
      return static_cast<std::uint32_t>(defined + i);
    }
    if (i > 0xFFFFFFFFll)
      ctx.fail(tok.column, "vertex index " + std::to_string(i) + " is out of range", kIndexHint);
    if (i > defined) forward_.push_back({i, ctx.line(), tok.column});
    return static_cast<std::uint32_t>(i - 1);
  }

  void check_forward_references() const {
    const auto n = static_cast<std::int64_t>(raw_.vertices.size());
    for (const ForwardReference& f : forward_)
      if (f.index > n)
        fail(name_, f.line, f.column,
             "vertex index " + std::to_string(f.index) + " is out of range (" +
                 (n == 0 ? std::string("the file has no vertices") : "1.." + std::to_string(n)) + ")",
             kIndexHint);
  }

  void warn_once(const std::string& key, int line, int column, std::string message) {
    if (warned_.insert(key).second) raw_.warnings.push_back({name_, line, column, std::move(message), ""});
  }

 private:
  const std::string& name_;
  RawMesh& raw_;
  std::vector<ForwardReference> forward_;
  std::set<std::string> warned_;
};

}  // namespace

namespace mesh_detail {

namespace {

// Statements with nothing to draw, skipped by both readers.
bool ignored(std::string_view keyword) {
  return one_of(keyword, {"vt", "vn", "vp", "o", "g", "s", "usemtl", "mtllib", "maplib", "usemap", "lod",
                          "shadow_obj", "trace_obj", "bevel", "c_interp", "d_interp", "p"});
}

// "-?digits" at the start of s, advancing past it; false (s unchanged) if there are none.
bool leading_integer(std::string_view& s, std::int64_t& out) {
  std::size_t i = s.starts_with('-') ? 1 : 0;
  std::int64_t v = 0;
  const std::size_t first = i;
  while (i < s.size() && s[i] >= '0' && s[i] <= '9' && i - first < 18) v = 10 * v + (s[i++] - '0');
  if (i == first || (i < s.size() && s[i] >= '0' && s[i] <= '9')) return false;
  out = s[0] == '-' ? -v : v;
  s.remove_prefix(i);
  return true;
}

}  // namespace

bool read_obj_fast(std::string_view text, const std::string& name, const MeshImportOptions& options,
                   RawMesh& raw) {
  if (text.empty()) return false;
  raw = RawMesh{};
  raw.files = {name};
  raw.vertex_base = 1;
  FastCursor in(text, '#');
  std::int64_t furthest = 0;  // the largest positive index, checked once every vertex is read
  std::string_view keyword, ref;
  while (in.next_record()) {
    const Source where{0, in.line(), in.column(), -1};
    if (!in.word(keyword)) return false;
    if (keyword == "v") {
      Point3 p;
      if (!in.real(p.x) || !in.real(p.y) || !in.real(p.z) || raw.vertices.size() >= 0xFFFFFFFFu) return false;
      in.skip_line();  // extras (w, colour) ignored
      raw.vertices.push_back({p, where});
    } else if (keyword == "f" || keyword == "fo") {
      if (raw.face_count() >= options.max_faces) return false;
      const auto defined = static_cast<std::int64_t>(raw.vertices.size());
      while (!in.end_of_line()) {
        // v, v/vt, v//vn or v/vt/vn.
        std::int64_t i = 0, ignored_part = 0;
        if (!in.word(ref) || !leading_integer(ref, i)) return false;
        if (ref.starts_with('/')) {
          ref.remove_prefix(1);
          if (!ref.starts_with('/') && !leading_integer(ref, ignored_part)) return false;
          if (ref.starts_with('/')) {
            ref.remove_prefix(1);
            if (!leading_integer(ref, ignored_part)) return false;
          }
        }
        if (!ref.empty() || i == 0 || -i > defined || i > 0xFFFFFFFFll) return false;
        furthest = std::max(furthest, i);
        raw.face_vertices.push_back(static_cast<std::uint32_t>(i < 0 ? defined + i : i - 1));
      }
      raw.end_face(where);
    } else if (ignored(keyword)) {
      in.skip_line();
    } else {
      return false;  // lines, free-form geometry, unknown statements: the careful reader's warnings
    }
  }
  return furthest <= static_cast<std::int64_t>(raw.vertices.size());
}

RawMesh read_obj_careful(std::string_view text, const std::string& name, const MeshImportOptions& options) {
  RawMesh raw;
  raw.files = {name};
  raw.vertex_base = 1;
  if (text.empty())
    fail(name, 0, 0, "the file is empty", "an OBJ file lists vertices ('v x y z') and faces ('f 1 2 3')");
  ObjReader reader(name, raw);
  LineScanner lines(text);
  while (lines.next()) {
    const std::vector<Token>& t = lines.tokens('#');
    if (t.empty()) continue;
    const LineContext ctx(name, lines.line());
    const std::string_view keyword = t[0].text;
    if (keyword == "v") {
      if (t.size() < 4)
        ctx.fail(t[0].column, "a vertex needs three coordinates, found " + std::to_string(t.size() - 1),
                 "write 'v x y z'");
      const Point3 p{ctx.real(t[1], "the x coordinate"), ctx.real(t[2], "the y coordinate"),
                     ctx.real(t[3], "the z coordinate")};
      if (raw.vertices.size() >= 0xFFFFFFFFu) ctx.fail(t[0].column, "too many vertices", "split the mesh");
      raw.vertices.push_back({p, {0, ctx.line(), t[0].column, -1}});
    } else if (keyword == "f" || keyword == "fo") {
      if (raw.face_count() >= options.max_faces)
        ctx.fail(t[0].column, "the file has more than " + std::to_string(options.max_faces) + " faces",
                 "raise the face limit or simplify the mesh");
      for (std::size_t i = 1; i < t.size(); ++i) raw.face_vertices.push_back(reader.reference(t[i], ctx));
      raw.end_face(
          {0, ctx.line(), t[0].column, -1});  // fewer than 3 vertices: dropped with a warning when built
    } else if (keyword == "l") {
      std::vector<std::uint32_t> chain;
      for (std::size_t i = 1; i < t.size(); ++i) chain.push_back(reader.reference(t[i], ctx));
      if (chain.size() < 2)
        raw.warnings.push_back(
            {name, ctx.line(), t[0].column, "a line needs at least two vertices; skipped it", ""});
      for (std::size_t i = 0; i + 1 < chain.size(); ++i)
        raw.lines.push_back({chain[i], chain[i + 1], {0, ctx.line(), t[i + 1].column, -1}});
    } else if (ignored(keyword)) {
      continue;  // texture, normals, grouping, materials, points: nothing to draw
    } else if (one_of(keyword, {"cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim",
                                "hole", "scrv", "sp", "end", "con"})) {
      reader.warn_once(
          "free-form", ctx.line(), t[0].column,
          "free-form curves and surfaces ('" + std::string(keyword) + "') are not supported; ignored them");
    } else {
      reader.warn_once(std::string(keyword), ctx.line(), t[0].column,
                       "unknown statement " + quoted(keyword) + "; ignored it (and any like it)");
    }
  }
  reader.check_forward_references();
  return raw;
}

}  // namespace mesh_detail

RawMesh mesh_detail::read_obj(std::string_view text, const std::string& name,
                              const MeshImportOptions& options) {
  return fast_or_careful(read_obj_fast, read_obj_careful, text, name, options);
}

ImportedMesh import_obj(std::string_view text, const std::string& name, const MeshImportOptions& options) {
  return build_mesh(read_obj(text, name, options), options);
}

}  // namespace hlr::stdlib
