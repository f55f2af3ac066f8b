#include "core/hlr/face_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/counting_sort.hpp"
#include "core/geometry/float_bounds.hpp"
#include "core/parallel.hpp"
#include "core/tolerance.hpp"

namespace hlr {
namespace {

// A depth as a 30-bit key in the floats' order, never above the depth (a NaN as −∞: never passed over),
// and the float a key stands for.
std::uint32_t depth_key(double depth) {
  const float f = std::isnan(depth) ? -std::numeric_limits<float>::infinity() : float_below(depth);
  const auto bits = std::bit_cast<std::uint32_t>(f);
  const std::uint32_t ordered = (bits & 0x80000000u) != 0 ? ~bits : bits | 0x80000000u;
  return ordered >> 2;  // dropping the low bits rounds towards −∞
}

float depth_of_key(std::uint32_t key) {
  const std::uint32_t ordered = key << 2;
  return std::bit_cast<float>((ordered & 0x80000000u) != 0 ? ordered & 0x7fffffffu : ~ordered);
}

}  // namespace

FaceGrid::FaceGrid(const FrameSetup& setup, const Rect2& domain, unsigned threads) : domain_(domain) {
  const std::vector<Occluder>& occluders = setup.occluders;
  if (occluders.empty() || domain.empty()) return;
  // About one cell per occluder, at most 2048 a side, shaped like a typical occluder (the median width
  // over the median height, within 1:64 either way): the tall thin sides of a many-sided prism then lie
  // in a few tall thin cells each, instead of down a column of square cells shared with hundreds of others.
  const double w = std::max(domain.width(), Tolerance::kFloor),
               h = std::max(domain.height(), Tolerance::kFloor);
  const double cells = std::clamp(static_cast<double>(occluders.size()), 1.0, 2048.0 * 2048.0);
  std::vector<double> widths, heights;
  widths.reserve(occluders.size());
  heights.reserve(occluders.size());
  for (const Occluder& o : occluders) {
    if (!o.bounds.overlaps(domain_)) continue;
    widths.push_back(o.bounds.width());
    heights.push_back(o.bounds.height());
  }
  double aspect = 1;  // cell width over height
  if (!widths.empty()) {
    const auto middle = static_cast<std::ptrdiff_t>(widths.size() / 2);
    std::nth_element(widths.begin(), widths.begin() + middle, widths.end());
    std::nth_element(heights.begin(), heights.begin() + middle, heights.end());
    const double mw = widths[static_cast<std::size_t>(middle)],
                 mh = heights[static_cast<std::size_t>(middle)];
    if (mw > 0 && mh > 0) aspect = std::clamp(mw / mh, 1.0 / 64, 64.0);
  }
  nx_ = static_cast<int>(std::clamp(std::ceil(std::sqrt(cells * w / (h * aspect))), 1.0, 2048.0));
  ny_ = static_cast<int>(std::clamp(std::ceil(cells / nx_), 1.0, 2048.0));
  cell_w_ = w / nx_;
  cell_h_ = h / ny_;
  // Degenerate domains (a single point or a line) still get finite cells.
  if (!(cell_w_ > 0) || !std::isfinite(cell_w_)) cell_w_ = 1;
  if (!(cell_h_ > 0) || !std::isfinite(cell_h_)) cell_h_ = 1;

  cell_start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  // An occluder's cells: in each row its bounds span, the columns of its outline's x range within the
  // row (the outline's extremes in a band of rows lie on its edges there), widened by its tolerance. A
  // slanted sliver then lies in a thin diagonal run of cells, not in every cell of its box.
  constexpr std::uint32_t kTracedPoints = 32;  // larger outlines are entered by their bounds
  auto for_cells = [&](const Occluder& o, auto&& fn) {
    if (!o.bounds.overlaps(domain_)) return;
    const int c0 = column(o.bounds.xmin), c1 = column(o.bounds.xmax);
    const int r0 = row(o.bounds.ymin), r1 = row(o.bounds.ymax);
    const std::uint32_t end = setup.ring_ends[o.first_ring];
    const bool traced = r0 != r1 && c0 != c1 && end - o.first_point <= kTracedPoints;
    for (int r = r0; r <= r1; ++r) {
      int from = c0, to = c1;
      if (traced) {
        const double slack = o.picture_tolerance + Tolerance::kRelative * (cell_w_ + cell_h_);
        const double y0 = domain_.ymin + r * cell_h_ - slack, y1 = domain_.ymin + (r + 1) * cell_h_ + slack;
        double xlo = o.bounds.xmax, xhi = o.bounds.xmin;
        for (std::uint32_t i = o.first_point; i < end; ++i) {
          const Point2 p = setup.polygon_points[i],
                       q = setup.polygon_points[i + 1 < end ? i + 1 : o.first_point];
          const double ylo = std::max(std::min(p.y, q.y), y0), yhi = std::min(std::max(p.y, q.y), y1);
          if (ylo > yhi) continue;
          double xa = p.x, xb = q.x;
          if (q.y != p.y) {
            xa = p.x + (ylo - p.y) / (q.y - p.y) * (q.x - p.x);
            xb = p.x + (yhi - p.y) / (q.y - p.y) * (q.x - p.x);
          }
          xlo = std::min({xlo, xa, xb});
          xhi = std::max({xhi, xa, xb});
        }
        if (xlo > xhi) continue;  // the outline misses this row (rounding at its ends)
        from = std::max(c0, column(xlo - slack));
        to = std::min(c1, column(xhi + slack));
      }
      for (int c = from; c <= to; ++c) fn(static_cast<std::size_t>(r) * nx_ + c);
    }
  };
  // The occluders ranked nearest first, by their depth rounded down to 30 bits of a float (ties in the
  // occluders' order); a cell lists its occluders in that order, and each item carries the depth it was
  // ranked by, so that a walk may stop at the first lying behind an edge.
  std::vector<std::uint64_t> ranked(occluders.size());
  for (std::size_t i = 0; i < occluders.size(); ++i)
    ranked[i] = std::uint64_t{depth_key(occluders[i].min_depth)} << 32 | i;
  sort_by_30_bits(ranked, 32);
  // Each occluder's cells are found once, by chunks of occluders in parallel, listed in occluder order
  // with where each occluder's begin; the cells' lists are then filled occluder by occluder in rank
  // order, so each lists its occluders in that order whatever the number of threads.
  constexpr std::size_t kChunk = 4096;
  const std::size_t chunks = (occluders.size() + kChunk - 1) / kChunk;
  std::vector<std::vector<std::uint32_t>> cells_of(chunks);
  std::vector<std::uint32_t> first_cell(occluders.size());  // in its chunk's list
  parallel_chunks(chunks, threads_for(occluders.size(), 2 * kChunk, threads), [&](std::size_t k) {
    std::vector<std::uint32_t> cells;  // moved in once: the chunks' lists share cache lines
    for (std::size_t i = k * kChunk; i < std::min(occluders.size(), (k + 1) * kChunk); ++i) {
      first_cell[i] = static_cast<std::uint32_t>(cells.size());
      for_cells(occluders[i], [&](std::size_t cell) { cells.push_back(static_cast<std::uint32_t>(cell)); });
    }
    cells_of[k] = std::move(cells);
  });
  for (const std::vector<std::uint32_t>& chunk : cells_of)
    for (const std::uint32_t cell : chunk) ++cell_start_[cell + 1];
  for (std::size_t i = 1; i < cell_start_.size(); ++i) cell_start_[i] += cell_start_[i - 1];
  items_.resize(cell_start_.back());
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (const std::uint64_t key : ranked) {
    const auto i = static_cast<std::uint32_t>(key);
    const std::vector<std::uint32_t>& chunk = cells_of[i / kChunk];
    const std::size_t end =
        i + 1 < occluders.size() && (i + 1) % kChunk != 0 ? first_cell[i + 1] : chunk.size();
    const float depth = depth_of_key(static_cast<std::uint32_t>(key >> 32));
    for (std::size_t e = first_cell[i]; e < end; ++e) items_[fill[chunk[e]]++] = {depth, i};
  }
}

int FaceGrid::column(double x) const {
  const double c = std::floor((x - domain_.xmin) / cell_w_);
  return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(nx_ - 1)));
}

int FaceGrid::row(double y) const {
  const double r = std::floor((y - domain_.ymin) / cell_h_);
  return static_cast<int>(std::clamp(r, 0.0, static_cast<double>(ny_ - 1)));
}

}  // namespace hlr
