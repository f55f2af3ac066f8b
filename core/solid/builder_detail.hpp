// Internals of SolidBuilder::build(), shared by its translation units (solid_builder.cpp: input and
// assembly; vertex_table.cpp: ids and vertices; face_loops.cpp: rings and planes of one face; winding.cpp:
// consistent outward orientation; edge_table.cpp: edges, markings and free lines). Not part of the public
// API. Faces are streamed: each is prepared in reused buffers and its edges entered at once, so only the
// solid under construction and the edge table grow with the input.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/format_number.hpp"
#include "core/solid/face_geometry.hpp"
#include "core/solid/solid.hpp"
#include "core/solid/solid_builder.hpp"
#include "core/tolerance.hpp"

namespace hlr::solid_detail {

// Collects diagnostics in the order they are found; build() returns no solid once any is an error.
class Diagnostics {
 public:
  explicit Diagnostics(std::vector<SolidDiagnostic>& out) : out_(out) {}
  void error(const char* code, std::string message, std::int64_t tag) {
    out_.push_back({SolidDiagnostic::Severity::Error, code, std::move(message), tag});
    has_errors_ = true;
  }
  void warning(const char* code, std::string message, std::int64_t tag) {
    out_.push_back({SolidDiagnostic::Severity::Warning, code, std::move(message), tag});
  }
  bool has_errors() const { return has_errors_; }
  void append(std::vector<SolidDiagnostic>& more) { insert(out_.size(), more); }  // moves them in, in order
  // The same, placed before the one at `at` (at most size()): where they belong in the stages' order.
  void insert(std::size_t at, std::vector<SolidDiagnostic>& more) {
    for (const SolidDiagnostic& d : more)
      has_errors_ = has_errors_ || d.severity == SolidDiagnostic::Severity::Error;
    out_.insert(out_.begin() + static_cast<std::ptrdiff_t>(at), std::make_move_iterator(more.begin()),
                std::make_move_iterator(more.end()));
    more.clear();
  }
  std::size_t size() const { return out_.size(); }

 private:
  std::vector<SolidDiagnostic>& out_;
  bool has_errors_ = false;
};

inline constexpr VertexIndex kNoVertex = 0xffffffffu;

// Tags by input position; an empty list means all are -1 (SolidBuilder stores none until one is given).
struct Tags {
  const std::vector<std::int64_t>& list;
  std::int64_t operator[](std::size_t i) const { return list.empty() ? -1 : list[i]; }
};

// The declared vertices, resolved: index = declaration order, leaving out a vertex whose id was declared
// before (references to that id keep the first declaration).
struct VertexTable {
  // The builder's positions, or `kept` when some were left out; not copied, so that the solid's copy
  // can wait until the edge table is done.
  const std::vector<Point3>& positions() const { return input_of.empty() ? *input_positions : kept; }
  const std::vector<Point3>* input_positions = nullptr;
  std::vector<Point3> kept;
  std::vector<bool> usable;     // false for non-finite positions (already reported)
  Tolerance tolerance;          // scaled to the largest coordinate of the scene
  std::size_t input_count = 0;  // vertices declared
  // Both empty when no id was declared twice, i.e. index = input number.
  std::vector<VertexIndex> input_of;  // index → input number
  std::vector<VertexIndex> table_of;  // input number → index (of the first declaration of its id)
  std::vector<VertexIndex> by_id;     // interned id → index, kNoVertex if no vertex has it
  const std::vector<std::uint32_t>* input_ids = nullptr;  // SolidBuilder::vertex_ids_
  const IdTable* ids = nullptr;
  const std::function<std::string(VertexIndex)>* label = nullptr;  // names indexed vertices, if set

  VertexIndex resolve(VertexRef ref) const;   // kNoVertex if no vertex has that id
  std::string ref_text(VertexRef ref) const;  // the id a reference names
  std::string id(VertexIndex v) const;
};

// Vertex stage (vertex_table.cpp): non-finite coordinates and duplicate ids are errors. `input_ids` and
// `ids` as in SolidBuilder.
VertexTable resolve_vertices(const std::vector<Point3>& positions, Tags tags,
                             const std::vector<std::uint32_t>& input_ids, const IdTable& ids,
                             const std::function<std::string(VertexIndex)>* label, Diagnostics& diagnostics);
// Two vertices at one position (within the table's tolerance) are an error, reported with the later one.
// Reads the table only, so it may run beside the face stages.
void report_vertex_twins(const VertexTable& table, Tags tags, Diagnostics& diagnostics);

// Closed loops of vertex indices stored back to back.
struct Loops {
  std::vector<VertexIndex> vertices;
  std::vector<std::uint32_t> ends;  // end of each loop in `vertices`

