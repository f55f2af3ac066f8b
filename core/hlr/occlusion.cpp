#include "core/hlr/occlusion.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>

#include "core/geometry/clip2d.hpp"
#include "core/geometry/polygon2d.hpp"
#include "core/hlr/exact_occlusion.hpp"
#include "core/tolerance.hpp"

namespace hlr {

namespace {
constexpr std::uint32_t kSideTestPoints = 32;  // outlines up to this size get quick reject 2

// True when the picture segment a→b leaves a corner of triangle t that it starts or ends at exactly, on
// a bearing outside the corner's angle: the triangle lies within that angle, so the rest of the segment
// is outside it and the triangle hides none of it. An edge against the faces round its end vertices (a
// mesh's commonest test) meets them so: they share its end point. Near-flat corners and bearings within
// the relative tolerance of the angle's sides are left to the full test.
bool leaves_triangle_corner(const Point2* t, Point2 a, Point2 b) {
  for (int i = 0; i < 3; ++i) {
    Vector2 d;
    if (t[i] == a) {
      d = b - a;
    } else if (t[i] == b) {
      d = a - b;
    } else {
      continue;
    }
    const Vector2 u = t[(i + 2) % 3] - t[i], w = t[(i + 1) % 3] - t[i];
    const double k2 = Tolerance::kRelative * Tolerance::kRelative;
    const double uu = dot(u, u), ww = dot(w, w), dd = dot(d, d);
    const double turn = cross(u, w);
    if (turn * turn <= k2 * uu * ww) return false;                // no angle to speak of
    const double side_u = turn > 0 ? cross(u, d) : -cross(u, d);  // < 0: d turns away from w past u
    const double side_w = turn > 0 ? cross(d, w) : -cross(d, w);  // < 0: d turns away from u past w
    return (side_u < 0 && side_u * side_u > k2 * uu * dd) || (side_w < 0 && side_w * side_w > k2 * ww * dd);
  }
  return false;
}

// Sides of the candidate's ends that lie within the tolerance of the occluder's plane (side 0), decided
// exactly where ExactTriangleTest can; `root` set when both were within it (g is then rounding, and so
// would its root be). Rare, and kept out of the hot path.
[[gnu::noinline]] void decide_within_tolerance(const ExactTriangleTest& exact, int& side0, int& side1,
                                               double& root) {
  const bool both = side0 == 0 && side1 == 0;
  if (side0 == 0) side0 = exact.side(0);
  if (side1 == 0) side1 = exact.side(1);
  if (both && side0 * side1 < 0) root = exact.root();
}

// A piece whose midpoint lies within the tolerance of the occluder's outline in the picture, or of a seam:
// inside or not, exactly. Exactly on a seam is inside: the neighbour across it covers the rest.
template <typename IsSeam>
[[gnu::noinline]] bool exactly_inside(const ExactTriangleTest& exact, double t_mid, IsSeam&& is_seam) {
  int side = -1;
  const PointClass where = exact.shadow(t_mid, side);
  return where == PointClass::Inside ||
         (where == PointClass::Boundary && side >= 0 && is_seam(static_cast<std::uint32_t>(side)));
}

}  // namespace

double picture_param(const Candidate& c, const Camera& camera, double t) {
  if (camera.projection != Projection::Perspective) return t;
  const double z0 = c.view0.z, z1 = c.view1.z;
  return t * z1 / ((1 - t) * z0 + t * z1);
}

double view_param(const Candidate& c, const Camera& camera, double s) {
  if (camera.projection != Projection::Perspective) return s;
  const double z0 = c.view0.z, z1 = c.view1.z;
  return s * z0 / ((1 - s) * z1 + s * z0);
}

void add_hidden_intervals(const FrameSetup& setup, const Camera& camera, const Candidate& c,
                          const Occluder& o, OcclusionScratch& scratch, IntervalSet& hidden) {
  const double ltol = setup.length_tolerance;
  const double ptol = std::max(c.picture_tolerance, o.picture_tolerance);
  // Quick reject: the polygon's outline lies wholly on one side of the segment's line, beyond the
  // tolerance (the sides of a prism seen at a slant overlap in their boxes, not on the picture; a
  // 20 000-gon prism's edges meet 60 such sides each, and this rejects 98 % of its tests). First, as the
  // cheapest test. Only for small polygons: a large one is cheaper to meet through its grid.
  const std::uint32_t outer_end = setup.ring_ends[o.first_ring];
  if (outer_end - o.first_point <= kSideTestPoints) {
    // Quick reject 3, asked first: the faces round an edge's end vertices (two thirds of a scanned mesh's
    // tests), told by comparing points before any arithmetic.
    if (outer_end - o.first_point == 3 && o.ring_count == 1 &&
        leaves_triangle_corner(&setup.polygon_points[o.first_point], c.pic0, c.pic1)) {
      return;
    }
    const Vector2 d = c.pic1 - c.pic0;
    const double reach = ptol * length(d);
    bool left = true, right = true;
    for (std::uint32_t i = o.first_point; i < outer_end && (left || right); ++i) {
      const double side = cross(d, setup.polygon_points[i] - c.pic0);
      left = left && side > reach;
      right = right && side < -reach;
    }
    if (left || right) return;
  }
  // 1. Behind the plane: g(t) = eye_side·(n·v(t) + offset) < 0, linear in t. Beyond the tolerance the
  //    sign of g is certain; within it, a triangle's side is decided exactly (decide_within_tolerance).
  const double g0 = o.eye_side * (dot(o.normal, to_vector(c.view0)) + o.offset);
  const double g1 = o.eye_side * (dot(o.normal, to_vector(c.view1)) + o.offset);
  int side0 = g0 > ltol ? 1 : (g0 < -ltol ? -1 : 0), side1 = g1 > ltol ? 1 : (g1 < -ltol ? -1 : 0);
  // The exact fallbacks share one ExactTriangleTest, prepared the first time one is needed.
  int exact_state = 0;  // 0 untried, 1 ready, −1 unavailable
  std::optional<ExactTriangleTest> exact;
  auto exact_test = [&]() -> const ExactTriangleTest* {
    if (exact_state == 0) {
      exact.emplace();
      exact_state = exact->prepare(setup, camera, c, o) ? 1 : -1;
    }
    return exact_state > 0 ? &*exact : nullptr;
  };
  double root = -1;  // where it crosses the plane, when decided exactly
  if (side0 == 0 || side1 == 0)
    if (const ExactTriangleTest* e = exact_test()) decide_within_tolerance(*e, side0, side1, root);
  if (side0 >= 0 && side1 >= 0) return;  // in front of or on the plane throughout
  double t_lo = 0, t_hi = 1;
  if (side0 >= 0) {
    t_lo = root >= 0 ? root : g0 / (g0 - g1);  // enters the back side there
  } else if (side1 >= 0) {
    t_hi = root >= 0 ? root : g0 / (g0 - g1);
  }
  t_lo = std::clamp(t_lo, 0.0, 1.0);
  t_hi = std::clamp(t_hi, 0.0, 1.0);
  if (t_hi <= t_lo) return;
  const double s_lo = picture_param(c, camera, t_lo), s_hi = picture_param(c, camera, t_hi);
  // Quick reject: the part behind the plane misses the polygon's bounds. (The range itself is not narrowed
  // to the bounds: breaks there would put midpoints within the tolerance of the polygon's corners.)
  const Rect2 box{o.bounds.xmin - ptol, o.bounds.ymin - ptol, o.bounds.xmax + ptol, o.bounds.ymax + ptol};
  const auto over = clip_segment_to_rect(c.pic0, c.pic1, box);
  if (!over || over->second < s_lo || over->first > s_hi) return;

  // 2. Inside the projected polygon: break the picture segment where it meets any ring edge or passes
  //    within the tolerance of a ring vertex, then classify each piece by its midpoint. Extra breaks are
  //    harmless; a missed one is not, so the tests are generous.
  const Point2 a = c.pic0, b = c.pic1;
  const Vector2 r = b - a;
  const double r2 = dot(r, r);
  if (r2 <= ptol * ptol) return;
  std::vector<double>& breaks = scratch.breaks;
  breaks.clear();
  breaks.push_back(s_lo);
  breaks.push_back(s_hi);
  const std::size_t point_count = setup.ring_ends[o.first_ring + o.ring_count - 1] - o.first_point;
  const std::span<const Point2> pts(setup.polygon_points.data() + o.first_point, point_count);
  const FaceIndex* seams = setup.polygon_seams.data() + o.first_point;
  // A seam covers a point only through the neighbour across it, which must not be the edge's own face.
  auto is_seam = [&](std::uint32_t i) {
    const FaceIndex n = seams[i];
    return n != kNoFace && !(o.object == c.own_object0() && n == c.own_face0) &&
           !(o.object == c.own_object1() && n == c.own_face1);
  };
  std::uint32_t ends_buf[64];
  std::vector<std::uint32_t> ends_heap;
  std::uint32_t* ends = ends_buf;
  if (o.ring_count > 64) {
    ends_heap.resize(o.ring_count);
    ends = ends_heap.data();
  }
  for (std::uint32_t k = 0; k < o.ring_count; ++k)
    ends[k] = setup.ring_ends[o.first_ring + k] - o.first_point;
  const double rlen = std::sqrt(r2);
  // Lines nearly parallel in the picture cross where floating point puts them only to within u / angle
  // of their length: a triangle's side then gets its exact crossing too (extra breaks are harmless).
  auto exact_break = [&](std::uint32_t i) {
    const ExactTriangleTest* e = exact_test();
    if (!e) return;
    const double t = e->sight_crossing(static_cast<int>(i));
    if (t < 0) return;
    const double s = picture_param(c, camera, t);
    if (s > s_lo && s < s_hi) breaks.push_back(s);
  };
  // Breaks from ring edge i, p→q.
  auto test_edge = [&](std::uint32_t i, Point2 p, Point2 q) {
    const Vector2 e = q - p;
    const Vector2 ap = p - a;
    // Ring vertex close to the segment's line: break at its foot.
    const double sp = dot(ap, r) / r2;
    if (std::abs(cross(r, ap)) <= ptol * rlen && sp > s_lo && sp < s_hi) breaks.push_back(sp);
    // Proper crossing. A crossing at or near a ring vertex is also caught by the vertex test above, so
    // u needs no margin; parallel edges have no crossing of their own.
    const double den = cross(r, e);
    if (point_count == 3 && std::abs(den) <= Tolerance::kNearlyParallel * rlen * length(e)) exact_break(i);
    if (den == 0) return;
    const double s = cross(ap, e) / den;
    const double u = cross(ap, r) / den;
    if (u >= 0 && u <= 1 && s > s_lo && s < s_hi) breaks.push_back(s);
  };
  const RingEdgeGrid* grid = o.grid >= 0 ? &setup.ring_grids[static_cast<std::size_t>(o.grid)] : nullptr;
  if (grid) {  // only the ring edges near the part behind the plane (some twice: extra breaks are harmless)
    grid->for_each_edge_near(lerp(a, b, s_lo), lerp(a, b, s_hi), ptol,
                             [&](std::uint32_t i) { test_edge(i, pts[i], pts[grid->next(i)]); });
  } else {
    std::uint32_t begin = 0;
    for (std::uint32_t k = 0; k < o.ring_count; ++k) {
      const std::uint32_t end = ends[k];
      for (std::uint32_t i = begin; i < end; ++i) test_edge(i, pts[i], pts[i + 1 < end ? i + 1 : begin]);
      begin = end;
    }
  }
  std::sort(breaks.begin(), breaks.end());
  const std::span<const std::uint32_t> ring_ends(ends, o.ring_count);
  double open_lo = -1;  // start of the hidden run being built, or -1
  double open_hi = -1;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double s0 = breaks[i], s1 = breaks[i + 1];
    if (s1 <= s0) continue;
    const Point2 mid = lerp(a, b, 0.5 * (s0 + s1));
    const PointClass where =
        grid ? grid->classify(mid, ptol, is_seam) : classify_point(pts, ring_ends, mid, ptol, is_seam);
    bool inside = where == PointClass::Inside;
    if (where == PointClass::Boundary || where == PointClass::Seam) {
      const ExactTriangleTest* e = exact_test();
      inside =
          e ? exactly_inside(*e, view_param(c, camera, 0.5 * (s0 + s1)), is_seam) : where == PointClass::Seam;
    }
    if (inside) {
      if (open_lo < 0) open_lo = s0;
      open_hi = s1;
    } else if (open_lo >= 0) {
      hidden.add(view_param(c, camera, open_lo), view_param(c, camera, open_hi));
      open_lo = -1;
    }
  }
  if (open_lo >= 0) hidden.add(view_param(c, camera, open_lo), view_param(c, camera, open_hi));
}

}  // namespace hlr
