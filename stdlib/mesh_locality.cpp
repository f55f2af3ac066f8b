// Spatial order for a large mesh's vertices and faces (mesh_detail.hpp): a scan lists both in no order
// the space would suggest, and every later stage — the builder's edge table, the self-crossing search, the
// frame's set-up and examination — walks faces and fetches their vertices, waiting on memory at each.
#include <algorithm>
#include <cstdint>

#include "core/counting_sort.hpp"
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

}  // namespace

std::vector<std::uint32_t> morton_order(std::span<const Point3> points) {
  Box3 box;
  for (Point3 p : points) box.include(p);
  std::vector<std::uint64_t> keyed(points.size());  // the point's code above its index
  const Point3 lo = box.lo;
  const double scale[3] = {box.hi.x > lo.x ? 1023.0 / (box.hi.x - lo.x) : 0.0,
                           box.hi.y > lo.y ? 1023.0 / (box.hi.y - lo.y) : 0.0,
                           box.hi.z > lo.z ? 1023.0 / (box.hi.z - lo.z) : 0.0};
  auto cell = [](double t) {  // NaN (a non-finite vertex, refused later) to 0
    return t >= 0 ? static_cast<std::uint32_t>(std::min(t, 1023.0)) : 0u;
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point3 p = points[i];
    const std::uint64_t code = spread_bits(cell((p.x - lo.x) * scale[0])) |
                               spread_bits(cell((p.y - lo.y) * scale[1])) << 1 |
                               spread_bits(cell((p.z - lo.z) * scale[2])) << 2;
    keyed[i] = code << 32 | i;
  }
  sort_by_30_bits(keyed, 32);
  std::vector<std::uint32_t> order(keyed.size());
  for (std::size_t i = 0; i < keyed.size(); ++i) order[i] = static_cast<std::uint32_t>(keyed[i]);
  return order;
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
