// Builds a validated Solid from vertex ids and faces, reporting every problem precisely.
// Checks (codes in brackets): unknown vertex [unknown-vertex], face with fewer than 3 distinct vertices
// [too-few-vertices], non-planar face with its deviation [non-planar], zero-area face [zero-area],
// duplicate vertex id or two ids at the same position [duplicate-vertex], NaN/inf coordinates
// [non-finite], an edge used by more than two faces or twice by one [non-manifold-edge], inconsistent
// winding (faces reoriented, with a warning) [reoriented], a surface that cannot be oriented (Möbius)
// [non-orientable], a hole outside its face or crossing it [bad-hole]; warnings for a vertex repeated
// in a row (dropped) [repeated-vertex] and a line from a vertex to itself (dropped) [degenerate-line].
// Messages name faces by their 1-based position in input order ("face 3"), lines likewise ("line 2"),
// vertices by id. Errors make build() return no solid; warnings do not.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/solid/solid.hpp"
#include "core/solid/vertex_ids.hpp"
#include "core/tolerance.hpp"

namespace hlr {

struct SolidDiagnostic {
  enum class Severity { Warning, Error };
  Severity severity = Severity::Error;
  std::string code;       // stable short name, e.g. "non-planar"
  std::string message;    // full sentence naming the face/vertex ids and what to do
  std::int64_t tag = -1;  // the tag given with the offending vertex/face/line (e.g. a source position)
};

struct SolidBuildOptions {
  // Edges between faces meeting at less than this dihedral deviation (degrees between normals) are
  // Smooth: drawn only on the contour. 0 means only coplanar edges are suppressed.
  double crease_angle_deg = 0;
  // Reorient faces whose winding disagrees with their neighbours (warning) instead of failing.
  bool fix_winding = true;
  // A face is planar when every vertex lies within planarity_tolerance × (face size) of its plane
  // (face size = diagonal of its bounding box). Raise it only for legacy data known to be warped:
  // Desens' carrier hull (faces 13–16) deviates by up to 2.7e-3. Faces beyond Tolerance::kPlanarity
  // but within this are accepted with a [non-planar] warning.
  double planarity_tolerance = Tolerance::kPlanarity;
  // Accept holes that cross or leave their face's outer ring (or cross each other) with a [bad-hole]
  // warning instead of an error; the face is then the even-odd region of its rings. For legacy data:
  // in Desens' carrier, face 17's hull outline pokes out past the deck slab's starboard notch.
  bool allow_crossing_holes = false;
};

struct SolidBuildResult {
  std::optional<Solid> solid;
  std::vector<SolidDiagnostic> diagnostics;
  bool ok() const { return solid.has_value(); }
};

class SolidBuilder {
 public:
  explicit SolidBuilder(SolidBuildOptions options = {});

  // Vertex ids are integers or identifiers, kept as text ("1", "top").
  void add_vertex(const std::string& id, Point3 position, std::int64_t tag = -1);
  // A planar face: outer loop counter-clockwise seen from outside, then holes.
  void add_face(const std::vector<std::string>& outer,
                const std::vector<std::vector<std::string>>& holes = {}, std::int64_t tag = -1);
  // A face given as one closed loop in the theses' style (Desens' LSTFAC, Albers' .SUR): edges traversed
  // in both directions within the loop are lines on the face (bridges to holes, markings), the rest
  // form the outer boundary and the holes.
  void add_face_loop(const std::vector<std::string>& loop, std::int64_t tag = -1);
  // A line between two vertices: a marking if both ends lie on one face (drawn, hides nothing), else a
  // free line.
  void add_line(const std::string& a, const std::string& b, std::int64_t tag = -1);

  // Indexed input (generators, mesh files), with the same checks and messages but no id strings kept: a
  // vertex added this way has its number among all added vertices as id, in decimal ("0", "1", ...),
  // and returns that number. Indexed faces and lines name vertices by such numbers; they behave exactly
  // like add_face and add_line with the decimal ids, so both styles may be mixed.
  VertexIndex add_vertex(Point3 position, std::int64_t tag = -1);
  // Many at once, tagged tags[i] (tags empty: none); the same as adding them one by one. Returns the first's
  // number.
  VertexIndex add_vertices(std::span<const Point3> positions, std::span<const std::int64_t> tags = {});
  // rings[0] is the outer loop, the others holes, as in add_face.
  void add_indexed_face(std::span<const std::vector<VertexIndex>> rings, std::int64_t tag = -1);
  // A face of one ring (no holes), the common case of mesh files: no vector per face.
  void add_indexed_polygon(std::span<const VertexIndex> ring, std::int64_t tag = -1);
  // Many such faces at once: face k lists vertices[ends[k − 1] .. ends[k]) (from 0 for k = 0) and has the
  // tag first_tag + k, or -1 when first_tag is -1. The same as adding them one by one.
  void add_indexed_polygons(std::span<const VertexIndex> vertices, std::span<const std::size_t> ends,
                            std::int64_t first_tag = -1);
  // A face given as one closed loop, as add_face_loop.
  void add_indexed_face_loop(std::span<const VertexIndex> loop, std::int64_t tag = -1);
  void add_indexed_line(VertexIndex a, VertexIndex b, std::int64_t tag = -1);
  // How messages name indexed vertices (a mesh file's own vertex numbers, say); by default their number.
  // Only the wording changes: ids given as text still match an indexed vertex by its number.
  void label_indexed_vertices(std::function<std::string(VertexIndex)> label) { label_ = std::move(label); }
  // Optional: room for this many more vertices, faces and vertex references in all rings, and for their
  // tags when `tagged`.
  void reserve(std::size_t vertices, std::size_t faces, std::size_t references, bool tagged = false);

  SolidBuildResult build() const;

 private:
  using VertexRef = solid_detail::VertexRef;
  static constexpr std::uint32_t kIndexedId = solid_detail::IdTable::kNone;
  VertexRef id_ref(const std::string& id);
  VertexRef index_ref(VertexIndex v);
  void end_ring();
  void end_face(std::int64_t tag, bool from_loop);
  static void add_tag(std::vector<std::int64_t>& tags, std::size_t position, std::int64_t tag);

  // The input as flat arrays; a face's rings are ring_ends_[face_ends_[f − 1] .. face_ends_[f]).
  SolidBuildOptions options_;
  std::vector<Point3> positions_;
  std::vector<std::int64_t> vertex_tags_;  // empty while every tag is -1 (likewise face_tags_)
  std::vector<std::uint32_t> vertex_ids_;  // interned id, or kIndexedId; empty while every vertex is indexed
  solid_detail::IdTable ids_;
  std::vector<VertexRef> refs_;           // all rings, back to back
  std::vector<std::uint32_t> ring_ends_;  // end of each ring in refs_
  std::vector<std::uint32_t> face_ends_;  // end of each face's rings in ring_ends_
  std::vector<std::int64_t> face_tags_;
  std::vector<bool> face_is_loop_;  // from add_face_loop: split into rings and on-face lines by build()
  std::vector<solid_detail::LineSpec> lines_;
  std::function<std::string(VertexIndex)> label_;  // empty: the number in decimal
};

}  // namespace hlr
