// STL, ASCII and binary. STL lists every triangle with its own three corners, so shared vertices are
// found by welding exactly equal coordinates; the facet normals are ignored (the winding decides, and
// the builder makes it consistent).
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "stdlib/mesh_detail.hpp"

namespace hlr::stdlib {

using namespace mesh_detail;

namespace {

constexpr const char* kAsciiHint =
    "an ASCII STL reads: solid NAME / facet normal nx ny nz / outer loop / vertex x y z "
    "(three times) / endloop / endfacet / ... / endsolid NAME";

// Welds vertices by exact coordinate equality (-0 equals +0).
class Welder {
 public:
  explicit Welder(RawMesh& raw, std::size_t expected = 0) : raw_(raw), index_(expected) {}
  std::uint32_t add(Point3 p, const Source& where) {
    const auto fresh = static_cast<std::uint32_t>(raw_.vertices.size());
    const std::uint32_t v = index_.insert(p, fresh);
    if (v == fresh) raw_.vertices.push_back({{p.x + 0.0, p.y + 0.0, p.z + 0.0}, where});  // -0 + 0 = +0
    return v;
  }

 private:
  RawMesh& raw_;
  ExactPointIndex index_;
};

std::uint32_t read_u32(const unsigned char* p) {
  return std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 |
         std::uint32_t{p[3]} << 24;
}
double read_f32(const unsigned char* p) { return static_cast<double>(std::bit_cast<float>(read_u32(p))); }

RawMesh read_binary(std::string_view bytes, const std::string& name, const MeshImportOptions& options) {
  RawMesh raw;
  raw.files = {name};
  raw.face_noun = "triangle";
  raw.vertex_base = 1;
  raw.welded_by_format = true;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::uint64_t count = read_u32(data + 80);
  if (count > options.max_faces)
    fail(name, 0, 0,
         "the header announces " + std::to_string(count) + " triangles, more than the limit of " +
             std::to_string(options.max_faces),
         "raise the face limit or simplify the mesh");
  // The caller checked that the size is exactly 84 + 50·count, so this reserve is backed by data.
  raw.face_vertices.reserve(3 * count);
  raw.face_ends.reserve(count);
  raw.face_sources.reserve(count);
  Welder welder(raw, count / 2);  // a closed triangle mesh has about half as many vertices as triangles
  for (std::uint64_t k = 0; k < count; ++k) {
    const std::uint64_t offset = 84 + 50 * k;
    for (int c = 0; c < 3; ++c) {
      const unsigned char* p = data + offset + 12 + 12 * static_cast<std::uint64_t>(c);
      const Point3 v{read_f32(p), read_f32(p + 4), read_f32(p + 8)};
      if (!is_finite(v))
        fail(name, 0, 0,
             "triangle " + std::to_string(k + 1) + " (byte offset " + std::to_string(offset) +
                 ") has a non-finite " + "coordinate in corner " + std::to_string(c + 1) + " (byte offset " +
                 std::to_string(offset + 12 + 12 * static_cast<std::uint64_t>(c)) + ")",
             "every coordinate must be a finite number; repair the mesh and export it again");
      raw.face_vertices.push_back(welder.add(v, {0, 0, 0, static_cast<std::int64_t>(offset)}));
    }
    raw.end_face({0, 0, 0, static_cast<std::int64_t>(offset)});
  }
  return raw;
}

// Token stream over the lines of an ASCII STL.
class AsciiReader {
 public:
  AsciiReader(std::string_view text, const std::string& name) : lines_(text), name_(name) {}

  // The next token, or an empty token (column 0) at the end of the file.
  Token next() {
    while (pos_ >= tokens_.size()) {
      if (!lines_.next()) return {};
      tokens_ = lines_.tokens();
      pos_ = 0;
    }
    return tokens_[pos_++];
  }
  void skip_rest_of_line() { pos_ = tokens_.size(); }
  LineContext context() const { return LineContext(name_, lines_.line()); }

