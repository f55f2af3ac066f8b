// Smooth contours of curved meshes (tracker issue 36). A triangle mesh that stands for a smooth surface (a
// scan, a sphere, a torus) has, on its picture, an outline made of whole mesh edges: a zigzag. The smooth
// surface it approximates has for its contour the zero set of g(p) = n(p)·(p − eye) (n·d for a view
// direction d), n the surface normal. With n interpolated from normals at the corners — each the
// angle-weighted mean of the face normals round the vertex, across smooth and flat edges only, so a crease
// keeps a normal a side — g is linear inside each triangle (a polygon face is taken as a fan from its first
// corner), and its zero set there is one segment between two of its sides: a smooth curve across the
// mesh (Hertzmann & Zorin 2000; Bénard & Hertzmann's contour survey). Where two faces share an edge and a
// smooth group, the point on it is computed from the same two corners in the same order, so neighbouring
// segments meet exactly and the pen plan joins them into one stroke.
//
// Such a solid draws these segments instead of its Smooth edges on the contour. Each lies on its face, and
// is hidden exactly like an edge by every face except those near its own face: of its solid, with a
// vertex within the face's longest side of the face's centre. An interpolated contour runs inside the
// mesh's polyhedral outline, on faces that turn away from the eye, and its sight line grazes the mesh
// there: it passes through the mesh's own faces for up to about half a face's length before it reaches
// the contour (a chord's sagitta under a tangent), so those faces would hide what the smooth surface
// shows. Long thin faces (a sphere's poles) make that neighbourhood wider than the faces round the face.
// A fold of the surface nearer than that (a tube thinner than its faces are long) does not hide it.
#pragma once

#include <cstdint>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/hlr/frame_setup.hpp"
#include "core/solid/solid.hpp"

namespace hlr {

// Appends to `out` the contour pieces of faces [face_begin, face_end) of `solid` (scene object `object`),
// as candidates: source Contour, `edge` and own face the face they lie on, view points of their world ends.
void add_contour_candidates(std::vector<Candidate>& out, std::uint32_t object, const Solid& solid,
                            const CornerNormals& normals, const Camera& camera, std::size_t face_begin,
                            std::size_t face_end);

// Whether face `other` of `solid` is near face `own` as above, so that it hides no contour piece on `own`.
bool near_contour_face(const Solid& solid, FaceIndex own, FaceIndex other);

}  // namespace hlr
