#include "core/hlr/face_grid.hpp"

#include <algorithm>
#include <cmath>

#include "core/tolerance.hpp"

namespace hlr {

FaceGrid::FaceGrid(const std::vector<Occluder>& occluders, const Rect2& domain) : domain_(domain) {
  if (occluders.empty() || domain.empty()) return;
  // About one cell per occluder, shaped like the domain, at most 2048 a side.
  const double w = std::max(domain.width(), Tolerance::kFloor), h = std::max(domain.height(), Tolerance::kFloor);
  const double cells = std::clamp(static_cast<double>(occluders.size()), 1.0, 2048.0 * 2048.0);
  nx_ = static_cast<int>(std::clamp(std::ceil(std::sqrt(cells * w / h)), 1.0, 2048.0));
  ny_ = static_cast<int>(std::clamp(std::ceil(cells / nx_), 1.0, 2048.0));
  cell_w_ = w / nx_;
  cell_h_ = h / ny_;
  // Degenerate domains (a single point or a line) still get finite cells.
  if (!(cell_w_ > 0) || !std::isfinite(cell_w_)) cell_w_ = 1;
  if (!(cell_h_ > 0) || !std::isfinite(cell_h_)) cell_h_ = 1;

  cell_start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  auto for_cells = [&](const Occluder& o, auto&& fn) {
    if (!o.bounds.overlaps(domain_)) return;
    const int c0 = column(o.bounds.xmin), c1 = column(o.bounds.xmax);
    const int r0 = row(o.bounds.ymin), r1 = row(o.bounds.ymax);
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) fn(static_cast<std::size_t>(r) * nx_ + c);
  };
  for (const Occluder& o : occluders) for_cells(o, [&](std::size_t cell) { ++cell_start_[cell + 1]; });
  for (std::size_t i = 1; i < cell_start_.size(); ++i) cell_start_[i] += cell_start_[i - 1];
  items_.resize(cell_start_.back());
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::uint32_t i = 0; i < occluders.size(); ++i)
    for_cells(occluders[i], [&](std::size_t cell) { items_[fill[cell]++] = i; });
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