  Token expect(std::string_view keyword, const char* after) {
    const Token t = next();
    if (t.column == 0)
      fail(name_, lines_.line(), 0,
           std::string("the file ends ") + after + "; expected '" + std::string(keyword) + "'",
           "the file is truncated");
    if (!iequals(t.text, keyword))
      context().fail(t.column,
                     "expected '" + std::string(keyword) + "' " + after + ", found " + quoted(t.text),
                     kAsciiHint);
    return t;
  }

 private:
  LineScanner lines_;
  const std::string& name_;
  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
};

}  // namespace

namespace mesh_detail {

bool read_stl_ascii_fast(std::string_view text, const std::string& name, const MeshImportOptions& options,
                         RawMesh& raw) {
  raw = RawMesh{};
  raw.files = {name};
  raw.face_noun = "facet";
  raw.vertex_base = 1;
  raw.welded_by_format = true;
  Welder welder(raw);
  FastCursor in(text);
  std::string_view word;
  int line = 0, column = 0;  // of `word`
  // To the next token, across lines.
  auto advance = [&] { return !in.at_line_end() || (in.end_of_line() && in.next_record()); };
  auto next = [&] {
    if (!advance()) return false;
    line = in.line();
    column = in.column();
    return in.word(word);
  };
  auto expect = [&](std::string_view keyword) { return next() && word == keyword; };
  if (!in.next_record() || !expect("solid")) return false;
  in.skip_line();  // the solid's name
  for (;;) {
    if (!in.next_record() || !next()) return false;  // ends inside a solid
    if (word == "endsolid") {
      in.skip_line();
      if (!in.next_record()) return true;  // end of file: done
      if (!expect("solid")) return false;
      in.skip_line();
      continue;
    }
    const Source where{0, line, column, -1};
    if (word != "facet" || raw.face_count() >= options.max_faces || !next()) return false;
    if (word == "normal") {
      double ignored = 0;  // even "nan" normals are common
      for (int k = 0; k < 3; ++k)
        if (!next() || !parse_real(word, ignored)) return false;
      if (!next()) return false;
    }
    if (word != "outer" || !expect("loop")) return false;
    for (;;) {
      if (!next()) return false;
      if (word == "endloop") break;
      if (word != "vertex") return false;
      const Source corner{0, line, column, -1};
      Point3 p;
      if (!advance() || !in.real(p.x) || !advance() || !in.real(p.y) || !advance() || !in.real(p.z))
        return false;
      raw.face_vertices.push_back(welder.add(p, corner));
    }
    if (!expect("endfacet")) return false;
    raw.end_face(where);
  }
}

}  // namespace mesh_detail

RawMesh mesh_detail::read_stl_ascii_careful(std::string_view text, const std::string& name,
                                            const MeshImportOptions& options, bool could_be_binary) {
  RawMesh raw;
  raw.files = {name};
  raw.face_noun = "facet";
  raw.vertex_base = 1;
  raw.welded_by_format = true;
  Welder welder(raw);
  AsciiReader in(text, name);
  try {
    in.expect("solid", "at the start");
    in.skip_rest_of_line();  // the solid's name
    for (;;) {
      Token t = in.next();
      if (t.column == 0)
        fail(name, in.context().line(), 0, "the file ends inside a solid; expected 'endsolid'",
             "the file is truncated");
      if (iequals(t.text, "endsolid")) {
        in.skip_rest_of_line();
        t = in.next();
        if (t.column == 0) break;  // end of file: done
        if (!iequals(t.text, "solid"))
          in.context().fail(t.column, "expected 'solid' or the end of the file, found " + quoted(t.text),
                            kAsciiHint);
        in.skip_rest_of_line();
        continue;
      }
      if (!iequals(t.text, "facet"))
        in.context().fail(t.column, "expected 'facet' or 'endsolid', found " + quoted(t.text), kAsciiHint);
      if (raw.face_count() >= options.max_faces)
        in.context().fail(t.column, "the file has more than " + std::to_string(options.max_faces) + " facets",
                          "raise the face limit or simplify the mesh");
      const Source where{0, in.context().line(), t.column, -1};
      Token word = in.next();
      if (iequals(word.text, "normal")) {
        for (const char* what : {"the normal's x", "the normal's y", "the normal's z"}) {
          const Token n = in.next();
          if (n.column == 0)
            fail(name, where.line, 0, "the file ends inside a facet", "the file is truncated");
          in.context().any_real(n, what);  // ignored: even "nan" normals are common
        }
        word = in.next();
      }
      if (word.column == 0)
        fail(name, where.line, 0, "the file ends inside a facet", "the file is truncated");
      if (!iequals(word.text, "outer"))
        in.context().fail(word.column,
                          "expected 'outer loop' in facet " + std::to_string(raw.face_count() + 1) +
                              ", found " + quoted(word.text),
                          kAsciiHint);
      in.expect("loop", "after 'outer'");
      for (;;) {
        const Token v = in.next();
        if (v.column == 0)
          fail(name, in.context().line(), 0, "the file ends inside a facet; expected 'endloop'",
               "the file is truncated");
        if (iequals(v.text, "endloop")) break;
        if (!iequals(v.text, "vertex"))
          in.context().fail(v.column, "expected 'vertex' or 'endloop', found " + quoted(v.text), kAsciiHint);
        const int line = in.context().line();
        double xyz[3];
        const char* names[3] = {"the x coordinate", "the y coordinate", "the z coordinate"};
        for (int c = 0; c < 3; ++c) {
          const Token n = in.next();
          if (n.column == 0) fail(name, line, 0, "the file ends inside a vertex", "the file is truncated");
          xyz[c] = in.context().real(n, names[c]);
        }
        raw.face_vertices.push_back(welder.add({xyz[0], xyz[1], xyz[2]}, {0, line, v.column, -1}));
      }
      in.expect("endfacet", "after 'endloop'");
      raw.end_face(where);  // fewer than three vertices: dropped with a warning when built
    }
  } catch (MeshImportError& e) {
    if (could_be_binary) {
      e.problem.hint += (e.problem.hint.empty() ? "" : "; ") +
                        std::string("if this is a binary STL, its size does not match its triangle count");
      throw MeshImportError(std::move(e.problem));
    }
    throw;
  }
  return raw;
}

RawMesh mesh_detail::read_stl(std::string_view bytes, const std::string& name,
                              const MeshImportOptions& options) {
  if (bytes.empty())
    fail(name, 0, 0, "the file is empty", "an STL file is either ASCII ('solid ...') or binary");
  // Binary exactly when the size matches the triangle count: binary headers may start with "solid" too.
  if (bytes.size() >= 84) {
    const std::uint64_t count = read_u32(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
    if (bytes.size() == 84 + 50 * count) return read_binary(bytes, name, options);
  }
  std::string_view start = bytes.substr(0, 512);
  if (start.starts_with("\xEF\xBB\xBF")) start.remove_prefix(3);
  while (!start.empty() && (start[0] == ' ' || start[0] == '\t' || start[0] == '\r' || start[0] == '\n'))
    start.remove_prefix(1);
  const bool ascii = start.size() >= 5 && iequals(start.substr(0, 5), "solid");
  if (ascii) {
    RawMesh raw;
    if (!read_stl_ascii_fast(bytes, name, options, raw))
      raw = read_stl_ascii_careful(bytes, name, options, bytes.size() >= 84);
    return raw;
  }
  if (bytes.size() < 84)
    fail(name, 0, 0,
         "not an STL file: " + std::to_string(bytes.size()) +
             " bytes is too short for a binary STL (84-byte header) and it does not start with 'solid'",
         "export the mesh as STL again");
  const std::uint64_t count = read_u32(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
  fail(name, 0, 0,
       "truncated or padded binary STL: the header (byte offset 80) announces " + std::to_string(count) +
           " triangles, which take " + std::to_string(84 + 50 * count) + " bytes, but the file has " +
           std::to_string(bytes.size()),
       "the file was cut off or damaged; export it again");
}

ImportedMesh import_stl(std::string_view bytes, const std::string& name, const MeshImportOptions& options) {
  return build_mesh(read_stl(bytes, name, options), options);
}

}  // namespace hlr::stdlib
