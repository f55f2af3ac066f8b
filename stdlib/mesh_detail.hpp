// Internals of mesh import shared by the per-format parsers (mesh_off/obj/stl/albers.cpp), the text
// scanner (mesh_text.cpp), triangulation (mesh_triangulate.cpp) and the common assembly into a Solid
// (mesh_build.cpp). Not part of the stdlib API.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/geometry/vector.hpp"
#include "stdlib/mesh_import.hpp"

namespace hlr::stdlib::mesh_detail {

// ---- raw mesh: what a parser read, before any repair -------------------------------------------------

// Where a record came from: a line and column of a text file, or a byte offset of a binary one.
struct Source {
  bool operator==(const Source&) const = default;
  int file = 0;  // index into RawMesh::files
  int line = 0;
  int column = 0;
  std::int64_t offset = -1;  // binary data: byte offset of the record
};

struct RawVertex {
  Point3 position;
  Source where;
  bool operator==(const RawVertex&) const = default;
};

struct RawLine {
  std::uint32_t a = 0, b = 0;
  Source where;
  bool operator==(const RawLine&) const = default;
};

struct RawMesh {
  std::vector<std::string> files;  // names used in problems
  std::string face_noun = "face";  // "face", "facet", "triangle", "surface" (by value: == compares words)
  int vertex_base = 0;             // the number of the first vertex in messages (OFF 0, others 1)
  bool welded_by_format = false;   // STL: exact welding is how its vertices are found, not a repair
  std::vector<RawVertex> vertices;
  // Faces back to back (one allocation for all, not one per face): face k ("<noun> k+1" in messages)
  // lists face_vertices[face_ends[k-1] .. face_ends[k]), indices into `vertices` checked by the parser.
  std::vector<std::uint32_t> face_vertices;
  std::vector<std::size_t> face_ends;
  std::vector<Source> face_sources;
  std::vector<RawLine> lines;
  std::vector<MeshProblem> warnings;  // found while parsing

  std::size_t face_count() const { return face_ends.size(); }
  std::span<const std::uint32_t> face(std::size_t k) const {
    const std::size_t begin = k == 0 ? 0 : face_ends[k - 1];
    return {face_vertices.data() + begin, face_ends[k] - begin};
  }
  // Ends the face whose vertices were appended to face_vertices since the last one.
  void end_face(const Source& where) {
    face_ends.push_back(face_vertices.size());
    face_sources.push_back(where);
  }
  bool operator==(const RawMesh&) const = default;  // for tests comparing two readers
};

// Points by their exact coordinates, -0 and +0 being equal (welding): open addressing, a slot holding a
// stored point's index and 32 bits of its hash, so that a lookup touches one cache line (and the point
// only when those bits match), not a node per point as std::unordered_map would. Eight bytes a slot, not
// the 32 of the coordinates themselves: the table of a 10⁶-triangle mesh is 8 MB of fresh memory, not 32.
// The points are the caller's: point_at(i) gives the point stored with index i.
class ExactPointIndex {
 public:
  explicit ExactPointIndex(std::size_t expected = 0);
  // The index stored for p, or `index` (now stored for p) when p is new.
  template <typename PointAt>
  std::uint32_t insert(Point3 p, std::uint32_t index, const PointAt& point_at) {
    if (2 * (size_ + 1) > slots_.size()) grow(point_at);
    const Key key = key_of(p);
    const std::uint64_t hash = hash_of(key);
    const auto fingerprint = static_cast<std::uint32_t>(hash >> 32);
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t s = static_cast<std::size_t>(hash) & mask;; s = (s + 1) & mask) {
      Slot& slot = slots_[s];
      if (slot.index == kEmpty) {
        slot = {fingerprint, index};
        ++size_;
        return index;
      }
      if (slot.fingerprint == fingerprint && key_of(point_at(slot.index)) == key) return slot.index;
    }
  }

 private:
  using Key = std::array<std::uint64_t, 3>;
  struct Slot {
    std::uint32_t fingerprint;  // the hash's top half
    std::uint32_t index;        // kEmpty: free
  };
  static constexpr std::uint32_t kEmpty = 0xffffffffu;
  static Key key_of(Point3 p);
  static std::uint64_t hash_of(const Key& key);
  template <typename PointAt>
  void grow(const PointAt& point_at) {
    std::vector<Slot> old(2 * slots_.size(), Slot{0, kEmpty});
    old.swap(slots_);
    const std::size_t mask = slots_.size() - 1;
    for (const Slot& slot : old) {
      if (slot.index == kEmpty) continue;
      std::size_t s = static_cast<std::size_t>(hash_of(key_of(point_at(slot.index)))) & mask;
      while (slots_[s].index != kEmpty) s = (s + 1) & mask;
      slots_[s] = slot;
    }
  }
  std::vector<Slot> slots_;  // a power of two, at most half full
  std::size_t size_ = 0;
};

