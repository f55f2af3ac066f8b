// The OpenCASCADE peer: the same solid through HLRBRep_PolyAlgo, OCCT's hidden-line removal on
// triangulated B-rep shapes (README.md beside this file says how the two are made comparable).
#pragma once

#include <cstddef>

#include "core/camera/camera.hpp"
#include "core/solid/solid.hpp"

namespace hlr::peers {

struct OcctResult {
  double build_s = 0;  // B-rep from the solid's faces, continuity of smooth edges, BRepMesh
  double hide_s = 0;   // median of: HLRBRep_PolyAlgo Load + Projector + Update, then Hide() on every edge
  double visible_length = 0;  // sharp + outline visible pieces, in the camera's picture units
  double smooth_visible_length = 0;  // visible pieces of smooth (Rg1) edges that are not outlines
  std::size_t visible_pieces = 0;    // visible intervals of all classes
  int runs = 0;                      // hiding runs made
  // With to_shape: one more run through HLRBRep_PolyHLRToShape (Update, VCompound, OutLineVCompound),
  // its time and the length of those compounds (scaled as ours, but without perspective division).
  double to_shape_s = 0, to_shape_length = 0;
};

// Builds the shape once, then runs the hiding `runs` times, fewer once `budget_s` seconds are spent
// (median time; lengths from the last run). Perspective and orthographic cameras are supported; the
// picture frame (Camera::frame) is ignored. tol_angular > 0 replaces HLRBRep_PolyAlgo's angular tolerance
// (default 0.001 rad: faces within it of edge-on are treated as such).
OcctResult run_occt(const Solid& solid, const Camera& camera, int runs, double budget_s, bool to_shape,
                    double tol_angular);

}  // namespace hlr::peers
