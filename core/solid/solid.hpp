// A polyhedral solid after validation: vertices, planar faces (with holes), the edge table with face
// adjacency, marking lines and free lines. Build one with SolidBuilder (solid_builder.hpp), which checks
// the input and reports precise diagnostics; the engine relies on the invariants stated here.
#pragma once

#include <atomic>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/geometry/affine3.hpp"
#include "core/geometry/vector.hpp"
#include "core/small_vector.hpp"
#include "core/solid/derived_cache.hpp"

namespace hlr {

using VertexIndex = std::uint32_t;
using FaceIndex = std::int32_t;  // -1 where there is no face
inline constexpr FaceIndex kNoFace = -1;
inline constexpr std::uint32_t kNoEdge = 0xffffffffu;

// A closed loop of vertex indices (the closing edge back to the first vertex is implied). Up to four
// vertices are kept inline (SmallVector): a triangle or quad face needs no allocation.
struct Ring {
  SmallVector<VertexIndex, 4> vertices;
  // edges[i]: index into Solid::edges of the edge vertices[i]→vertices[i+1], so the engine can tell a
  // face's outline from the seams it shares with its neighbours (kNoEdge if unknown). Filled by
  // link_ring_edges().
  SmallVector<std::uint32_t, 4> edges = {};
};

// A planar polygon. rings[0] is the outer boundary, counter-clockwise seen from outside (from the side
// the normal points to); rings[1..] are holes, clockwise seen from outside. Containment is even-odd over
// all rings, so a hole touching the outer ring at one vertex is fine. (An island inside a hole is a
// further ring, counter-clockwise again.)
struct Face {
  SmallVector<Ring, 1> rings;  // one inline: most faces have no hole
};

// Plane n·p + d = 0 with unit outward normal n.
struct Plane {
  Vector3 normal{};
  double offset = 0;
  double signed_distance(Point3 p) const { return dot(normal, to_vector(p)) + offset; }
};

enum class EdgeKind : std::uint8_t {
  Feature,   // between two faces at a dihedral angle above the crease angle: always a candidate
  Smooth,    // between two non-coplanar faces below the crease angle: drawn only on the contour
  Flat,      // between two coplanar faces: never drawn
  Boundary,  // on exactly one face (open surface): always a candidate
  Marking,   // a line lying on a face: drawn where visible, hides nothing
  Free,      // a line on no face: drawn where visible, hides nothing
  Hatch,     // shading laid on a face (core/solid/hatching.hpp): a marking the devices draw in the hatch pen,
             // never as a hidden line
};

// An undirected edge. For edges between two faces, `left` is the face that traverses v0→v1 (the edge
// has that face on its left seen from outside) and `right` the face that traverses v1→v0.
struct SolidEdge {
  VertexIndex v0 = 0, v1 = 0;
  FaceIndex left = kNoFace, right = kNoFace;
  EdgeKind kind = EdgeKind::Feature;
  bool concave = false;  // dihedral angle measured outside the solid below 180° (Pfister's c > 0)
};

// A piece of the line where two faces of one solid cross (parts of one mesh that interpenetrate), in the
// solid's coordinates. Faces that share an edge are not said to cross; faces that share one vertex cross
// where they pass through each other from it (p0 is then that vertex).
struct SelfCrossing {
  Point3 p0, p1;
  FaceIndex face0 = kNoFace, face1 = kNoFace;  // face0 < face1
};

// Unit normals at the corners of each face's outer ring, each the angle-weighted mean of the face normals
// round its vertex across smooth and flat edges (a crease keeps a normal a side): the normals of the smooth
// surface the mesh stands for (core/solid/corner_normals.cpp; smooth contours, core/hlr/smooth_contours.hpp).
struct CornerNormals {
  std::vector<std::uint32_t>
      first;                     // per face, the index of its outer ring's first corner; one more at the end
  std::vector<Vector3> normals;  // per corner, in ring order
};

struct Solid {
  std::vector<Point3> vertices;
  std::vector<Face> faces;
  std::vector<Plane> planes;     // one per face, outward
  std::vector<SolidEdge> edges;  // each shared edge exactly once; markings and free lines too
  // Every boundary edge has exactly two faces traversing it in opposite directions: the surface encloses
  // a volume, so back faces may be culled while the solid lies wholly in front of the eye.
  bool closed = false;
  // Some edge joins two triangles folded flat onto each other: exactly in one plane, on the same side of
  // the edge (a concave face split into a fan folds a triangle back over its neighbours). The surface then
  // winds negatively round the points under the fold, as round a fold through itself, so its back faces
  // are not culled.
  bool folded = false;
  double crease_angle_deg = 0;  // the crease angle the edge kinds were classified with
  // It stands for a smooth surface: its outline is drawn as that surface's contour, interpolated across its
  // faces (core/hlr/smooth_contours.hpp), instead of as its Smooth edges on the contour.
  bool smooth_contours = false;
  // The pen its Hatch edges are drawn in (1..255); 0: the pen the solid is drawn in.
  int hatch_pen = 0;

  DerivedCache<std::vector<SelfCrossing>> self_crossing_cache;
  DerivedCache<CornerNormals> corner_normal_cache;

  // This solid moved by `worldFromObject` (any invertible affine map; a mirror keeps faces outward).
  Solid transformed(const Affine3& worldFromObject) const;

  // Where faces of this solid cross each other (core/solid/self_crossings.cpp), sorted by faces.
  const std::vector<SelfCrossing>& self_crossings() const;
  // Its corner normals (core/solid/corner_normals.cpp), computed once.
  const CornerNormals& corner_normals() const;
};

// Fills Ring::edges of every face from Solid::edges (the builder and transformed() call it).
void link_ring_edges(Solid& solid);

// Newell's normal of a ring (length = twice the area; direction by the right-hand rule).
Vector3 newell_normal(const std::vector<Point3>& vertices, std::span<const VertexIndex> ring);
inline Vector3 newell_normal(const std::vector<Point3>& vertices, const Ring& ring) {
  return newell_normal(vertices, std::span<const VertexIndex>(ring.vertices));
}

}  // namespace hlr
