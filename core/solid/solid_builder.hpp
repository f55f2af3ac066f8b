// Builds a validated Solid from vertex ids and faces, reporting every problem precisely.
// Checks (codes in brackets): unknown vertex [unknown-vertex], face with fewer than 3 distinct vertices
// [too-few-vertices], non-planar face with its deviation [non-planar], zero-area face [zero-area],
// duplicate vertex id or two ids at the same position [duplicate-vertex], NaN/inf coordinates
// [non-finite], an edge used by more than two faces [non-manifold-edge], inconsistent winding
// (faces reoriented, with a warning) [reoriented], a hole outside its face or crossing it [bad-hole].
// Errors make build() return no solid; warnings do not.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/solid/solid.hpp"

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
    std::vector<std::vector<std::string>> rings;  // outer first
    std::vector<std::pair<std::string, std::string>> lines;  // on-face lines from add_face_loop
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
