// STL, ASCII and binary. STL lists every triangle with its own three corners, so shared vertices are
// found by welding exactly equal coordinates; the facet normals are ignored (the winding decides, and
// the builder makes it consistent).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "core/parallel.hpp"
#include "core/release_memory.hpp"
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
    const std::uint32_t v =
        index_.insert(p, fresh, [&](std::uint32_t k) { return raw_.vertices[k].position; });
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

// A corner's coordinates as the file stores them (three floats), -0 as +0: equal keys are equal points
// (finite floats widen to doubles exactly).
struct CornerKey {
  std::uint32_t bits[3];
  bool operator==(const CornerKey&) const = default;
};

CornerKey corner_key(const unsigned char* p) {
  CornerKey k;
  for (int i = 0; i < 3; ++i) {
    k.bits[i] = read_u32(p + 4 * i);
    if (k.bits[i] == 0x80000000u) k.bits[i] = 0;
  }
  return k;
}

std::uint64_t corner_hash(const CornerKey& k) {
  std::uint64_t h = (std::uint64_t{k.bits[0]} << 32 | k.bits[1]) * 0x9E3779B97F4A7C15ull;
  h = (h ^ (h >> 29) ^ k.bits[2]) * 0xBF58476D1CE4E5B9ull;
  return h ^ (h >> 32);
}

// Binary STL, welded as Welder would weld it corner by corner, but side by side: the corners are sorted
// into buckets by their hash (in corner order within each bucket), each bucket finds the first corner of
// every point on its own, and one pass in corner order numbers the points as they first appear.
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
  // The caller checked that the size is exactly 84 + 50·count, so what follows is backed by data.
  const std::size_t corners = 3 * count;
  auto corner_at = [&](std::size_t c) { return data + 84 + 50 * (c / 3) + 12 + 12 * (c % 3); };
  constexpr std::size_t kPartCorners = 3 * 8192;
  const std::size_t parts = std::max<std::size_t>(1, (corners + kPartCorners - 1) / kPartCorners);
  const std::size_t buckets = std::bit_ceil(std::max<std::size_t>(1, corners / 4096));
  const int bucket_shift = 64 - std::countr_zero(buckets);  // a bucket: the hash's top bits
  auto bucket_of = [&](std::uint64_t h) {
    return buckets == 1 ? 0 : static_cast<std::size_t>(h >> bucket_shift);
  };
  const unsigned threads = threads_for(count, 16384, 0);

  // Count each part's corners per bucket, and find its first non-finite corner.
  std::vector<std::uint32_t> counts(parts * buckets, 0);
  std::vector<std::size_t> first_bad(parts, corners);
  parallel_chunks(parts, threads, [&](std::size_t k) {
    std::uint32_t* count_of = counts.data() + k * buckets;
    for (std::size_t c = k * kPartCorners; c < std::min(corners, (k + 1) * kPartCorners); ++c) {
      const unsigned char* p = corner_at(c);
      if (first_bad[k] == corners && !is_finite(Point3{read_f32(p), read_f32(p + 4), read_f32(p + 8)}))
        first_bad[k] = c;
      ++count_of[bucket_of(corner_hash(corner_key(p)))];
    }
  });
  for (const std::size_t c : first_bad) {
    if (c == corners) continue;
    const std::uint64_t k = c / 3, offset = 84 + 50 * k;
    fail(name, 0, 0,
         "triangle " + std::to_string(k + 1) + " (byte offset " + std::to_string(offset) +
             ") has a non-finite " + "coordinate in corner " + std::to_string(c % 3 + 1) + " (byte offset " +
             std::to_string(offset + 12 + 12 * (c % 3)) + ")",
         "every coordinate must be a finite number; repair the mesh and export it again");
  }

  // Sort the corners into buckets, in corner order within each (bucket-major, then part, then corner).
  struct Sorted {
    CornerKey key;
    std::uint32_t corner;
  };
  std::vector<std::size_t> bucket_begin(buckets + 1, 0);
  std::vector<std::size_t> at(parts * buckets);
  {
    std::size_t sum = 0;
    for (std::size_t b = 0; b < buckets; ++b) {
      bucket_begin[b] = sum;
      for (std::size_t k = 0; k < parts; ++k) at[k * buckets + b] = sum, sum += counts[k * buckets + b];
    }
    bucket_begin[buckets] = sum;
  }
  release(counts);
  std::vector<Sorted> sorted(corners);
  parallel_chunks(parts, threads, [&](std::size_t k) {
    std::size_t* next = at.data() + k * buckets;
    for (std::size_t c = k * kPartCorners; c < std::min(corners, (k + 1) * kPartCorners); ++c) {
      const CornerKey key = corner_key(corner_at(c));
      sorted[next[bucket_of(corner_hash(key))]++] = {key, static_cast<std::uint32_t>(c)};
    }
  });

  // In each bucket, every corner's first corner at the same point (open addressing on the hash's low bits).
  std::vector<std::uint32_t> first(corners);
  parallel_chunks(buckets, threads, [&](std::size_t b) {
    const std::size_t begin = bucket_begin[b], size = bucket_begin[b + 1] - begin;
    if (size == 0) return;
    std::vector<std::uint32_t> slots(std::bit_ceil(2 * size), 0);  // entry in `sorted` + 1, 0 = free
    const std::size_t mask = slots.size() - 1;
    for (std::size_t i = begin; i < begin + size; ++i) {
      const Sorted& corner = sorted[i];
      for (std::size_t s = static_cast<std::size_t>(corner_hash(corner.key)) & mask;; s = (s + 1) & mask) {
        if (slots[s] == 0) {
          slots[s] = static_cast<std::uint32_t>(i + 1);
          first[corner.corner] = corner.corner;
          break;
        }
        const Sorted& earlier = sorted[slots[s] - 1];
        if (earlier.key == corner.key) {
          first[corner.corner] = earlier.corner;
          break;
        }
      }
    }
  });
  release(sorted);

  // Number the points in the order they first appear; `first` becomes the corners' vertex numbers.
  for (std::size_t c = 0; c < corners; ++c) {
    if (first[c] != c) {
      first[c] = first[first[c]];
      continue;
    }
    const unsigned char* p = corner_at(c);
    first[c] = static_cast<std::uint32_t>(raw.vertices.size());
    raw.vertices.push_back({{read_f32(p) + 0.0, read_f32(p + 4) + 0.0, read_f32(p + 8) + 0.0},  // -0 + 0 = +0
                            {0, 0, 0, static_cast<std::int64_t>(84 + 50 * (c / 3))}});
  }
  raw.face_vertices = std::move(first);
  raw.face_ends.resize(count);
  raw.face_sources.resize(count);
  for (std::size_t k = 0; k < count; ++k) {
    raw.face_ends[k] = 3 * (k + 1);
    raw.face_sources[k] = {0, 0, 0, static_cast<std::int64_t>(84 + 50 * k)};
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
