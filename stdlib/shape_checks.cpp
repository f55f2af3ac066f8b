// Simplicity of polygons and polylines for the shape generators: catching a self-intersecting outline
// here gives the script a clear message instead of a solid the builder rejects (or, worse, accepts).
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "core/tolerance.hpp"
#include "stdlib/shapes.hpp"

namespace hlr::stdlib {

namespace {

struct Edge {
  std::size_t ring, index;
  Point2 a, b;
  double min_x, max_x, min_y, max_y;
};

double distance_to_segment(Point2 p, Point2 a, Point2 b) {
  const Vector2 ab = b - a, ap = p - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(ap, ab) / len2, 0.0, 1.0) : 0.0;
  return distance(p, a + t * ab);
}

// Strict crossing: each segment's end points lie strictly on opposite sides of the other's line.
bool properly_cross(Point2 a, Point2 b, Point2 c, Point2 d) {
  const double o1 = cross(b - a, c - a), o2 = cross(b - a, d - a);
  const double o3 = cross(d - c, a - c), o4 = cross(d - c, b - c);
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

bool meet(const Edge& e, const Edge& f, double tol) {
  if (properly_cross(e.a, e.b, f.a, f.b)) return true;
  return std::min({distance_to_segment(e.a, f.a, f.b), distance_to_segment(e.b, f.a, f.b),
                   distance_to_segment(f.a, e.a, e.b), distance_to_segment(f.b, e.a, e.b)}) <= tol;
}

}  // namespace

std::optional<RingDefect> find_ring_defect(const std::vector<std::vector<Point2>>& rings, bool closed,
                                           double extent) {
  for (const auto& ring : rings)
    for (const Point2& p : ring) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
  const double tol = Tolerance::kRelative * extent;

  std::vector<Edge> edges;
  std::vector<std::size_t> edge_count(rings.size());
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& ring = rings[r];
    const std::size_t n = ring.size() < 2 ? 0 : (closed ? ring.size() : ring.size() - 1);
    edge_count[r] = n;
    for (std::size_t i = 0; i < n; ++i) {
      const Point2 a = ring[i], b = ring[(i + 1) % ring.size()];
      if (distance(a, b) <= tol) return RingDefect{r, i, r, i};
      edges.push_back(
          {r, i, a, b, std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)});
    }
  }
  // Neighbours in one ring share a corner; they only conflict when one folds back onto the other.
  auto neighbours = [&](const Edge& e, const Edge& f) {
    if (e.ring != f.ring) return false;
    const std::size_t n = edge_count[e.ring], lo = std::min(e.index, f.index),
                      hi = std::max(e.index, f.index);
    return hi == lo + 1 || (closed && n >= 3 && lo == 0 && hi == n - 1);
  };
  auto fold = [&](const Edge& e, const Edge& f) {
    // e's end is f's start (or the other way round): the far ends must stay off the other edge.
    const Edge& first = (e.b == f.a) ? e : f;
    const Edge& second = (e.b == f.a) ? f : e;
    return distance_to_segment(first.a, second.a, second.b) <= tol ||
           distance_to_segment(second.b, first.a, first.b) <= tol;
  };

  std::sort(edges.begin(), edges.end(), [](const Edge& e, const Edge& f) { return e.min_x < f.min_x; });
  std::optional<RingDefect> found;
  auto record = [&](const Edge& e, const Edge& f) {
    auto key_e = std::tie(e.ring, e.index), key_f = std::tie(f.ring, f.index);
    const RingDefect d = key_e < key_f ? RingDefect{e.ring, e.index, f.ring, f.index}
                                       : RingDefect{f.ring, f.index, e.ring, e.index};
    // Keep the lowest pair so the message does not depend on the sweep order.
    if (!found || std::tie(d.ring_a, d.edge_a, d.ring_b, d.edge_b) <
                      std::tie(found->ring_a, found->edge_a, found->ring_b, found->edge_b))
      found = d;
  };
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Edge& e = edges[i];
    for (std::size_t j = i + 1; j < edges.size() && edges[j].min_x <= e.max_x + tol; ++j) {
      const Edge& f = edges[j];
      if (f.min_y > e.max_y + tol || f.max_y < e.min_y - tol) continue;
      if (neighbours(e, f) ? fold(e, f) : meet(e, f, tol)) record(e, f);
    }
  }
  return found;
}

std::string describe_ring_defect(const RingDefect& defect, const std::vector<std::string>& names,
                                 const std::vector<std::vector<Point2>>& rings, bool closed) {
  auto name = [&](std::size_t r) { return r < names.size() ? names[r] : "ring " + std::to_string(r); };
  auto edge = [&](std::size_t r, std::size_t e) {
    const std::size_t n = r < rings.size() ? rings[r].size() : 0;
    const std::size_t end = closed && n > 0 ? (e + 1) % n : e + 1;
    return std::to_string(e) + "\u2013" + std::to_string(end);
  };
  const RingDefect& d = defect;
  if (d.ring_a == d.ring_b && d.edge_a == d.edge_b)
    return name(d.ring_a) + " has a zero-length edge " + edge(d.ring_a, d.edge_a) + " (a repeated point)";
  if (d.ring_a == d.ring_b)
    return name(d.ring_a) + " is not simple: its edges " + edge(d.ring_a, d.edge_a) + " and " +
           edge(d.ring_b, d.edge_b) + " cross or touch";
  return name(d.ring_b) + " crosses or touches " + name(d.ring_a) + " (edge " + edge(d.ring_b, d.edge_b) +
         " of " + name(d.ring_b) + ", edge " + edge(d.ring_a, d.edge_a) + " of " + name(d.ring_a) + ")";
}

}  // namespace hlr::stdlib
