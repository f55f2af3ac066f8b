// The OpenCASCADE peer: the same solid through HLRBRep_PolyAlgo, OCCT's hidden-line removal on
// triangulated B-rep shapes (README.md beside this file says how the two are made comparable).
#pragma once

#include <cstddef>

#include "core/camera/camera.hpp"
#include "core/solid/solid.hpp"

namespace hlr::peers {

struct OcctResult {
  double build_s = 0;         // B-rep from the solid's faces, continuity of smooth edges, BRepMesh
  double hide_s = 0;          // median of HLRBRep_PolyAlgo Load + Projector + Update (the hiding)
  double extract_s = 0;       // HLRBRep_PolyHLRToShape Update + the visible compounds asked for
  double visible_length = 0;  // sharp + outline visible edges, in the camera's picture units
  double smooth_visible_length = 0;  // Rg1LineVCompound: smooth edges, visible, anywhere (not compared)
  std::size_t visible_edges = 0;     // edges in the compared compounds
};

// Builds the shape once, then runs the hiding `runs` times (median time; lengths from the last run).
// Perspective and orthographic cameras are supported; the picture frame (Camera::frame) is ignored.
OcctResult run_occt(const Solid& solid, const Camera& camera, int runs);

}  // namespace hlr::peers