  std::size_t size() const { return ends.size(); }
  std::span<const VertexIndex> operator[](std::size_t k) const {
    const std::size_t begin = k == 0 ? 0 : ends[k - 1];
    return {vertices.data() + begin, ends[k] - begin};
  }
  void clear() {
    vertices.clear();
    ends.clear();
  }
  void close() { ends.push_back(static_cast<std::uint32_t>(vertices.size())); }  // ends the current loop
};

// One face in preparation; the buffers are reused from face to face. build() puts the resolved input
// rings (or the single loop of add_face_loop) into `loops`; prepare_face cleans them — they then fix the
// order in which the face's edges are first entered — and, if the face is valid, leaves its rings (outer
// first; holes opposite to it), on-face lines, plane and size (bounding-box diagonal of its vertices, the
// scale of its tolerances).
struct FaceWork {
  Loops loops;
  SmallVector<Ring, 1> rings;                              // as Face::rings: moves into the solid
  std::vector<std::pair<VertexIndex, VertexIndex>> lines;  // edges traversed both ways, lower index first
  bool rings_are_loops = false;                            // rings[k] == loops[k] for every k
  Plane plane;
  Vector3 area{};  // the rings' Newell normals summed: twice the face's area vector, holes subtracting
  double size = 0;
  Loops scratch_loops;  // prepare_face's own buffers
  std::vector<VertexIndex> scratch;
  std::vector<double> areas;
};

// Cleans, splits and checks one face (face_loops.cpp). `number` is its 1-based position in input order,
// the name used in messages ("face 3"); `from_loop` only changes wording. Returns whether it is valid.
bool prepare_face(FaceWork& work, bool from_loop, int number, std::int64_t tag, const VertexTable& vertices,
                  const SolidBuildOptions& options, Diagnostics& diagnostics);

// A face's traversal of an undirected edge: `forward` when it runs lo→hi.
struct EdgeUse {
  FaceIndex face;
  bool forward;
};

// All undirected edges named by faces and lines, in first-seen order (Desens' LINES order). The usual
// two ring traversals are stored inline; further ones (a non-manifold edge) in EdgeEntries::extra().
struct EdgeEntry {
  VertexIndex lo = 0, hi = 0;  // lo < hi
  FaceIndex face[2] = {kNoFace, kNoFace};
  FaceIndex marking_face = kNoFace;  // first face naming it as an on-face line
  std::uint8_t forward = 0;          // bit k: traversal k runs lo→hi
  std::uint8_t uses = 0;             // ring traversals: 0, 1, 2, or 3 for more than two
  bool free_line = false;            // from add_line, on no face
  EdgeUse use(int k) const { return {face[k], ((forward >> k) & 1) != 0}; }
};

class EdgeEntries {
 public:
  struct Extra {
    std::uint32_t entry;
    EdgeUse use;
  };
  // `vertex_count`: the solid's vertices, all edges' ends below it. Given, the lookup table keeps the
  // edges in the order of their lower vertex (see home()).
  // `indexed_entries`: how many of them the lookup table is sized for (all when 0).
  explicit EdgeEntries(std::size_t expected_entries, std::size_t vertex_count = 0,
                       std::size_t indexed_entries = 0);
  std::uint32_t get(VertexIndex a, VertexIndex b);         // its number; creates the entry if new
  std::uint32_t find(VertexIndex a, VertexIndex b) const;  // kNoEdge if absent
  void add_use(std::uint32_t e, EdgeUse use);
  EdgeEntry& operator[](std::uint32_t e) { return blocks_[e >> kShift][e & kMask]; }
  const EdgeEntry& operator[](std::uint32_t e) const { return blocks_[e >> kShift][e & kMask]; }
  std::uint32_t size() const { return size_; }
  std::vector<Extra>& extra() { return extra_; }  // traversals beyond the second, in order
  const std::vector<Extra>& extra() const { return extra_; }
  void release_index();  // frees the lookup table once no more get()/find() will come
  // Asks the memory for the slot of edge ab ahead of its get(): a face's edges are looked up a few faces
  // early, so the lookups of a large table do not wait on memory one after another.
  void prefetch(VertexIndex a, VertexIndex b) const {
    __builtin_prefetch(&slots_[home(std::min(a, b), std::max(a, b))]);
  }
  // Takes in `later`'s entries, entered from faces after all of this table's, as if entered here: those
  // already here get their uses, the others are numbered after this table's. number[j] is then later's
  // entry j's number here. Returns false, changing nothing, if a use beyond the second would result (a
  // non-manifold edge: enter the faces one by one instead, for its uses' order). Frees the lookup table.
  bool absorb(const EdgeEntries& later, std::vector<std::uint32_t>& number);
  // Frees the block holding entry e once e is its last entry: a last pass in order frees as it goes.
  void release_after(std::uint32_t e) {
    if ((e & kMask) == kMask) blocks_[e >> kShift] = std::vector<EdgeEntry>();
  }