// The readers of each text format: fast where they can (false: declined), careful otherwise (throws
// MeshImportError at the first problem). Both give the same RawMesh for every file the fast one takes.
// OFF's records are read in parallel chunks of about `chunk_bytes` (split at line ends); tests pass small
// chunks to hold the split to the careful reader's lines and columns.
constexpr std::size_t kOffChunkBytes = 128 * 1024;
bool read_off_fast(std::string_view text, const std::string& name, const MeshImportOptions& options,
                   RawMesh& raw, std::size_t chunk_bytes = kOffChunkBytes);
RawMesh read_off_careful(std::string_view text, const std::string& name, const MeshImportOptions& options);
bool read_obj_fast(std::string_view text, const std::string& name, const MeshImportOptions& options,
                   RawMesh& raw);
RawMesh read_obj_careful(std::string_view text, const std::string& name, const MeshImportOptions& options);
bool read_stl_ascii_fast(std::string_view text, const std::string& name, const MeshImportOptions& options,
                         RawMesh& raw);
// `could_be_binary`: the size allows a binary STL, so problems add that it may be a damaged one.
RawMesh read_stl_ascii_careful(std::string_view text, const std::string& name,
                               const MeshImportOptions& options, bool could_be_binary);

// The fast reader's raw mesh, or the careful reader's where the fast one declines.
template <typename Fast, typename Careful>
RawMesh fast_or_careful(Fast fast, Careful careful, std::string_view text, const std::string& name,
                        const MeshImportOptions& options) {
  RawMesh raw;
  if (!fast(text, name, options, raw)) raw = careful(text, name, options);
  return raw;
}

// A file of each format read into a raw mesh (fast if possible, else carefully).
RawMesh read_off(std::string_view text, const std::string& name, const MeshImportOptions& options);
RawMesh read_obj(std::string_view text, const std::string& name, const MeshImportOptions& options);
RawMesh read_stl(std::string_view bytes, const std::string& name, const MeshImportOptions& options);

// Repairs the raw mesh (welding, repeated vertices, degenerate faces, non-planar polygons), builds the
// Solid through SolidBuilder and turns its diagnostics into warnings or a MeshImportError.
ImportedMesh build_mesh(RawMesh raw, const MeshImportOptions& options);

// ---- locality (mesh_locality.cpp) ----------------------------------------------------------------------

// Meshes of at least this many faces reach the builder in spatial order (mesh_build.cpp): below it a mesh's
// vertices and faces stay in cache whatever their order.
constexpr std::size_t kSpatialOrderFaces = 8192;
// The points' indices in the order of a Morton curve through their bounding box (1024 cells an axis; points
// in one cell keep their order).
std::vector<std::uint32_t> morton_order(std::span<const Point3> points);
// The faces (face k lists vertices[ends[k − 1] .. ends[k]), from 0 for k = 0) in the order of their least
// vertex; faces with the same least vertex keep their order.
std::vector<std::uint32_t> faces_by_least_vertex(std::span<const std::uint32_t> vertices,
                                                 std::span<const std::size_t> ends, std::size_t vertex_count);
// The faces in that order: their vertices back to back in `ordered`, each face's end in `ordered_ends`.
void order_faces_by_least_vertex(std::span<const std::uint32_t> vertices, std::span<const std::size_t> ends,
                                 std::size_t vertex_count, std::vector<std::uint32_t>& ordered,
                                 std::vector<std::size_t>& ordered_ends);

// ---- problems ------------------------------------------------------------------------------------------

[[noreturn]] void fail(const std::string& file, int line, int column, std::string message,
                       std::string hint = {});

// A token for messages: quoted, non-printable bytes escaped, long tokens shortened.
std::string quoted(std::string_view token);

// The first `size` bytes of the open file `fd`, read by parts of 4 MB side by side (import_mesh, files of
// 16 MB or more). Nothing when a part cannot be read or the file's size is not `size`: the caller then
// reads it one part after the other.
std::optional<std::string> read_in_parts(int fd, std::size_t size);

// ---- text scanning ---------------------------------------------------------------------------------------

struct Token {
  std::string_view text;
  int column = 0;  // 1-based
};

