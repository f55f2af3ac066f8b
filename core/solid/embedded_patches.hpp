// Patches of a solid's triangles that cannot pass through each other: each projects one to one onto a
// coordinate plane, so two of its faces meet only along the edges and at the vertices they share. The
// search for where a solid crosses itself (self_crossings.cpp) then tests no pair of faces of one patch —
// on a smooth scan nearly every pair its grid meets.
//
// The certificate, for a set P of triangles and an axis: (1) every triangle of P projects along the axis
// with the same strict orientation (exact orient2d on the two other coordinates, which projection does not
// round); (2) every edge two triangles of P share is run in opposite directions by them; (3) the edges of P
// shared with no other triangle of P form closed loops whose projections are simple and disjoint (exact
// segment tests), exactly one of them turning as the triangles do (the outline) and every other the other
// way (holes). The projected triangles then cover each point of the plane (off their outlines) as many
// times as the loops wind round it, summed — the chain's boundary is the loops, and every triangle counts
// +1 — which such loops do at most once: no two triangles' projections overlap, so no two triangles share
// a point off their outlines, and none cross. Faces that fail stay outside every patch and are searched as
// before; the certificate is never needed to find a crossing, only to skip a pair that has none.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/solid/solid.hpp"

namespace hlr {

inline constexpr std::uint32_t kNoPatch = 0xffffffffu;

// Per face: the patch it lies in (the index of one of its faces), or kNoPatch. Patches are grown over
// neighbouring triangles facing the same way along one axis, in runs of the solid's face order (spatial
// for imported meshes), and kept where the certificate above holds. Needs the rings' edges linked.
std::vector<std::uint32_t> embedded_patches(const Solid& solid);

// The certificate for the triangles `faces` of `solid` projected along `axis` (0 x, 1 y, 2 z): whether
// (1)–(3) above hold. Exposed for tests.
bool projects_one_to_one(const Solid& solid, std::span<const FaceIndex> faces, int axis);

}  // namespace hlr
