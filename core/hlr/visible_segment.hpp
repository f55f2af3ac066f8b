// The engine's output: pieces of edges, each wholly visible (or, on request, wholly hidden).
#pragma once

#include <cstdint>
#include <vector>

#include "core/geometry/vector.hpp"

namespace hlr {

enum class SegmentSource : std::uint8_t {
  Edge,          // a piece of SolidEdge `edge` of object `object`
  Intersection,  // a piece of the line where two solids' faces cross (objects `object` and `other`)
  Contour,       // a piece of the smooth contour on face `edge` of object `object` (Solid::smooth_contours)
};

struct VisibleSegment {
  Point3 p0, p1;  // world-space end points
  Point2 s0, s1;  // picture coordinates of the camera
  std::uint32_t object = 0;
  std::uint32_t edge = 0;   // index into the object's Solid::edges (Edge source)
  std::uint32_t other = 0;  // second object (Intersection source)
  SegmentSource source = SegmentSource::Edge;
  bool hidden = false;
  // Hidden pieces: how many surfaces lie between the eye and the piece when the frame counted them
  // (HlrOptions::max_level > 0; every face counts, back faces too), else 1. Visible pieces: 0.
  std::uint16_t level = 0;
  bool hatch = false;  // a piece of a hatch line (EdgeKind::Hatch, Edge source), drawn in the hatch pen
};

struct FrameStats {
  std::size_t candidate_edges = 0;     // edges examined after culling and clipping
  std::size_t occluder_faces = 0;      // faces that can hide something
  std::size_t face_tests = 0;          // edge-face pairs examined after the spatial index
  std::size_t intersection_lines = 0;  // pieces of intersection lines (between solids and within one)
  std::size_t visible_segments = 0;
  // Wall time of the stages, in ms (for --stats; nothing depends on them). The self-crossing search is
  // what the frame waited for it: it runs once per solid, mostly beside the edges' examination.
  struct Stages {
    double self_crossings = 0;  // the search run first (one thread, large scenes) and the wait at the end
    double setup = 0;           // projection, culling, candidates and occluders
    double grid = 0;            // the picture grid of occluders
    double examine = 0;         // every candidate against the occluders near it
    double finish = 0;          // the intersection lines' examination, the join, coincident pieces
  } ms;
};

struct FrameResult {
  std::vector<VisibleSegment> segments;
  FrameStats stats;
};

}  // namespace hlr
