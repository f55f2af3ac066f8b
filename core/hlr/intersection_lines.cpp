#include "core/hlr/intersection_lines.hpp"

#include <algorithm>
#include <cmath>

#include "core/geometry/polygon2d.hpp"
#include "core/hlr/interval_set.hpp"
#include "core/tolerance.hpp"

namespace hlr {
namespace {

struct Box3 {
  Point3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  void include(Point3 p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  bool overlaps(const Box3& o, double tol) const {
    return lo.x <= o.hi.x + tol && o.lo.x <= hi.x + tol && lo.y <= o.hi.y + tol && o.lo.y <= hi.y + tol &&
           lo.z <= o.hi.z + tol && o.lo.z <= hi.z + tol;
  }
};

Box3 face_box(const Solid& solid, const Face& face) {
  Box3 b;
  for (VertexIndex v : face.rings[0].vertices) b.include(solid.vertices[v]);
  return b;
}

// The face's rings in 2-D, dropping the normal's dominant axis (an affine, area-preserving-up-to-scale
// view of the plane, so containment is unchanged).
struct FlatFace {
  std::vector<Point2> points;
  std::vector<std::uint32_t> ring_ends;
  int drop = 2;
  Point2 flatten(Point3 p) const {
    if (drop == 0) return {p.y, p.z};
    if (drop == 1) return {p.z, p.x};
    return {p.x, p.y};
  }
};

void flatten_face(const Solid& solid, FaceIndex f, FlatFace& out) {
  const Vector3 n = solid.planes[f].normal;
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  out.drop = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
  out.points.clear();
  out.ring_ends.clear();
  for (const Ring& ring : solid.faces[f].rings) {
    for (VertexIndex v : ring.vertices) out.points.push_back(out.flatten(solid.vertices[v]));
    out.ring_ends.push_back(static_cast<std::uint32_t>(out.points.size()));
  }
}

// Parameter intervals of the line L0 + λ·dir lying strictly inside face f of `solid`.
void inside_intervals(const Solid& solid, FaceIndex f, const Plane& other_plane, Point3 origin, Vector3 dir,
                      double tol, FlatFace& flat, std::vector<double>& breaks, std::vector<Interval>& out) {
  out.clear();
  breaks.clear();
  auto param = [&](Point3 x) { return dot(x - origin, dir); };
  for (const Ring& ring : solid.faces[f].rings) {
    const std::size_t n = ring.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point3 p = solid.vertices[ring.vertices[i]], q = solid.vertices[ring.vertices[(i + 1) % n]];
      const double dp = other_plane.signed_distance(p), dq = other_plane.signed_distance(q);
      if ((dp > tol && dq > tol) || (dp < -tol && dq < -tol)) continue;
      if (std::abs(dp) <= tol) breaks.push_back(param(p));
      if (std::abs(dq) <= tol) breaks.push_back(param(q));
      if ((dp > tol && dq < -tol) || (dp < -tol && dq > tol)) breaks.push_back(param(lerp(p, q, dp / (dp - dq))));
    }
  }
  if (breaks.size() < 2) return;
  std::sort(breaks.begin(), breaks.end());
  flatten_face(solid, f, flat);
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double a = breaks[i], b = breaks[i + 1];
    if (b - a <= tol) continue;
    const Point2 mid = flat.flatten(origin + (0.5 * (a + b)) * dir);
    if (classify_point(flat.points, flat.ring_ends, mid, tol) != PointClass::Inside) continue;
    if (!out.empty() && out.back().hi >= a) {
      out.back().hi = b;
    } else {
      out.push_back({a, b});
    }
  }
}

}  // namespace