 private:
  // Blocks of 2^kShift entries (the first one grows like a vector from the expected size): no copies of
  // the whole table as it grows. Large blocks are mapped by malloc on their own (over its largest mmap
  // threshold, 32 MiB), so freeing them returns the memory instead of leaving holes among the solid's
  // small allocations.
  static constexpr int kShift = 21;
  static constexpr std::uint32_t kMask = (1u << kShift) - 1;
  // Open addressing with the key in the slot: a lookup reads one slot, not also the entry.
  struct Slot {
    VertexIndex lo = 0, hi = 0;
    std::uint32_t entry = 0;  // entry + 1, 0 = empty
  };
  // An edge's first slot to look in. In vertex order (lower vertex v at v·slots/vertices, a few slots a
  // vertex): the faces of a large mesh come in spatial order (stdlib/mesh_locality.cpp), so one face's
  // edges and the next face's lie near each other in the table, where scattered over it each lookup of a
  // table larger than the cache waited on memory (the 10⁶-triangle torus's edges: 150–210 ms scattered,
  // 67–98 ms in order). Edges crowding round one vertex (a fan of thousands) would make long runs of
  // full slots: the first lookup that runs past kLongRun slots scatters the table by Fibonacci hashing
  // (top bits of key × 2^64/φ).
  std::size_t home(VertexIndex lo, VertexIndex hi) const {
    if (per_vertex_ != 0)
      return static_cast<std::size_t>((std::uint64_t{lo} * per_vertex_) >> 32) & (slots_.size() - 1);
    return static_cast<std::size_t>((((std::uint64_t{lo} << 32) | hi) * 0x9E3779B97F4A7C15ull) >> shift_);
  }
  static constexpr std::size_t kLongRun = 64;
  // Its slot, or the empty one it would take; `run` counts the slots looked at.
  std::size_t slot_of(VertexIndex lo, VertexIndex hi, std::size_t& run) const;
  std::size_t slot_of(VertexIndex lo, VertexIndex hi) const {
    std::size_t run = 0;
    return slot_of(lo, hi, run);
  }
  void index_again(std::size_t slot_count);  // rebuilds the table with slot_count slots
  void set_per_vertex();
  std::vector<std::vector<EdgeEntry>> blocks_;
  std::size_t expected_;
  std::uint32_t size_ = 0;
  std::vector<Slot> slots_;  // a power of two, at most half full
  int shift_ = 64;           // 64 − log2(slots_.size())
  std::size_t vertex_count_ = 0;
  std::uint64_t per_vertex_ = 0;  // slots a vertex, × 2^32; 0: scattered
  std::vector<Extra> extra_;
};

// Enters the edges of a valid face (edge_table.cpp): first-seen order from its cleaned loops (null when
// its rings are those loops), then its ring traversals (filling each ring's `edges` with entry numbers)
// and on-face lines.
void enter_face_edges(EdgeEntries& edges, FaceIndex face, SmallVector<Ring, 1>& rings, const Loops* loops,
                      std::span<const std::pair<VertexIndex, VertexIndex>> lines);

// Entering faces in order, face f asks for the slots of face f + kPrefetchFaces's edges (if valid and
// before `end`), so that the lookups of a large table do not wait on memory one after another.
inline constexpr std::size_t kPrefetchFaces = 8;
void prefetch_face_edges(const EdgeEntries& edges, const std::vector<Face>& faces,
                         const std::vector<char>& ready, std::size_t f, std::size_t end);

// The edges of the valid faces (ready[f] != 0), all with their rings as their loops and no on-face lines,
// entered as enter_face_edges face after face would — the same numbers, uses and order — by two halves of
// the faces side by side, the second half's entries then absorbed. The table is left without its lookup
// table.
EdgeEntries enter_plain_faces(std::vector<Face>& faces, const std::vector<char>& ready,
                              std::size_t expected_entries, std::size_t vertex_count);

// Reports edges used by more than two faces.
void report_non_manifold(const EdgeEntries& edges, Tags face_tags, const VertexTable& vertices,
                         Diagnostics& diagnostics);

// Makes windings consistent per connected component and closed components outward (winding.cpp;
// `areas` as FaceWork::area):
// reverses the rings of the faces it flips (with their `edges`), updates their planes and the uses in
// `edges`, and reports each flip. Returns whether every component is closed.
bool orient_faces(std::vector<Face>& faces, std::vector<Plane>& planes, const std::vector<bool>& valid,
                  const std::vector<Vector3>& areas, Tags face_tags, EdgeEntries& edges,
                  const VertexTable& vertices, const SolidBuildOptions& options, Diagnostics& diagnostics);

// Adds the add_line lines as markings or free lines, fills the solid's edge table from `edges` (kinds,
// concavity) and turns the rings' entry numbers into indices of solid.edges (edge_table.cpp). The solid
// has its faces and planes; `face_sizes` is needed only when there are lines. Frees `edges`.
void build_edge_table(Solid& solid, EdgeEntries& edges, const std::vector<bool>& valid,
                      const std::vector<double>& face_sizes, const std::vector<LineSpec>& lines,
                      const VertexTable& vertices, const SolidBuildOptions& options,
                      Diagnostics& diagnostics);

// Name of an edge for messages: "3–4" (vertex ids, lower index first).
std::string edge_name(const VertexTable& vertices, VertexIndex a, VertexIndex b);

}  // namespace hlr::solid_detail
