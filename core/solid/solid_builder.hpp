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
#include <optional>
#include <string>
#include <vector>

#include "core/solid/solid.hpp"
#include "core/tolerance.hpp"

namespace hlr {

struct SolidDiagnostic {
  enum class Severity { Warning, Error };
  Severity severity = Severity::Error;
  std::string code;     // stable short name, e.g. "non-planar"
  std::string message;  // full sentence naming the face/vertex ids and what to do
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
  void add_face(const std::vector<std::string>& outer, const std::vector<std::vector<std::string>>& holes = {},
                std::int64_t tag = -1);
  // A face given as one closed loop in the theses' style (Desens' LSTFAC, Albers' .SUR): edges traversed
  // in both directions within the loop are lines on the face (bridges to holes, markings), the rest
  // form the outer boundary and the holes.
  void add_face_loop(const std::vector<std::string>& loop, std::int64_t tag = -1);
  // A line between two vertices: a marking if both ends lie on one face (drawn, hides nothing), else a
  // free line.
  void add_line(const std::string& a, const std::string& b, std::int64_t tag = -1);

  SolidBuildResult build() const;

 private:
  struct VertexInput {
    std::string id;
    Point3 position;
    std::int64_t tag;
  };
  struct FaceInput {
    std::vector<std::vector<std::string>> rings;  // outer first, or the single loop of add_face_loop
    bool from_loop;                               // split into rings and on-face lines by build()
    std::int64_t tag;
  };
  struct LineInput {
    std::string a, b;
    std::int64_t tag;
  };
  SolidBuildOptions options_;
  std::vector<VertexInput> vertices_;
  std::vector<FaceInput> faces_;
  std::vector<LineInput> lines_;
};

}  // namespace hlr
