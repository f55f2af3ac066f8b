// Internals of SolidBuilder::build(), shared by its translation units (solid_builder.cpp: vertices and
// assembly; face_loops.cpp: rings and planes of one face; winding.cpp: consistent outward orientation;
// edge_table.cpp: edges, markings and free lines). Not part of the public API.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

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

 private:
  std::vector<SolidDiagnostic>& out_;
  bool has_errors_ = false;
};

// Shortest decimal text of a number for messages: "0.25", "1e-06", "nan".
std::string format_number(double value);

// The declared vertices, resolved: index = insertion order (duplicate ids keep their first declaration).
struct VertexTable {
  std::vector<Point3> positions;
  std::vector<std::string> ids;
  std::vector<bool> usable;  // false for non-finite positions (already reported)
  std::unordered_map<std::string, VertexIndex> index_of;
  Tolerance tolerance;  // scaled to the largest coordinate of the scene
};

// One input face after resolution and checks. `number` is its 1-based position in input order, the
// name used in messages ("face 3").
struct PreparedFace {
  int number = 0;
  std::int64_t tag = -1;
  bool valid = false;
  std::vector<Ring> rings;                                      // outer first; holes opposite to it
  std::vector<std::pair<VertexIndex, VertexIndex>> lines;       // on-face lines (edges traversed both ways)
  std::vector<std::vector<VertexIndex>> traversal;              // cleaned input loops: fixes edge order
  Plane plane;
  double size = 0;  // bounding-box diagonal of the face's vertices, the scale of its tolerances
};

// Resolves, cleans, splits and checks one face (face_loops.cpp). `input_rings` are the outer ring and
// holes (add_face) or the single loop (add_face_loop); `from_loop` only changes wording.
PreparedFace prepare_face(const std::vector<std::vector<std::string>>& input_rings, bool from_loop, int number,
                          std::int64_t tag, const VertexTable& vertices, const SolidBuildOptions& options,
                          Diagnostics& diagnostics);

// A face's traversal of an undirected edge: `forward` when it runs lo→hi.
struct EdgeUse {
  FaceIndex face;
  bool forward;
};

// All undirected edges named by faces and lines, in first-seen order (Desens' LINES order).
struct EdgeEntry {
  VertexIndex lo = 0, hi = 0;      // lo < hi
  std::vector<EdgeUse> uses;       // ring traversals
  FaceIndex marking_face = kNoFace;  // first face naming it as an on-face line
  bool free_line = false;          // from add_line, on no face
};

class EdgeEntries {
 public:
  EdgeEntry& get(VertexIndex a, VertexIndex b);  // creates the entry if new
  const EdgeEntry* find(VertexIndex a, VertexIndex b) const;
  std::vector<EdgeEntry>& list() { return list_; }
  const std::vector<EdgeEntry>& list() const { return list_; }

 private:
  static std::uint64_t key(VertexIndex a, VertexIndex b);
  std::vector<EdgeEntry> list_;
  std::unordered_map<std::uint64_t, std::size_t> index_;
};

// Enters every ring edge and on-face line of the valid faces (edge_table.cpp) and reports edges used
// by more than two faces.
EdgeEntries collect_edges(const std::vector<PreparedFace>& faces, const VertexTable& vertices,
                          Diagnostics& diagnostics);

// Makes windings consistent per connected component and closed components outward (winding.cpp):
// reverses the rings of the faces it flips, updates their planes and the uses in `edges`, and reports
// each flip. Returns whether every component is closed.
bool orient_faces(std::vector<PreparedFace>& faces, EdgeEntries& edges, const VertexTable& vertices,
                  const SolidBuildOptions& options, Diagnostics& diagnostics);

// Fills the solid's edge table from `edges` (kinds, concavity), then adds the add_line lines as
// markings or free lines (edge_table.cpp).
struct LineSpec {
  std::string a, b;
  std::int64_t tag;
};
void build_edge_table(Solid& solid, EdgeEntries& edges, const std::vector<PreparedFace>& faces,
                      const std::vector<LineSpec>& lines, const VertexTable& vertices,
                      const SolidBuildOptions& options, Diagnostics& diagnostics);

// Name of an edge for messages: "3–4" (vertex ids, lower index first).
std::string edge_name(const VertexTable& vertices, VertexIndex a, VertexIndex b);

}  // namespace hlr::solid_detail
