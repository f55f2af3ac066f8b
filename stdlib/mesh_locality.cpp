// Spatial order for a large mesh's vertices and faces (mesh_detail.hpp): a scan lists both in no order
// the space would suggest, and every later stage — the builder's edge table, the self-crossing search, the
// frame's set-up and examination — walks faces and fetches their vertices, waiting on memory at each.
#include <algorithm>
#include <cstdint>
#include <utility>

#include "core/geometry/box3.hpp"
#include "stdlib/mesh_detail.hpp"

namespace hlr::stdlib::mesh_detail {
namespace {

// The bits of v (10 of them) spread to every third place.
std::uint32_t spread_bits(std::uint32_t v) {
  v &= 0x3ffu;
  v = (v | (v << 16)) & 0x030000ffu;
  v = (v | (v << 8)) & 0x0300f00fu;
  v = (v | (v << 4)) & 0x030c30c3u;
  v = (v | (v << 2)) & 0x09249249u;
  return v;
}

// Indices 0..keys.size()-1 stably sorted by their 30-bit keys: two counting passes of 15 bits.
std::vector<std::uint32_t> sorted_by_key(const std::vector<std::uint32_t>& keys) {
  const auto n = static_cast<std::uint32_t>(keys.size());
  std::vector<std::uint32_t> order(n), buffer(n);
  for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
  std::vector<std::uint32_t> counts(1u << 15);
  for (const int shift : {0, 15}) {
    std::fill(counts.begin(), counts.end(), 0u);
    for (std::uint32_t i : order) ++counts[(keys[i] >> shift) & 0x7fffu];
    std::uint32_t sum = 0;
    for (std::uint32_t& c : counts) sum += std::exchange(c, sum);
    for (std::uint32_t i : order) buffer[counts[(keys[i] >> shift) & 0x7fffu]++] = i;
    order.swap(buffer);
  }
  return order;
}

}  // namespace

std::vector<std::uint32_t> morton_order(std::span<const Point3> points) {
  Box3 box;
  for (Point3 p : points) box.include(p);
  std::vector<std::uint32_t> keys(points.size());
  const Point3 lo = box.lo;
  const double scale[3] = {box.hi.x > lo.x ? 1023.0 / (box.hi.x - lo.x) : 0.0,
                           box.hi.y > lo.y ? 1023.0 / (box.hi.y - lo.y) : 0.0,
                           box.hi.z > lo.z ? 1023.0 / (box.hi.z - lo.z) : 0.0};
  auto cell = [](double t) {  // NaN (a non-finite vertex, refused later) to 0
    return t >= 0 ? static_cast<std::uint32_t>(std::min(t, 1023.0)) : 0u;
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point3 p = points[i];
    keys[i] = spread_bits(cell((p.x - lo.x) * scale[0])) | spread_bits(cell((p.y - lo.y) * scale[1])) << 1 |
              spread_bits(cell((p.z - lo.z) * scale[2])) << 2;
  }
  return sorted_by_key(keys);
}

std::vector<std::uint32_t> faces_by_least_vertex(std::span<const std::uint32_t> vertices,
                                                 std::span<const std::size_t> ends,
                                                 std::size_t vertex_count) {
  const std::size_t n = ends.size();
  std::vector<std::uint32_t> least(n);
  for (std::size_t f = 0; f < n; ++f) {
    const std::size_t begin = f == 0 ? 0 : ends[f - 1];
    least[f] = *std::min_element(vertices.begin() + static_cast<std::ptrdiff_t>(begin),
                                 vertices.begin() + static_cast<std::ptrdiff_t>(ends[f]));
  }
  // A counting sort by that vertex (stable: faces at one vertex keep the file's order).
  std::vector<std::uint32_t> first(vertex_count + 1, 0), order(n);
  for (std::uint32_t v : least) ++first[v + 1];
  for (std::size_t v = 0; v < vertex_count; ++v) first[v + 1] += first[v];
  for (std::size_t f = 0; f < n; ++f) order[first[least[f]]++] = static_cast<std::uint32_t>(f);
  return order;
}

}  // namespace hlr::stdlib::mesh_detail
