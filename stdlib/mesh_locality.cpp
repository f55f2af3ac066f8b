// Spatial order for a large mesh's vertices and faces (mesh_detail.hpp): a scan lists both in no order
// the space would suggest, and every later stage — the builder's edge table, the self-crossing search, the
// frame's set-up and examination — walks faces and fetches their vertices, waiting on memory at each.
#include <algorithm>
#include <cstdint>

#include "core/counting_sort.hpp"
#include "core/geometry/box3.hpp"
#include "core/parallel.hpp"
#include "stdlib/mesh_detail.hpp"

namespace hlr::stdlib::mesh_detail {
namespace {

// Points or faces a part, where a loop over them goes by parts side by side.
constexpr std::size_t kLocalityPart = 16384;

// The bits of v (10 of them) spread to every third place.
std::uint32_t spread_bits(std::uint32_t v) {
  v &= 0x3ffu;
  v = (v | (v << 16)) & 0x030000ffu;
  v = (v | (v << 8)) & 0x0300f00fu;
  v = (v | (v << 4)) & 0x030c30c3u;
  v = (v | (v << 2)) & 0x09249249u;
  return v;
}

}  // namespace

std::vector<std::uint32_t> morton_order(std::span<const Point3> points) {
  const std::size_t n = points.size();
  std::vector<Box3> part_box((n + kLocalityPart - 1) / kLocalityPart);
  parallel_chunks(part_box.size(), threads_for(n, 2 * kLocalityPart, 0), [&](std::size_t k) {
    Box3 part;  // stored once: the parts' boxes share cache lines
    for (std::size_t i = k * kLocalityPart; i < std::min(n, (k + 1) * kLocalityPart); ++i)
      part.include(points[i]);
    part_box[k] = part;
  });
  Box3 box;  // by coordinates: an empty part's box changes nothing
  for (const Box3& b : part_box) {
    box.lo = {std::min(box.lo.x, b.lo.x), std::min(box.lo.y, b.lo.y), std::min(box.lo.z, b.lo.z)};
    box.hi = {std::max(box.hi.x, b.hi.x), std::max(box.hi.y, b.hi.y), std::max(box.hi.z, b.hi.z)};
  }
  std::vector<std::uint64_t> keyed(n);  // the point's code above its index
  const Point3 lo = box.lo;
  const double scale[3] = {box.hi.x > lo.x ? 1023.0 / (box.hi.x - lo.x) : 0.0,
                           box.hi.y > lo.y ? 1023.0 / (box.hi.y - lo.y) : 0.0,
                           box.hi.z > lo.z ? 1023.0 / (box.hi.z - lo.z) : 0.0};
  auto cell = [](double t) {  // NaN (a non-finite vertex, refused later) to 0
    return t >= 0 ? static_cast<std::uint32_t>(std::min(t, 1023.0)) : 0u;
  };
  parallel_indices(n, kLocalityPart, [&](std::size_t i) {
    const Point3 p = points[i];
    const std::uint64_t code = spread_bits(cell((p.x - lo.x) * scale[0])) |
                               spread_bits(cell((p.y - lo.y) * scale[1])) << 1 |
                               spread_bits(cell((p.z - lo.z) * scale[2])) << 2;
    keyed[i] = code << 32 | i;
  });
  sort_by_30_bits(keyed, 32);
  std::vector<std::uint32_t> order(n);
  parallel_indices(n, kLocalityPart, [&](std::size_t i) { order[i] = static_cast<std::uint32_t>(keyed[i]); });
  return order;
}

std::vector<std::uint32_t> faces_by_least_vertex(std::span<const std::uint32_t> vertices,
                                                 std::span<const std::size_t> ends,
                                                 std::size_t vertex_count) {
  const std::size_t n = ends.size();
  std::vector<std::uint32_t> least(n);
  parallel_indices(n, kLocalityPart, [&](std::size_t f) {
    const std::size_t begin = f == 0 ? 0 : ends[f - 1];
    least[f] = *std::min_element(vertices.begin() + static_cast<std::ptrdiff_t>(begin),
                                 vertices.begin() + static_cast<std::ptrdiff_t>(ends[f]));
  });
  // A counting sort by that vertex (stable: faces at one vertex keep the file's order).
  std::vector<std::uint32_t> first(vertex_count + 1, 0), order(n);
  for (std::uint32_t v : least) ++first[v + 1];
  for (std::size_t v = 0; v < vertex_count; ++v) first[v + 1] += first[v];
  for (std::size_t f = 0; f < n; ++f) order[first[least[f]]++] = static_cast<std::uint32_t>(f);
  return order;
}

void order_faces_by_least_vertex(std::span<const std::uint32_t> vertices, std::span<const std::size_t> ends,
                                 std::size_t vertex_count, std::vector<std::uint32_t>& ordered,
                                 std::vector<std::size_t>& ordered_ends) {
  const std::vector<std::uint32_t> order = faces_by_least_vertex(vertices, ends, vertex_count);
  const std::size_t n = order.size();
  ordered_ends.resize(n);
  for (std::size_t k = 0, end = 0; k < n; ++k) {
    const std::size_t f = order[k];
    end += ends[f] - (f == 0 ? 0 : ends[f - 1]);
    ordered_ends[k] = end;
  }
  ordered.resize(vertices.size());
  parallel_indices(n, kLocalityPart, [&](std::size_t i) {
    const std::size_t f = order[i], begin = f == 0 ? 0 : ends[f - 1];
    std::copy(vertices.begin() + static_cast<std::ptrdiff_t>(begin),
              vertices.begin() + static_cast<std::ptrdiff_t>(ends[f]),
              ordered.begin() + static_cast<std::ptrdiff_t>(i == 0 ? 0 : ordered_ends[i - 1]));
  });
}

}  // namespace hlr::stdlib::mesh_detail
