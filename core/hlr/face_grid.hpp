// Screen-space uniform grid over the occluders' picture bounds, so each edge meets only the faces whose
// bounds overlap the cells it crosses: the cost follows what actually overlaps.
#pragma once

#include <cstdint>
#include <vector>

#include "core/geometry/rect2.hpp"
#include "core/hlr/frame_setup.hpp"

namespace hlr {

class FaceGrid {
 public:
  // Indexes the frame's occluders over `domain` (the region where anything is drawn): each in the cells
  // its outline covers, row by row (by its bounds when the outline has many points). `threads` as for
  // parallel_chunks(); the grid is the same for any value.
  FaceGrid(const FrameSetup& setup, const Rect2& domain, unsigned threads = 1);

  // Calls visit(occluder index) once for every occluder listed in a cell the segment a→b crosses whose
  // nearest view depth is less than `max_depth` (one wholly at or beyond it hides nothing there), and
  // perhaps for some up to a float's rounding beyond it: the caller tells those exactly. `stamp` must have
  // one entry per occluder and `mark` must be unique per call (duplicate filter).
  template <typename Visit>
  void for_each_near(Point2 a, Point2 b, double max_depth, std::vector<std::uint32_t>& stamp,
                     std::uint32_t mark, Visit&& visit) const;

  bool empty() const { return nx_ == 0; }
  // The cells, numbered row by row: how many, and the one holding p (clamped to the grid).
  std::size_t cell_count() const { return static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_); }
  std::size_t cell_of(Point2 p) const {
    return static_cast<std::size_t>(row(p.y)) * static_cast<std::size_t>(nx_) +
           static_cast<std::size_t>(column(p.x));
  }

 private:
  int column(double x) const;
  int row(double y) const;
  Rect2 domain_;
  int nx_ = 0, ny_ = 0;
  double cell_w_ = 1, cell_h_ = 1;
  // An occluder listed in a cell, with its nearest depth rounded down to a float: a cell's items are
  // sorted by it, so a walk stops at the first that lies wholly behind the edge (a third of the bunny's
  // entries met), without fetching it.
  struct Item {
    float depth;
    std::uint32_t occluder;
  };
  std::vector<std::uint32_t> cell_start_;  // CSR: cell_start_[c]..cell_start_[c+1] in items_
  std::vector<Item> items_;
};

template <typename Visit>
void FaceGrid::for_each_near(Point2 a, Point2 b, double max_depth, std::vector<std::uint32_t>& stamp,
                             std::uint32_t mark, Visit&& visit) const {
  if (nx_ == 0) return;
  // Walk the rows the segment spans; in each row only the columns its x-range covers there.
  const int r0 = row(std::min(a.y, b.y)), r1 = row(std::max(a.y, b.y));
  const double dy = b.y - a.y;
  for (int r = r0; r <= r1; ++r) {
    double xa = a.x, xb = b.x;
    if (r0 != r1 && dy != 0) {
      const double y_lo = domain_.ymin + r * cell_h_, y_hi = y_lo + cell_h_;
      double t0 = (y_lo - a.y) / dy, t1 = (y_hi - a.y) / dy;
      if (t0 > t1) std::swap(t0, t1);
      t0 = std::max(t0, 0.0);
      t1 = std::min(t1, 1.0);
      xa = a.x + t0 * (b.x - a.x);
      xb = a.x + t1 * (b.x - a.x);
    }
    const int c0 = column(std::min(xa, xb)), c1 = column(std::max(xa, xb));
    for (int c = c0; c <= c1; ++c) {
      const std::size_t cell = static_cast<std::size_t>(r) * nx_ + c;
      for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
        if (items_[k].depth >= max_depth) break;  // then so does the occluder's own depth
        const std::uint32_t id = items_[k].occluder;
        if (stamp[id] == mark) continue;
        stamp[id] = mark;
        visit(id);
      }
    }
  }
}

}  // namespace hlr