void add_intersection_candidates(const Scene& scene, const Camera& camera,
                                 const std::vector<std::vector<std::int8_t>>& facing, const std::vector<char>& cull,
                                 double tol, bool keep_culled, FrameSetup& setup) {
  const std::size_t n = scene.objects.size();
  std::vector<Box3> boxes(n);
  for (std::size_t o = 0; o < n; ++o)
    for (Point3 p : scene.objects[o].solid->vertices) boxes[o].include(p);

  struct FaceRef {
    FaceIndex face;
    Box3 box;
  };
  // A face of a closed solid that faces away lies behind the solid's own front faces: the intersection
  // lines on it are hidden.
  auto culled_face = [&](std::size_t o, FaceIndex f) { return cull[o] && facing[o][f] <= 0; };
  auto faces_of = [&](std::size_t o, const Box3& clip) {
    std::vector<FaceRef> refs;
    const Solid& s = *scene.objects[o].solid;
    for (std::size_t f = 0; f < s.faces.size(); ++f) {
      const Box3 b = face_box(s, s.faces[f]);
      if (b.overlaps(clip, tol)) refs.push_back({static_cast<FaceIndex>(f), b});
    }
    std::sort(refs.begin(), refs.end(), [](const FaceRef& a, const FaceRef& b) { return a.box.lo.x < b.box.lo.x; });
    return refs;
  };

  FlatFace flat;
  std::vector<double> breaks;
  std::vector<Interval> in_a, in_b;
  std::uint32_t piece_index = 0;
  // Broad phase: sweep the objects' boxes along x, so cities of many separate solids stay near-linear.
  std::vector<std::size_t> order(n);
  for (std::size_t o = 0; o < n; ++o) order[o] = o;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return boxes[a].lo.x < boxes[b].lo.x; });
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n && boxes[order[b]].lo.x <= boxes[order[a]].hi.x + tol; ++b)
      if (boxes[order[a]].overlaps(boxes[order[b]], tol))
        pairs.emplace_back(std::min(order[a], order[b]), std::max(order[a], order[b]));
  std::sort(pairs.begin(), pairs.end());
  for (const auto& [i, j] : pairs) {
    {
      const Solid& si = *scene.objects[i].solid;
      const Solid& sj = *scene.objects[j].solid;
      const std::vector<FaceRef> fa = faces_of(i, boxes[j]), fb = faces_of(j, boxes[i]);
      // Sweep over x: each face of i meets the faces of j whose x-range overlaps.
      std::size_t start = 0;
      for (const FaceRef& a : fa) {
        while (start < fb.size() && fb[start].box.hi.x < a.box.lo.x - tol) ++start;
        for (std::size_t k = start; k < fb.size() && fb[k].box.lo.x <= a.box.hi.x + tol; ++k) {
          const FaceRef& b = fb[k];
          if (b.box.hi.x < a.box.lo.x - tol || !a.box.overlaps(b.box, tol)) continue;
          const Plane& pa = si.planes[a.face];
          const Plane& pb = sj.planes[b.face];
          Vector3 dir = cross(pa.normal, pb.normal);
          const double d2 = dot(dir, dir);
          if (std::sqrt(d2) < Tolerance::kCoplanarAngle) continue;  // parallel or coplanar: no line
          // A point on both planes (n·x = −offset): x0 = (h1 (n2 × d) + h2 (d × n1)) / |d|².
          const Point3 origin =
              to_point(((-pa.offset) * cross(pb.normal, dir) + (-pb.offset) * cross(dir, pa.normal)) / d2);
          dir = dir / std::sqrt(d2);
          inside_intervals(si, a.face, pb, origin, dir, tol, flat, breaks, in_a);
          if (in_a.empty()) continue;
          inside_intervals(sj, b.face, pa, origin, dir, tol, flat, breaks, in_b);
          for (const Interval& x : in_a)
            for (const Interval& y : in_b) {
              const double lo = std::max(x.lo, y.lo), hi = std::min(x.hi, y.hi);
              if (hi - lo <= tol) continue;
              // Pieces are numbered whether or not they are kept, so a piece has the same number with
              // and without the hidden layer.
              const bool culled = culled_face(i, a.face) || culled_face(j, b.face);
              if (culled && !keep_culled) {
                ++piece_index;
                continue;
              }
              Candidate c;
              c.source = SegmentSource::Intersection;
              c.object = static_cast<std::uint32_t>(i);
              c.other = static_cast<std::uint32_t>(j);
              c.edge = piece_index++;
              c.own_face0 = a.face;
              c.own_face1 = b.face;
              c.view0 = camera.view(origin + lo * dir);
              c.view1 = camera.view(origin + hi * dir);
              c.culled = culled;
              setup.candidates.push_back(c);
            }
        }
      }
    }
  }
}

}  // namespace hlr
