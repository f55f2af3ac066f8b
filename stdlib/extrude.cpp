// Solids over a planar polygon given in 3-D: pyramid() (a cone over the polygon to an apex) and extrude()
// (the polygon, with holes, swept along a vector). Both keep the input points exactly as vertices; the
// polygon is only projected into its own plane to check that it is simple.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/tolerance.hpp"
#include "stdlib/generator_detail.hpp"
#include "stdlib/generators.hpp"
#include "stdlib/shapes.hpp"

namespace hlr::stdlib {

using detail::require;

namespace {

std::vector<Point3> without_closing_point(std::vector<Point3> ring) {
  if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
  return ring;
}

// Newell's normal: twice the area times the unit normal, by the right-hand rule.
Vector3 newell(const std::vector<Point3>& ring) {
  Vector3 n{};
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point3 p = ring[i], q = ring[(i + 1) % ring.size()];
    n += Vector3{(p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y)};
  }
  return n;
}

// The plane of an outline (with its holes): origin at the outline's centroid, unit normal n along the
// outline's Newell normal, and u × v = n spanning the plane.
struct PlaneFrame {
  Point3 origin;
  Vector3 u, v, n;
  double size = 0;  // bounding-box diagonal of all the points
  Point2 to_2d(Point3 p) const { return {dot(p - origin, u), dot(p - origin, v)}; }
};

// Fits the outline's plane and checks what a face needs: enough finite points, non-zero area, every point
// (holes too) on the plane within the builder's planarity tolerance, and simple, disjoint rings with
// every hole inside the outline. Messages name the rings as the script does ("outline", "hole 0").
PlaneFrame planar_polygon(const char* function, const std::vector<Point3>& outline,
                          const std::vector<std::vector<Point3>>& holes) {
  require(outline.size() >= 3, function, "outline needs at least 3 points");
  for (std::size_t k = 0; k < holes.size(); ++k)
    require(holes[k].size() >= 3, function, "hole " + std::to_string(k) + " needs at least 3 points");
  Point3 lo = outline[0], hi = outline[0];
  Vector3 sum{};
  auto visit = [&](const std::vector<Point3>& ring, const std::string& name) {
    for (const Point3& p : ring) {
      require(is_finite(p), function, name + " points must be finite");
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  };
  visit(outline, "outline");
  for (std::size_t k = 0; k < holes.size(); ++k) visit(holes[k], "hole " + std::to_string(k));
  for (const Point3& p : outline) sum += to_vector(p);

  PlaneFrame f;
  f.size = distance(lo, hi);
  const Vector3 normal = newell(outline);
  // Twice the area against the size squared, as the builder judges zero area.
  require(length(normal) > Tolerance::kRelative * f.size * f.size, function,
          "outline has zero area (its points are collinear, or it crosses itself)");
  f.n = normalize(normal);
  f.origin = to_point(sum / static_cast<double>(outline.size()));
  const double ax = std::abs(f.n.x), ay = std::abs(f.n.y), az = std::abs(f.n.z);
  const Vector3 axis =
      (ax <= ay && ax <= az) ? Vector3{1, 0, 0} : (ay <= az ? Vector3{0, 1, 0} : Vector3{0, 0, 1});
  f.u = normalize(cross(axis, f.n));
  f.v = cross(f.n, f.u);

  const double allowed = Tolerance::kPlanarity * f.size;
  for (const Point3& p : outline)
    require(std::abs(dot(p - f.origin, f.n)) <= allowed, function, "outline is not planar");
  for (std::size_t k = 0; k < holes.size(); ++k)
    for (const Point3& p : holes[k])
      require(std::abs(dot(p - f.origin, f.n)) <= allowed, function,
              "hole " + std::to_string(k) + " is not in the outline's plane");

  std::vector<std::vector<Point2>> flat(1 + holes.size());
  std::vector<std::string> names = {"outline"};
  for (const Point3& p : outline) flat[0].push_back(f.to_2d(p));
  for (std::size_t k = 0; k < holes.size(); ++k) {
    for (const Point3& p : holes[k]) flat[k + 1].push_back(f.to_2d(p));
    names.push_back("hole " + std::to_string(k));
  }
  // Judged at the scale of the 3-D coordinates, where the builder tells vertices apart.
  const double extent = std::max(
      {std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x), std::abs(hi.y), std::abs(hi.z)});
  if (const auto defect = find_ring_defect(flat, true, extent))
    require(false, function, describe_ring_defect(*defect, names, flat));
  // The rings are disjoint, so one point per hole decides containment.
  auto inside = [](Point2 p, const std::vector<Point2>& ring) {
    bool in = false;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
      if ((ring[i].y > p.y) != (ring[j].y > p.y) &&
          p.x < ring[j].x + (p.y - ring[j].y) * (ring[i].x - ring[j].x) / (ring[i].y - ring[j].y))
        in = !in;
    return in;
  };
  for (std::size_t k = 1; k < flat.size(); ++k) {
    require(inside(flat[k][0], flat[0]), function, names[k] + " is not inside the outline");
    for (std::size_t m = 1; m < flat.size(); ++m)
      require(m == k || !inside(flat[k][0], flat[m]), function, names[k] + " lies inside " + names[m]);
  }
  return f;
}

}  // namespace

