// Per-frame preparation: view-space geometry, facing, culling, near-plane clipping and projection.
// Produces the two lists the engine works on: occluders (faces that can hide) and candidates (edge
// pieces that may be drawn).
#pragma once

#include <cstdint>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/geometry/rect2.hpp"
#include "core/hlr/ring_edge_grid.hpp"
#include "core/hlr/scene.hpp"
#include "core/hlr/visible_segment.hpp"

namespace hlr {

// A face that can hide things, clipped to the near plane and projected.
struct Occluder {
  std::uint32_t object = 0;
  FaceIndex face = kNoFace;
  // View-space plane n·v + offset = 0 and the sign of the eye's side of it: a view point v is
  // behind the face when eye_side·(n·v + offset) < 0.
  Vector3 normal{};
  double offset = 0;
  double eye_side = 1;
  double min_depth = 0;           // nearest view depth of the clipped polygon
  Rect2 bounds;                   // picture bounds of the clipped polygon
  double picture_tolerance = 0;   // Tolerance::picture of its projected points
  std::uint32_t first_point = 0;  // into FrameSetup::polygon_points
  std::uint32_t first_ring = 0;   // into FrameSetup::ring_ends
  std::uint32_t ring_count = 0;
  std::int32_t grid = -1;  // into FrameSetup::ring_grids, for occluders of many points
};

// An edge piece to examine, already clipped to the near plane: view points a→b, picture points.
struct Candidate {
  std::uint32_t object = 0;
  std::uint32_t edge = 0;
  std::uint32_t other = 0;
  SegmentSource source = SegmentSource::Edge;
  bool culled = false;  // hidden by the back-face rules alone (no occlusion test needed)
  bool hatch = false;   // a hatch line (EdgeKind::Hatch): only its visible pieces are kept
  // Faces that must not be tested against this edge (its own faces): (own_object0(), own_face0) and
  // (own_object1(), own_face1).
  FaceIndex own_face0 = kNoFace, own_face1 = kNoFace;
  // View points of the clipped ends. World points are not stored (the candidate list is the frame's
  // largest structure): they are the camera's inverse applied to these.
  Point3 view0, view1;
  Point2 pic0, pic1;             // picture points of the clipped ends
  double picture_tolerance = 0;  // Tolerance::picture of its end points (set_picture_tolerance)

  std::uint32_t own_object0() const { return object; }
  std::uint32_t own_object1() const { return source == SegmentSource::Intersection ? other : object; }
};

struct FrameSetup {
  std::vector<Occluder> occluders;
  std::vector<Point2> polygon_points;  // all occluder rings, concatenated
  // Per point: if the ring edge starting there is a seam — shared with a neighbouring occluder of the
  // same solid that faces the same way, so the two cover it together — that neighbour's face, else kNoFace.
  std::vector<FaceIndex> polygon_seams;
  std::vector<std::uint32_t> ring_ends;  // end offset (exclusive) of each ring in polygon_points
  std::vector<RingEdgeGrid> ring_grids;  // over the rings of the occluders of many points
  std::vector<Candidate> candidates;
  double length_tolerance = 0;           // view-space
  Rect2 picture_bounds = Rect2::none();  // of all candidates
  // Per object, kept for the intersection candidates: each face's facing (see face_facing) and whether
  // the object is culled whole (a closed solid wholly in front of the eye, not passing through itself,
  // shows only its front faces).
  std::vector<std::vector<std::int8_t>> facing;
  std::vector<char> cull;
  // What the exact fallbacks read: the scene's world coordinates (it outlives the frame), and whether the
  // camera's view map keeps handedness (+1) or mirrors it (−1, Albers' eye system), which turns a world
  // orientation into the view-space side of a face.
  const Scene* scene = nullptr;
  int handedness = 1;
};

// What a frame does with the back faces of a closed solid wholly in front of the eye that does not pass
// through itself: such a solid's back faces hide nothing its front faces do not, and what lies on them is
// hidden.
enum class BackFaces {
  Cull,  // they are not occluders, and its edges that only they show are culled (Candidate::culled)
  // Occlusion levels: the same for a solid whose box meets no other solid's — a sight line to a point
  // outside it crosses its surface in pairs, front then back, so each front face stands for two surfaces
  // (FrameSetup::cull) and a culled edge, on its back, has one surface less: it is kept to be examined.
  // A solid whose box meets another's may cross or hold it: nothing of it is culled.
  CountLevels,
};

// Sets c.picture_tolerance from its current picture and view end points.
void set_picture_tolerance(Candidate& c, const Camera& camera, double length_tolerance);

// Culled candidates (hidden by the back-face rules alone) are kept only when `keep_culled` is set.
// Objects are prepared in parallel as core/parallel.hpp's `threads` says (0: the caller's arena). The
// candidates are the solids' edges; append_intersection_candidates() adds the lines where faces cross.
// `assume_uncrossed` culls a closed solid without asking whether it passes through itself (the search
// may still be running); the caller must check that guess (FrameSetup::cull) once it has the answer.
FrameSetup prepare_frame(const Scene& scene, const Camera& camera, bool keep_culled, unsigned threads = 0,
                         bool assume_uncrossed = false, BackFaces back_faces = BackFaces::Cull);

// Appends to the candidates of prepare_frame(scene, camera, keep_culled, …) the pieces of the lines where
// faces cross (of two solids, or of one: Solid::self_crossings, searched for now if not yet known),
// clipped to the near plane and projected.
void append_intersection_candidates(FrameSetup& setup, const Scene& scene, const Camera& camera,
                                    bool keep_culled);

}  // namespace hlr
