#include "core/hlr/ring_edge_grid.hpp"

#include "core/tolerance.hpp"

namespace hlr {

RingEdgeGrid::RingEdgeGrid(std::span<const Point2> points, std::span<const std::uint32_t> ring_ends)
    : points_(points) {
  const std::size_t n = points.size();
  next_.resize(n);
  std::uint32_t begin = 0;
  for (std::uint32_t end : ring_ends) {
    for (std::uint32_t i = begin; i < end; ++i) next_[i] = i + 1 < end ? i + 1 : begin;
    begin = end;
  }
  for (Point2 p : points) box_.include(p);
  // About two cells per edge along each axis of a square grid: a ring crossing the grid meets a few
  // edges per cell.
  const int side = std::clamp(static_cast<int>(std::ceil(2 * std::sqrt(static_cast<double>(n)))), 1, 2048);
  columns_ = rows_ = side;
  const double extent = std::max({box_.width(), box_.height(), Tolerance::kFloor});
  cell_w_ = std::max(box_.width(), extent / side) / side;
  cell_h_ = std::max(box_.height(), extent / side) / side;
  slack_ = Tolerance::kRelative * extent;

  // Offset lists by counting: first the sizes, then the entries.
  auto fill = [&](std::vector<std::uint32_t>& start, std::vector<std::uint32_t>& entries, std::size_t slots,
                  auto&& for_each_slot) {
    start.assign(slots + 1, 0);
    for (std::uint32_t i = 0; i < n; ++i) for_each_slot(i, [&](std::size_t s) { ++start[s + 1]; });
    for (std::size_t s = 1; s <= slots; ++s) start[s] += start[s - 1];
    entries.resize(start[slots]);
    std::vector<std::uint32_t> at(start.begin(), start.end() - 1);
    for (std::uint32_t i = 0; i < n; ++i) for_each_slot(i, [&](std::size_t s) { entries[at[s]++] = i; });
  };
  auto bands = [&](std::uint32_t i, auto&& add) {
    const Point2 a = points_[i], b = points_[next_[i]];
    for (int r = band_of(std::min(a.y, b.y)); r <= band_of(std::max(a.y, b.y)); ++r)
      add(static_cast<std::size_t>(r));
  };
  auto cells = [&](std::uint32_t i, auto&& add) {
    for_each_cell(points_[i], points_[next_[i]], slack_, add);
  };
  fill(band_start_, band_edges_, static_cast<std::size_t>(rows_), bands);
  fill(cell_start_, cell_edges_, static_cast<std::size_t>(rows_) * columns_, cells);
}

}  // namespace hlr