Solid pyramid(const std::vector<Point3>& outline_in, Point3 apex) {
  std::vector<Point3> outline = without_closing_point(outline_in);
  require(is_finite(apex), "pyramid", "apex must be finite");
  const PlaneFrame frame = planar_polygon("pyramid", outline, {});
  const double height = dot(apex - frame.origin, frame.n);
  const double size = std::max(frame.size, distance(apex, frame.origin));
  require(std::abs(height) > Tolerance::kPlanarity * size, "pyramid",
          "apex must lie off the outline's plane");
  // The base faces away from the apex.
  if (height > 0) std::reverse(outline.begin(), outline.end());
  const auto n = static_cast<std::uint32_t>(outline.size());
  std::vector<Point3> vertices = outline;
  vertices.push_back(apex);
  std::vector<IndexedFace> faces;
  IndexedFace base(1);
  for (std::uint32_t i = 0; i < n; ++i) base[0].push_back(i);
  faces.push_back(std::move(base));
  // The side over base edge a→b runs b→a, as its neighbour across that edge must.
  for (std::uint32_t i = 0; i < n; ++i) faces.push_back(IndexedFace{{(i + 1) % n, i, n}});
  return solid_from_indexed(vertices, faces);
}

Solid extrude(const std::vector<Point3>& outline_in, Vector3 direction,
              const std::vector<std::vector<Point3>>& holes_in) {
  std::vector<std::vector<Point3>> rings = {without_closing_point(outline_in)};
  for (const auto& h : holes_in) rings.push_back(without_closing_point(h));
  const std::vector<std::vector<Point3>> holes(rings.begin() + 1, rings.end());
  const PlaneFrame frame = planar_polygon("extrude", rings[0], holes);
  require(std::isfinite(direction.x) && std::isfinite(direction.y) && std::isfinite(direction.z), "extrude",
          "direction v must be finite");
  const double len = length(direction);
  double extent = 0;
  for (const auto& r : rings)
    for (const Point3& p : r) extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  // Each point and its copy must be distinct vertices, and the side faces must have area.
  require(len > 10 * Tolerance::kRelative * std::max(extent, frame.size), "extrude",
          "direction v must not be zero");
  require(std::abs(dot(direction, frame.n)) > Tolerance::kPlanarity * len, "extrude",
          "direction v must not be parallel to the outline's plane");

  // Seen from the side `direction` points to: the outline counter-clockwise, the holes clockwise. Then
  // the moved copy is the cap facing along `direction` and the original the base facing against it.
  for (std::size_t k = 0; k < rings.size(); ++k) {
    const bool along = dot(newell(rings[k]), direction) > 0;
    if (along != (k == 0)) std::reverse(rings[k].begin(), rings[k].end());
  }
  std::vector<Point3> vertices;
  std::vector<std::vector<std::uint32_t>> ids;
  for (const auto& r : rings) {
    ids.emplace_back();
    for (const Point3& p : r) {
      ids.back().push_back(static_cast<std::uint32_t>(vertices.size()));
      vertices.push_back(p);
    }
  }
  const auto count = static_cast<std::uint32_t>(vertices.size());
  for (std::uint32_t i = 0; i < count; ++i) vertices.push_back(vertices[i] + direction);

  std::vector<IndexedFace> faces(2);
  for (const auto& r : ids) {
    faces[0].emplace_back(r.rbegin(), r.rend());
    std::vector<std::uint32_t> moved;
    for (std::uint32_t id : r) moved.push_back(count + id);
    faces[1].push_back(std::move(moved));
  }
  // Side over ring edge a→b: its normal (b − a) × direction points away from the material on the left.
  for (const auto& r : ids)
    for (std::size_t i = 0; i < r.size(); ++i) {
      const std::uint32_t a = r[i], b = r[(i + 1) % r.size()];
      faces.push_back(IndexedFace{{a, b, count + b, count + a}});
    }
  return solid_from_indexed(vertices, faces);
}

}  // namespace hlr::stdlib
