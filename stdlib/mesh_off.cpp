// OFF (Geomview's Object File Format): header keyword with optional prefixes, counts, one vertex and
// one face per line. Read line by line so that every problem has a line and column.
#include <algorithm>
#include <cstdint>
#include <limits>

#include "core/first_touch.hpp"
#include "core/parallel.hpp"
#include "stdlib/mesh_detail.hpp"

namespace hlr::stdlib {

using namespace mesh_detail;

namespace {

constexpr const char* kHeaderHint = "an OFF file starts with 'OFF', then the vertex and face counts";

struct OffReader {
  const std::string& name;
  LineScanner lines;

  // The next line with data (comments and blank lines skipped), or null at the end of the file.
  const std::vector<Token>* next() {
    while (lines.next()) {
      const std::vector<Token>& t = lines.tokens('#');
      if (!t.empty()) return &t;
    }
    return nullptr;
  }
  LineContext context() const { return LineContext(name, lines.line()); }
};

// Checks the header keyword "[ST][C][N][n]OFF"; returns how many tokens of the line it used.
std::size_t read_keyword(const std::vector<Token>& t, const LineContext& ctx) {
  const std::string_view keyword = t[0].text;
  std::string_view prefix = keyword.substr(0, keyword.size() - 3);
  const bool has_dimension = prefix.ends_with('n');
  if (prefix.starts_with("ST")) prefix.remove_prefix(2);
  for (const char* flag : {"C", "N", "4", "n"})
    if (prefix.starts_with(flag)) {
      if (*flag == '4')
        ctx.fail(t[0].column, "4-D OFF (" + quoted(keyword) + ") is not supported", kHeaderHint);
      prefix.remove_prefix(1);
    }
  if (!prefix.empty()) ctx.fail(t[0].column, "unknown OFF header " + quoted(keyword), kHeaderHint);
  std::size_t used = 1;
  if (has_dimension) {
    if (t.size() < 2)
      ctx.fail(t[0].column, "the header 'nOFF' needs the dimension after it", "write 'nOFF 3'");
    if (ctx.integer(t[1], "the dimension", 0, std::numeric_limits<std::int64_t>::max()) != 3)
      ctx.fail(t[1].column, "only 3-dimensional OFF files are supported", "write 'nOFF 3' or plain 'OFF'");
    used = 2;
  }
  if (t.size() > used && iequals(t[used].text, "BINARY"))
    ctx.fail(t[used].column, "binary OFF is not supported", "save the mesh as text OFF");
  return used;
}

}  // namespace

namespace mesh_detail {

bool read_off_fast(std::string_view text, const std::string& name, const MeshImportOptions& options,
                   RawMesh& raw, std::size_t chunk_bytes) {
  FastCursor in(text, '#');
  std::string_view keyword;
  if (!in.next_record() || !in.word(keyword) || keyword != "OFF") return false;
  if (in.end_of_line() && !in.next_record()) return false;
  std::uint64_t n_vertices = 0, n_faces = 0, n_edges = 0;
  if (!in.index(n_vertices) || !in.index(n_faces)) return false;
  if (!in.end_of_line() && !(in.index(n_edges) && in.end_of_line())) return false;
  if (n_vertices > 0xFFFFFFFEull || n_faces > options.max_faces) return false;

  // The records after the header, in parts read side by side: first each part's lines and records are
  // counted, which numbers its first line and record; record k is vertex k, then the faces follow.
  const std::string_view body = text.substr(static_cast<std::size_t>(in.position() - text.data()));
  const std::vector<std::string_view> parts = split_at_line_ends(body, std::max<std::size_t>(chunk_bytes, 1));
  struct Part {
    PartCounts counts;
    bool ok = true;
    int first_line = 0;
    std::size_t first_record = 0;
    RawMesh faces;  // the part's faces (face_vertices, face_ends, face_sources)
  };
  std::vector<Part> read(parts.size());
  const unsigned threads = threads_for(body.size(), kOffChunkBytes, 0);
  parallel_chunks(parts.size(), threads, [&](std::size_t k) {
    read[k].ok = count_lines_and_records(parts[k], '#', read[k].counts);
  });
  std::size_t records = 0;
  std::int64_t line = in.line();
  for (Part& part : read) {
    if (!part.ok || line > std::numeric_limits<int>::max()) return false;
    part.first_line = static_cast<int>(line);
    part.first_record = records;
    line += static_cast<std::int64_t>(part.counts.lines);
    records += part.counts.records;
  }
  if (records != n_vertices + n_faces) return false;  // the careful reader says which is missing or extra

  raw = RawMesh{};
  raw.files = {name};
  raw.vertex_base = 0;
  // Backed by data (the records are there), and faulted in on every core before the parts fill it.
  resize_touched(raw.vertices, n_vertices, threads);
  parallel_chunks(parts.size(), threads, [&](std::size_t k) {
    Part& part = read[k];
    // Read into locals, stored once: the parts lie side by side, their ends sharing cache lines.
    bool ok = part.ok;
    RawMesh faces;
    FastCursor part_in(parts[k], part.first_line, '#');
    std::size_t r = part.first_record;
    for (; ok && part_in.next_record(); ++r) {
      const Source where{0, part_in.line(), part_in.column(), -1};
      if (r < n_vertices) {
        Point3 p;
        ok = part_in.real(p.x) && part_in.real(p.y) && part_in.real(p.z);
        part_in.skip_line();  // extras (normal, colour) ignored
        raw.vertices[r] = {p, where};
        continue;
      }
      std::uint64_t n = 0, v = 0;
      ok = part_in.index(n);
      for (std::uint64_t i = 0; ok && i < n; ++i) {
        ok = part_in.index(v) && v < n_vertices;
        faces.face_vertices.push_back(static_cast<std::uint32_t>(v));
      }
      double colour = 0;
      for (int extras = 0; ok && !part_in.end_of_line(); ++extras) ok = extras < 4 && part_in.real(colour);
      faces.end_face(where);
    }
    part.ok = ok && r == part.first_record + part.counts.records;
    part.faces = std::move(faces);
  });

  // The parts' faces joined in order, each part copied side by side into its place.
  std::vector<std::size_t> reference_at(read.size() + 1, 0), face_at(read.size() + 1, 0);
  for (std::size_t k = 0; k < read.size(); ++k) {
    if (!read[k].ok) return false;
    reference_at[k + 1] = reference_at[k] + read[k].faces.face_vertices.size();
    face_at[k + 1] = face_at[k] + read[k].faces.face_count();
  }
  resize_touched(raw.face_vertices, reference_at.back(), threads);
  resize_touched(raw.face_ends, face_at.back(), threads);
  resize_touched(raw.face_sources, face_at.back(), threads);
  parallel_chunks(read.size(), threads, [&](std::size_t k) {
    const RawMesh& faces = read[k].faces;
    std::copy(faces.face_vertices.begin(), faces.face_vertices.end(),
              raw.face_vertices.begin() + static_cast<std::ptrdiff_t>(reference_at[k]));
    std::copy(faces.face_sources.begin(), faces.face_sources.end(),
              raw.face_sources.begin() + static_cast<std::ptrdiff_t>(face_at[k]));
    for (std::size_t f = 0; f < faces.face_ends.size(); ++f)
      raw.face_ends[face_at[k] + f] = reference_at[k] + faces.face_ends[f];
    read[k].faces = RawMesh{};
  });
  return true;
}

RawMesh read_off_careful(std::string_view text, const std::string& name, const MeshImportOptions& options) {
  RawMesh raw;
  raw.files = {name};
  raw.vertex_base = 0;
  if (text.empty()) fail(name, 0, 0, "the file is empty", kHeaderHint);
  OffReader in{name, LineScanner(text)};

  const std::vector<Token>* t = in.next();
  if (!t) fail(name, 0, 0, "the file holds only comments and blank lines", kHeaderHint);
  std::size_t first = 0;  // first count token on this line
  double probe = 0;
  if ((*t)[0].text.size() >= 3 && (*t)[0].text.ends_with("OFF")) {
    first = read_keyword(*t, in.context());
  } else if (!parse_real((*t)[0].text, probe)) {
    in.context().fail((*t)[0].column,
                      "not an OFF file: expected 'OFF' or the counts, found " + quoted((*t)[0].text),
                      kHeaderHint);
  }
  if (first == t->size()) {
    const int header_line = in.lines.line();
    t = in.next();
    if (!t)
      fail(name, header_line, 0, "the file ends after the header", "give the counts: vertices faces edges");
    first = 0;
  }

  // Counts: vertices faces [edges].
  const LineContext counts = in.context();
  const std::size_t n_counts = t->size() - first;
  if (n_counts < 2 || n_counts > 3)
    counts.fail(
        (*t)[first].column,
        "the counts line holds " + std::to_string(n_counts) + " values; expected 'vertices faces [edges]'",
        kHeaderHint);
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
  const std::int64_t n_vertices = counts.integer((*t)[first], "the vertex count", 0, 0xFFFFFFFEll);
  const Token face_count = (*t)[first + 1];
  const std::int64_t n_faces = counts.integer(face_count, "the face count", 0, kMax);
  if (n_counts == 3) counts.integer((*t)[first + 2], "the edge count", 0, kMax);
  if (static_cast<std::uint64_t>(n_faces) > options.max_faces)
    counts.fail(face_count.column,
                "the header announces " + std::to_string(n_faces) + " faces, more than the limit of " +
                    std::to_string(options.max_faces),
                "raise the face limit or simplify the mesh");
  const std::string range =
      n_vertices == 0 ? "the file has no vertices" : "0.." + std::to_string(n_vertices - 1);

  // No reserve from the counts: the vectors grow only with data actually present.
  for (std::int64_t k = 0; k < n_vertices; ++k) {
    t = in.next();
    if (!t)
      fail(name, in.lines.line(), 0,
           "the file ends after " + std::to_string(k) + " of the " + std::to_string(n_vertices) +
               " vertices announced",
           "the file is truncated, or the header's vertex count is too large");
    const LineContext ctx = in.context();
    if (t->size() < 3)
      ctx.fail((*t)[0].column,
               "vertex " + std::to_string(k) + " has " + std::to_string(t->size()) + " value" +
                   (t->size() == 1 ? "" : "s") + "; expected x y z",
               "write the three coordinates of each vertex on one line");
    const Point3 p{ctx.real((*t)[0], "the x coordinate"), ctx.real((*t)[1], "the y coordinate"),
                   ctx.real((*t)[2], "the z coordinate")};
    raw.vertices.push_back({p, {0, ctx.line(), (*t)[0].column, -1}});  // extras (normal, colour) ignored
  }

  for (std::int64_t k = 0; k < n_faces; ++k) {
    t = in.next();
    if (!t)
      fail(name, in.lines.line(), 0,
           "the file ends after " + std::to_string(k) + " of the " + std::to_string(n_faces) +
               " faces announced",
           "the file is truncated, or the header's face count is too large");
    const LineContext ctx = in.context();
    const std::string face = "face " + std::to_string(k + 1);
    const std::int64_t n = ctx.integer((*t)[0], "the face's vertex count", 0, kMax);
    const auto listed = static_cast<std::int64_t>(t->size()) - 1;
    if (n > listed)
      ctx.fail((*t)[0].column,
               face + " announces " + std::to_string(n) + " vertices but lists " + std::to_string(listed),
               "each face line is: count, then that many vertex indices");
    if (listed - n > 4)
      ctx.fail((*t)[static_cast<std::size_t>(n) + 1].column,
               face + " has " + std::to_string(listed - n) + " values after its " + std::to_string(n) +
                   " vertex indices; at most a colour (4 values) may follow",
               "check the vertex count at the start of the line");
    for (std::int64_t i = 1; i <= n; ++i) {
      const Token& tok = (*t)[static_cast<std::size_t>(i)];
      const std::int64_t v =
          ctx.integer(tok, "a vertex index", std::numeric_limits<std::int64_t>::min(), kMax);
      if (v < 0 || v >= n_vertices)
        ctx.fail(tok.column, "vertex index " + std::to_string(v) + " is out of range (" + range + ")",
                 "OFF vertex indices count from 0");
      raw.face_vertices.push_back(static_cast<std::uint32_t>(v));
    }
    for (std::size_t i = static_cast<std::size_t>(n) + 1; i < t->size(); ++i)
      ctx.any_real((*t)[i], "the face colour");
    raw.end_face({0, ctx.line(), (*t)[0].column, -1});
  }

  if ((t = in.next()))
    in.context().fail((*t)[0].column,
                      "unexpected data after the " + std::to_string(n_faces) + " faces the header announced",
                      "the header's face count may be too small");
  return raw;
}

}  // namespace mesh_detail

RawMesh mesh_detail::read_off(std::string_view text, const std::string& name,
                              const MeshImportOptions& options) {
  auto fast = [](std::string_view t, const std::string& n, const MeshImportOptions& o, RawMesh& r) {
    return read_off_fast(t, n, o, r);
  };
  return fast_or_careful(fast, read_off_careful, text, name, options);
}

ImportedMesh import_off(std::string_view text, const std::string& name, const MeshImportOptions& options) {
  return build_mesh(read_off(text, name, options), options);
}

}  // namespace hlr::stdlib
