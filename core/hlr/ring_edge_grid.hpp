// A grid over the projected rings of one large occluder (a cap of many sides, a floor with many holes),
// so that testing an edge against it reads the ring edges near the edge's path and near a point's row,
// not all of them: the test's cost follows what is near, not the size of the face. Built per frame for
// occluders of many points (FrameSetup); the answers are the same as a scan of every ring edge.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "core/geometry/polygon2d.hpp"
#include "core/geometry/rect2.hpp"
#include "core/geometry/vector.hpp"

namespace hlr {

class RingEdgeGrid {
 public:
  // Occluders with fewer points are scanned whole: the grid would cost more than it saves.
  static constexpr std::uint32_t kMinPoints = 128;

  RingEdgeGrid() = default;
  // Ring edge i runs from points[i] to the next point of its ring (ring_ends: end of each ring in points).
  RingEdgeGrid(std::span<const Point2> points, std::span<const std::uint32_t> ring_ends);

  // Calls visit(i) for every ring edge i that may come within `tolerance` of the segment p→q (some more
  // than once).
  template <typename Visit>
  void for_each_edge_near(Point2 p, Point2 q, double tolerance, Visit&& visit) const {
    for_each_cell(p, q, tolerance, [&](std::size_t cell) {
      for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) visit(cell_edges_[k]);
    });
  }

  std::uint32_t next(std::uint32_t i) const { return next_[i]; }  // the end point of ring edge i

  // classify_point(points, ring_ends, p, tolerance, is_seam), reading only the edges of p's band.
  template <typename IsSeam>
  PointClass classify(Point2 p, double tolerance, IsSeam&& is_seam) const {
    const double tol2 = tolerance * tolerance;
    bool on_seam = false;
    // Boundary: the edges within the tolerance of p lie in the bands around it.
    for (int band = band_of(p.y - tolerance); band <= band_of(p.y + tolerance); ++band)
      for (std::uint32_t k = band_start_[band]; k < band_start_[band + 1]; ++k) {
        const std::uint32_t i = band_edges_[k];
        const Point2 a = points_[i], b = points_[next_[i]];
        const Vector2 ab = b - a, ap = p - a;
        const double c = cross(ab, ap);
        if (c * c <= tol2 * dot(ab, ab) && distance2_to_segment(p, a, b) <= tol2) {
          if (!is_seam(i) || dot(ap, ap) <= tol2 || dot(p - b, p - b) <= tol2) return PointClass::Boundary;
          on_seam = true;
        }
      }
    // Parity of the crossings to the right: every edge crossing p's row is listed once in p's band.
    bool inside = false;
    const int band = band_of(p.y);
    for (std::uint32_t k = band_start_[band]; k < band_start_[band + 1]; ++k) {
      const std::uint32_t i = band_edges_[k];
      const Point2 a = points_[i], b = points_[next_[i]];
      if ((a.y > p.y) != (b.y > p.y)) {
        const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
        if (x > p.x) inside = !inside;
      }
    }
    return on_seam ? PointClass::Seam : (inside ? PointClass::Inside : PointClass::Outside);
  }

 private:
  // The cells the segment p→q passes within `tolerance` of: row by row, the columns of the segment's x
  // range over the row (both widened by the tolerance).
  template <typename Visit>
  void for_each_cell(Point2 p, Point2 q, double tolerance, Visit&& visit) const {
    const double ylo = std::min(p.y, q.y) - tolerance, yhi = std::max(p.y, q.y) + tolerance;
    const double dy = q.y - p.y;
    for (int row = band_of(ylo); row <= band_of(yhi); ++row) {
      const double y0 = std::max(ylo, box_.ymin + row * cell_h_),
                   y1 = std::min(yhi, box_.ymin + (row + 1) * cell_h_);
      double x0 = std::min(p.x, q.x), x1 = std::max(p.x, q.x);
      if (std::abs(dy) > 0) {
        const double ta = std::clamp((y0 - p.y) / dy, 0.0, 1.0), tb = std::clamp((y1 - p.y) / dy, 0.0, 1.0);
        const double xa = p.x + ta * (q.x - p.x), xb = p.x + tb * (q.x - p.x);
        x0 = std::min(xa, xb);
        x1 = std::max(xa, xb);
      }
      for (int c = column_of(x0 - tolerance); c <= column_of(x1 + tolerance); ++c)
        visit(static_cast<std::size_t>(row) * columns_ + static_cast<std::size_t>(c));
    }
  }

  int band_of(double y) const {
    const double k = std::floor((y - box_.ymin) / cell_h_);
    return static_cast<int>(std::clamp(k, 0.0, static_cast<double>(rows_ - 1)));
  }
  int column_of(double x) const {
    const double k = std::floor((x - box_.xmin) / cell_w_);
    return static_cast<int>(std::clamp(k, 0.0, static_cast<double>(columns_ - 1)));
  }

  std::span<const Point2> points_;
  std::vector<std::uint32_t> next_;  // per edge: its end point
  Rect2 box_ = Rect2::none();
  int columns_ = 1, rows_ = 1;
  double cell_w_ = 1, cell_h_ = 1;
  double slack_ = 0;  // listing margin: rounding in for_each_cell never leaves out a cell an edge touches
  // Edges by the cells they pass through and by band (row of cells), as offset lists.
  std::vector<std::uint32_t> cell_start_, cell_edges_, band_start_, band_edges_;
};

}  // namespace hlr
