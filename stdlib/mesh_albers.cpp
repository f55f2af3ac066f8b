// Albers (1988) object files, App. D of the thesis: NAME.VER lists one vertex "x y z" per line (record i
// is vertex i, counting from 1); NAME.SUR lists one surface per line: its edge count n, then the n+1
// vertex numbers of its loop closed by repeating the first ("03 01 04 02 01"). The thesis's loader
// (Turbo Pascal Read/ReadLn) silently truncated at its array limits and checked nothing; we read any
// size, check every record and say which line is wrong.
#include <cstdint>
#include <limits>

#include "stdlib/mesh_detail.hpp"

namespace hlr::stdlib {

using namespace mesh_detail;

namespace {

constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
constexpr const char* kVerHint = "each line of a .VER file holds one vertex: three numbers x y z";
constexpr const char* kSurHint =
    "each line of a .SUR file holds one surface: the edge count n, then n+1 vertex numbers, the loop closed "
    "by "
    "repeating its first vertex (e.g. 03 01 04 02 01)";

// DOS text files may end with a Ctrl-Z end-of-file mark; nothing after it is data.
std::string_view until_dos_eof(std::string_view text) { return text.substr(0, text.find('\x1A')); }

}  // namespace

ImportedMesh import_albers(std::string_view ver_text, std::string_view sur_text, const std::string& ver_name,
                           const std::string& sur_name, const MeshImportOptions& options) {
  RawMesh raw;
  raw.files = {ver_name, sur_name};
  raw.face_noun = "surface";
  raw.vertex_base = 1;

  // NAME.VER
  ver_text = until_dos_eof(ver_text);
  if (ver_text.empty()) fail(ver_name, 0, 0, "the vertex file is empty", kVerHint);
  LineScanner ver(ver_text);
  while (ver.next()) {
    const std::vector<Token>& t = ver.tokens();
    if (t.empty()) continue;
    const LineContext ctx(ver_name, ver.line());
    const std::string record = "vertex record " + std::to_string(raw.vertices.size() + 1);
    if (t.size() < 3)
      ctx.fail(t[0].column,
               record + " has " + std::to_string(t.size()) + " number" + (t.size() == 1 ? "" : "s") +
                   "; expected three (x y z)",
               t.size() == 2 ? std::string(kVerHint) + " (the thesis's printed TETRA.VER lost its x column)"
                             : kVerHint);
    if (t.size() > 3)
      ctx.fail(t[3].column, record + " has " + std::to_string(t.size()) + " numbers; expected three (x y z)",
               kVerHint);
    const Point3 p{ctx.real(t[0], "the x coordinate"), ctx.real(t[1], "the y coordinate"),
                   ctx.real(t[2], "the z coordinate")};
    if (raw.vertices.size() >= 0xFFFFFFFFu) ctx.fail(t[0].column, "too many vertices", "split the object");
    raw.vertices.push_back({p, {0, ctx.line(), t[0].column, -1}});
  }
  if (raw.vertices.empty()) fail(ver_name, 0, 0, "the vertex file holds no vertices", kVerHint);
  const auto n_vertices = static_cast<std::int64_t>(raw.vertices.size());

  // NAME.SUR
  sur_text = until_dos_eof(sur_text);
  if (sur_text.empty()) fail(sur_name, 0, 0, "the surface file is empty", kSurHint);
  LineScanner sur(sur_text);
  while (sur.next()) {
    const std::vector<Token>& t = sur.tokens();
    if (t.empty()) continue;
    const LineContext ctx(sur_name, sur.line());
    const std::string surface = "surface " + std::to_string(raw.face_count() + 1);
    if (raw.face_count() >= options.max_faces)
      ctx.fail(t[0].column, "the file has more than " + std::to_string(options.max_faces) + " surfaces",
               "raise the face limit or simplify the object");
    const std::int64_t n = ctx.integer(t[0], "the edge count", 1, 0x7FFFFFFF);
    const auto listed = static_cast<std::int64_t>(t.size()) - 1;
    if (listed != n + 1) {
      const int column = listed > n + 1 ? t[static_cast<std::size_t>(n) + 2].column : t[0].column;
      ctx.fail(column,
               surface + " has edge count " + std::to_string(n) + ", so it needs " + std::to_string(n + 1) +
                   " vertex numbers, but lists " + std::to_string(listed) +
                   (listed == n ? " (the loop must end by repeating its first vertex)" : ""),
               kSurHint);
    }
    std::int64_t first = 0;
    for (std::size_t i = 1; i < t.size(); ++i) {
      const std::int64_t v =
          ctx.integer(t[i], "a vertex number", std::numeric_limits<std::int64_t>::min(), kMax);
      if (v < 1 || v > n_vertices)
        ctx.fail(
            t[i].column,
            "vertex number " + std::to_string(v) + " is out of range (1.." + std::to_string(n_vertices) + ")",
            "vertex numbers count the lines of " + ver_name + " from 1");
      if (i == 1) first = v;
      if (i + 1 < t.size())
        raw.face_vertices.push_back(static_cast<std::uint32_t>(v - 1));
      else if (v != first)
        ctx.fail(t[i].column,
                 surface + " ends with vertex " + std::to_string(v) + " instead of its first vertex " +
                     std::to_string(first),
                 kSurHint);
    }
    raw.end_face({1, ctx.line(), t[0].column, -1});
  }
  if (raw.face_count() == 0) fail(sur_name, 0, 0, "the surface file holds no surfaces", kSurHint);
  return build_mesh(std::move(raw), options);
}

}  // namespace hlr::stdlib