// Splits text into lines ending in "\n", "\r\n" or "\r" (a UTF-8 byte-order mark is skipped).
class LineScanner {
 public:
  explicit LineScanner(std::string_view text);
  bool next();  // advances to the next line; false at the end of the text
  int line() const { return line_; }
  std::string_view text() const { return current_; }
  // Whitespace-separated tokens of the current line, stopping at `comment` (0 = no comments).
  const std::vector<Token>& tokens(char comment = 0);

 private:
  std::string_view rest_, current_;
  int line_ = 0;
  std::vector<Token> tokens_;
};

// The fast reader of the common case (mesh_fast_text.cpp): records of plain decimal numbers separated
// by blanks, one record per line. It never reports a problem: where the text is anything else (a
// malformed or unusual token, a line it cannot place) it declines, and the format's careful reader —
// LineScanner and LineContext — reads the whole file again and says what is wrong. Lines and columns
// are counted as LineScanner counts them.
class FastCursor {
 public:
  explicit FastCursor(std::string_view text, char comment = 0);
  // A cursor over part of a text that starts at the beginning of line `first_line` (no byte-order mark).
  FastCursor(std::string_view part, int first_line, char comment);
  // Moves to the first token of the next line holding data, skipping blank lines and comments; false at
  // the end of the text. Call it at the start of the text or at the end of a record's line.
  bool next_record();
  bool real(double& out);            // a finite real, as parse_real reads it without a leading '+'
  bool index(std::uint64_t& out);    // decimal digits only (at most 18)
  bool word(std::string_view& out);  // any token
  bool end_of_line();                // only blanks or a comment left: moves past the line end
  void skip_line();                  // to the start of the next line
  bool at_line_end() const;          // nothing but blanks or a comment before the line end
  int line() const { return line_; }
  int column() const;  // of the next token
  const char* position() const { return p_; }

 private:
  bool boundary(const char* q) const;  // a token may end at q
  void skip_blanks();
  const char *p_, *end_, *line_start_;
  int line_ = 1;
  char comment_;
};

// Splitting a text for readers that work in parallel: parts of about `bytes` each (at least one), every
// part but the last ending just after a '\n'.
std::vector<std::string_view> split_at_line_ends(std::string_view text, std::size_t bytes);
// The lines ('\n'-terminated, the last may lack it) of a part and how many hold data (the lines
// FastCursor::next_record stops at). False when the part holds a lone '\r', which FastCursor counts as
// a line end: the counts would then differ from its lines.
struct PartCounts {
  std::size_t lines = 0, records = 0;
};
bool count_lines_and_records(std::string_view part, char comment, PartCounts& out);

// Parsing of numbers in one line of one file, reporting problems at the token.
class LineContext {
 public:
  LineContext(const std::string& file, int line) : file_(file), line_(line) {}
  // A finite real (decimal, optional sign and exponent; "nan"/"inf" and overflow are errors, underflow
  // is zero). `what` names the value in messages, e.g. "the y coordinate".
  double real(const Token& t, const char* what) const;
  // A real that may be non-finite (facet normals, which are ignored anyway).
  double any_real(const Token& t, const char* what) const;
  // An integer in [lo, hi] (decimal, optional sign, leading zeros allowed).
  std::int64_t integer(const Token& t, const char* what, std::int64_t lo, std::int64_t hi) const;
  [[noreturn]] void fail(int column, std::string message, std::string hint = {}) const;
  const std::string& file() const { return file_; }
  int line() const { return line_; }

 private:
  const std::string& file_;
  int line_;
};

// Whole-token parses without reporting (false when the token is not of that form).
bool parse_real(std::string_view text, double& out);  // out may be non-finite for "nan"/"inf"
bool parse_integer(std::string_view text, std::int64_t& out);
bool iequals(std::string_view a, std::string_view b);  // ASCII case-insensitive

// ---- triangulation
// -----------------------------------------------------------------------------------------

using Triangle = std::array<std::uint32_t, 3>;

// Triangulates a simple polygon (ring of indices into `points`, no repeated vertex) seen along `normal`,
// keeping its winding: a fan when its projection is convex, else ear clipping (an ear at a time, the
// first convex vertex whose triangle holds no other vertex; if none exists because the projection
// self-overlaps, the most convex vertex). `budget` bounds the total work across calls; returns false
// (and no triangles) once it is exhausted.
bool triangulate(const std::vector<Point3>& points, const std::vector<std::uint32_t>& ring, Vector3 normal,
                 std::vector<Triangle>& out, std::int64_t& budget);

}  // namespace hlr::stdlib::mesh_detail
