// The exact oracle (see exact_oracle.hpp). Plain loops over every triangle; only the determinants are
// clever, and only in being filtered before they are computed in rationals.
#include "tests/support/exact_oracle.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "tests/support/ray_caster_checks.hpp"

namespace hlr::test {

ExactPoint exact(Point3 p) { return {mpq_class(p.x), mpq_class(p.y), mpq_class(p.z)}; }

ExactPoint exact_lerp(Point3 a, Point3 b, double t) {
  const mpq_class q(t);
  ExactPoint p = exact(a);
  p.x += q * (mpq_class(b.x) - p.x);
  p.y += q * (mpq_class(b.y) - p.y);
  p.z += q * (mpq_class(b.z) - p.z);
  return p;
}

namespace {

struct ExactVector {
  mpq_class x, y, z;
};

ExactVector operator-(const ExactPoint& a, const ExactPoint& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
ExactVector cross(const ExactVector& u, const ExactVector& v) {
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}
mpq_class dot(const ExactVector& u, const ExactVector& v) { return u.x * v.x + u.y * v.y + u.z * v.z; }
ExactVector exact_vector(Vector3 v) { return {mpq_class(v.x), mpq_class(v.y), mpq_class(v.z)}; }
int sign_of(const mpq_class& q) { return sgn(q); }

// A row of a determinant: the difference of two points in doubles, with the magnitude that bounds its
// rounding, and how to make it exactly.
struct Row {
  double v[3];
  double m[3];
};

Row difference(Point3 x, Point3 y) {
  return {{x.x - y.x, x.y - y.y, x.z - y.z},
          {std::abs(x.x) + std::abs(y.x), std::abs(x.y) + std::abs(y.y), std::abs(x.z) + std::abs(y.z)}};
}

// Sign of det[r0; r1; r2] when the doubles decide it by a wide margin, else 2 (undecided).
int filtered_sign(const Row& r0, const Row& r1, const Row& r2) {
  const double* a = r0.v;
  const double* b = r1.v;
  const double* c = r2.v;
  const double d = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                   a[2] * (b[0] * c[1] - b[1] * c[0]);
  const double* p = r0.m;
  const double* q = r1.m;
  const double* s = r2.m;
  const double perm = p[0] * (q[1] * s[2] + q[2] * s[1]) + p[1] * (q[0] * s[2] + q[2] * s[0]) +
                      p[2] * (q[0] * s[1] + q[1] * s[0]);
  // Products below ~1e-280 may have underflowed (denormal coordinates), where no relative bound holds.
  if (!(perm > 1e-280) || !std::isfinite(perm)) return 2;
  if (d > 1e-12 * perm) return 1;
  if (d < -1e-12 * perm) return -1;
  return 2;
}

int exact_sign(const ExactVector& u, const ExactVector& v, const ExactVector& w) {
  return sign_of(dot(cross(u, v), w));
}

// The points where a triangle meets a plane, given its corners' signed values against it: corners on
// the plane, and where edges cross it.
std::vector<ExactPoint> meet_plane(const ExactPoint* v, const mpq_class* s) {
  std::vector<ExactPoint> out;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (sgn(s[i]) == 0) out.push_back(v[i]);
    if (sgn(s[i]) * sgn(s[j]) < 0) {
      const mpq_class t = s[i] / (s[i] - s[j]);
      out.push_back(
          {v[i].x + t * (v[j].x - v[i].x), v[i].y + t * (v[j].y - v[i].y), v[i].z + t * (v[j].z - v[i].z)});
    }
  }
  return out;
}

}  // namespace

ExactOracle::ExactOracle(const Scene& scene, const Camera& camera) : camera_(camera) {
  perspective_ = camera.projection == Projection::Perspective;
  eye_ = camera.eye_world();
  toward_eye_ = -camera.direction_world();
  bool first = true;
  for (std::uint32_t o = 0; o < scene.objects.size(); ++o) {
    const Solid& s = *scene.objects[o].solid;
    for (std::uint32_t f = 0; f < s.faces.size(); ++f) {
      const Face& face = s.faces[f];
      if (face.rings.size() != 1 || face.rings[0].vertices.size() != 3) {
        ADD_FAILURE() << "the exact oracle takes triangles only (object " << o << " face " << f << ")";
        continue;
      }
      Triangle t;
      t.object = o, t.face = f;
      t.va = face.rings[0].vertices[0], t.vb = face.rings[0].vertices[1], t.vc = face.rings[0].vertices[2];
      t.a = s.vertices[t.va], t.b = s.vertices[t.vb], t.c = s.vertices[t.vc];
      t.lo = {std::min({t.a.x, t.b.x, t.c.x}), std::min({t.a.y, t.b.y, t.c.y}),
              std::min({t.a.z, t.b.z, t.c.z})};
      t.hi = {std::max({t.a.x, t.b.x, t.c.x}), std::max({t.a.y, t.b.y, t.c.y}),
              std::max({t.a.z, t.b.z, t.c.z})};
      if (first) lo_ = t.lo, hi_ = t.hi, first = false;
      lo_ = {std::min(lo_.x, t.lo.x), std::min(lo_.y, t.lo.y), std::min(lo_.z, t.lo.z)};
      hi_ = {std::max(hi_.x, t.hi.x), std::max(hi_.y, t.hi.y), std::max(hi_.z, t.hi.z)};
      triangles_.push_back(t);
    }
  }
  extent_ = std::max(distance(lo_, hi_), 1e-300);
  for (const Triangle& t : triangles_) eye_sides_.push_back(eye_side(t));
}

int ExactOracle::side(const Triangle& t, const ExactPoint& p) const {
  const Point3 pa = p.approx();
  // The approximation's own rounding is covered by counting |p| in its row's magnitude.
  const int s = filtered_sign(difference(t.b, t.a), difference(t.c, t.a), difference(pa, t.a));
  if (s != 2) return s;
  const ExactPoint a = exact(t.a);
  return exact_sign(exact(t.b) - a, exact(t.c) - a, p - a);
}

int ExactOracle::eye_side(const Triangle& t) const {
  if (perspective_) return side(t, exact(eye_));
  Row r{{toward_eye_.x, toward_eye_.y, toward_eye_.z},
        {std::abs(toward_eye_.x), std::abs(toward_eye_.y), std::abs(toward_eye_.z)}};
  const int s = filtered_sign(difference(t.b, t.a), difference(t.c, t.a), r);
  if (s != 2) return s;
  const ExactPoint a = exact(t.a);
  return exact_sign(exact(t.b) - a, exact(t.c) - a, exact_vector(toward_eye_));
}

int ExactOracle::facing(std::uint32_t object, std::uint32_t face) const {
  for (std::size_t i = 0; i < triangles_.size(); ++i)
    if (triangles_[i].object == object && triangles_[i].face == face) return eye_sides_[i];
  return 0;
}

int ExactOracle::sight_orientation(Point3 u, Point3 v, const ExactPoint& p) const {
  const Point3 pa = p.approx();
  const Row r = perspective_
                    ? difference(eye_, pa)
                    : Row{{toward_eye_.x, toward_eye_.y, toward_eye_.z},
                          {std::abs(toward_eye_.x), std::abs(toward_eye_.y), std::abs(toward_eye_.z)}};
  const int s = filtered_sign(difference(u, pa), difference(v, pa), r);
  if (s != 2) return s;
  const ExactVector re = perspective_ ? exact(eye_) - p : exact_vector(toward_eye_);
  return exact_sign(exact(u) - p, exact(v) - p, re);
}

Visibility ExactOracle::visibility(const ExactPoint& p) const {
  const Point3 pa = p.approx();
  // The part of the sight line that can meet a triangle, boxed with a margin far above rounding.
  Point3 far;
  if (perspective_) {
    far = eye_;
  } else {
    const Point3 mid = lerp(lo_, hi_, 0.5);
    far = pa + (2 * extent_ + distance(pa, mid)) * normalize(toward_eye_);
  }
  const double margin = 1e-9 * (extent_ + distance(pa, far));
  const Point3 slo{std::min(pa.x, far.x) - margin, std::min(pa.y, far.y) - margin,
                   std::min(pa.z, far.z) - margin};
  const Point3 shi{std::max(pa.x, far.x) + margin, std::max(pa.y, far.y) + margin,
                   std::max(pa.z, far.z) + margin};
  bool ambiguous = false;
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    const Triangle& t = triangles_[i];
    if (t.hi.x < slo.x || t.lo.x > shi.x || t.hi.y < slo.y || t.lo.y > shi.y || t.hi.z < slo.z ||
        t.lo.z > shi.z)
      continue;
    const int s = side(t, p);
    if (s == 0 || s * eye_sides_[i] >= 0) continue;  // on its plane, or on the eye's side of it
    const int o1 = sight_orientation(t.a, t.b, p), o2 = sight_orientation(t.b, t.c, p),
              o3 = sight_orientation(t.c, t.a, p);
    if (o1 != 0 && o1 == o2 && o2 == o3) return Visibility::Hidden;
    const bool has_pos = o1 > 0 || o2 > 0 || o3 > 0, has_neg = o1 < 0 || o2 < 0 || o3 < 0;
    if (!(has_pos && has_neg)) ambiguous = true;  // through its boundary
  }
  return ambiguous ? Visibility::Ambiguous : Visibility::Visible;
}

std::vector<ExactCrossing> ExactOracle::crossings() const {
  std::vector<ExactCrossing> out;
  for (std::size_t i = 0; i < triangles_.size(); ++i)
    for (std::size_t j = i + 1; j < triangles_.size(); ++j) {
      const Triangle &t1 = triangles_[i], &t2 = triangles_[j];
      if (t1.hi.x < t2.lo.x || t2.hi.x < t1.lo.x || t1.hi.y < t2.lo.y || t2.hi.y < t1.lo.y ||
          t1.hi.z < t2.lo.z || t2.hi.z < t1.lo.z)
        continue;
      if (t1.object == t2.object) {
        int shared = 0;
        for (VertexIndex u : {t1.va, t1.vb, t1.vc}) shared += u == t2.va || u == t2.vb || u == t2.vc;
        if (shared >= 2) continue;  // neighbours along an edge
      }
      const ExactPoint v1[3] = {exact(t1.a), exact(t1.b), exact(t1.c)};
      const ExactPoint v2[3] = {exact(t2.a), exact(t2.b), exact(t2.c)};
      const ExactVector n1 = cross(v1[1] - v1[0], v1[2] - v1[0]), n2 = cross(v2[1] - v2[0], v2[2] - v2[0]);
      mpq_class s1[3], s2[3];  // t1's corners against t2's plane, and t2's against t1's
      for (int k = 0; k < 3; ++k) s1[k] = dot(n2, v1[k] - v2[0]), s2[k] = dot(n1, v2[k] - v1[0]);
      auto apart = [](const mpq_class* s) {
        return (sgn(s[0]) > 0 && sgn(s[1]) > 0 && sgn(s[2]) > 0) ||
               (sgn(s[0]) < 0 && sgn(s[1]) < 0 && sgn(s[2]) < 0);
      };
      if (apart(s1) || apart(s2)) continue;
      const ExactVector d = cross(n1, n2);
      if (sgn(d.x) == 0 && sgn(d.y) == 0 && sgn(d.z) == 0) continue;  // coplanar (or parallel): no line
      const std::vector<ExactPoint> m1 = meet_plane(v1, s1), m2 = meet_plane(v2, s2);
      if (m1.empty() || m2.empty()) continue;
      // Both lie on the planes' common line: order them along it.
      auto along = [&](const ExactPoint& p) -> mpq_class { return d.x * p.x + d.y * p.y + d.z * p.z; };
      auto extremes = [&](const std::vector<ExactPoint>& m, std::size_t& lo, std::size_t& hi) {
        lo = hi = 0;
        for (std::size_t k = 1; k < m.size(); ++k) {
          if (along(m[k]) < along(m[lo])) lo = k;
          if (along(m[k]) > along(m[hi])) hi = k;
        }
      };
      std::size_t lo1, hi1, lo2, hi2;
      extremes(m1, lo1, hi1);
      extremes(m2, lo2, hi2);
      const ExactPoint& from = along(m1[lo1]) >= along(m2[lo2]) ? m1[lo1] : m2[lo2];
      const ExactPoint& to = along(m1[hi1]) <= along(m2[hi2]) ? m1[hi1] : m2[hi2];
      if (along(from) >= along(to)) continue;  // they touch at a point, or not at all
      out.push_back({t1.object, t1.face, t2.object, t2.face, from, to});
    }
  return out;
}

std::string ExactReport::summary() const {
  std::ostringstream s;
  s << "drawn samples " << drawn_samples << " (hidden " << drawn_hidden << "), edge samples " << edge_samples
    << " (visible " << edge_visible << ", missing " << edge_missing << "), crossing samples "
    << crossing_samples << " (visible " << crossing_visible << ", missing " << crossing_missing
    << "), ambiguous " << ambiguous;
  for (const std::string& f : failures) s << "\n  " << f;
  return s.str();
}

namespace {

double point_segment_distance3(Point3 p, Point3 a, Point3 b) {
  const Vector3 ab = b - a;
  const double l2 = dot(ab, ab);
  const double t = l2 > 0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
  return distance(p, a + t * ab);
}

}  // namespace

ExactReport check_exact(const Scene& scene, const Camera& camera, const FrameResult& result,
                        const ExactCheckOptions& options) {
  ExactReport report;
  const ExactOracle oracle(scene, camera);
  const std::vector<ExactCrossing> crossings = oracle.crossings();
  double extent = 0;
  {
    Point3 lo{}, hi{};
    bool first = true;
    for (const SceneObject& o : scene.objects)
      for (Point3 p : o.solid->vertices) {
        if (first) lo = hi = p, first = false;
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
      }
    extent = distance(lo, hi);
  }
  const double reach = options.coverage * extent;
  const double picture_reach = options.coverage * picture_extent(scene, camera, result);
  auto fail = [&](const std::string& what) {
    if (report.failures.size() < options.max_failures) report.failures.push_back(what);
  };
  // Drawn pieces of edges, by (object, edge): their parameter ranges along the edge.
  std::vector<std::vector<std::vector<std::pair<double, double>>>> drawn(scene.objects.size());
  for (std::size_t o = 0; o < scene.objects.size(); ++o)
    drawn[o].resize(scene.objects[o].solid->edges.size());
  for (const VisibleSegment& s : result.segments) {
    if (s.hidden) continue;
    if (s.source == SegmentSource::Edge) {
      const Solid& solid = *scene.objects[s.object].solid;
      const SolidEdge& e = solid.edges[s.edge];
      const Point3 a = solid.vertices[e.v0], b = solid.vertices[e.v1];
      const Vector3 ab = b - a;
      const double l2 = dot(ab, ab);
      const double t0 = dot(s.p0 - a, ab) / l2, t1 = dot(s.p1 - a, ab) / l2;
      drawn[s.object][s.edge].push_back({std::min(t0, t1), std::max(t0, t1)});
      for (double f : kSegmentSampleFractions) {
        ++report.drawn_samples;
        const double t = t0 + f * (t1 - t0);
        const Visibility v = oracle.visibility(exact_lerp(a, b, t));
        if (v == Visibility::Ambiguous) ++report.ambiguous;
        if (v == Visibility::Hidden) {
          ++report.drawn_hidden;
          std::ostringstream m;
          m << "drawn but hidden: object " << s.object << " edge " << s.edge << " at t = " << t;
          fail(m.str());
        }
      }
      continue;
    }
    // An intersection piece: sampled on the exact crossing it lies along.
    const ExactCrossing* on = nullptr;
    for (const ExactCrossing& x : crossings) {
      const bool objects =
          (x.object0 == s.object && x.object1 == s.other) || (x.object0 == s.other && x.object1 == s.object);
      const Point3 x0 = x.p0.approx(), x1 = x.p1.approx();
      if (objects && point_segment_distance3(s.p0, x0, x1) <= 10 * reach &&
          point_segment_distance3(s.p1, x0, x1) <= 10 * reach) {
        on = &x;
        break;
      }
    }
    if (!on) {
      report.drawn_samples += kSegmentSampleFractions.size();
      report.drawn_hidden += kSegmentSampleFractions.size();
      std::ostringstream m;
      m << "an intersection piece of objects " << s.object << " and " << s.other
        << " lies on no crossing of their triangles";
      fail(m.str());
      continue;
    }
    const Point3 x0 = on->p0.approx(), x1 = on->p1.approx();
    const double l2 = dot(x1 - x0, x1 - x0);
    const double t0 = dot(s.p0 - x0, x1 - x0) / l2, t1 = dot(s.p1 - x0, x1 - x0) / l2;
    for (double f : kSegmentSampleFractions) {
      ++report.drawn_samples;
      const mpq_class t(std::clamp(t0 + f * (t1 - t0), 0.0, 1.0));
      ExactPoint p = on->p0;
      p.x += t * (on->p1.x - on->p0.x);
      p.y += t * (on->p1.y - on->p0.y);
      p.z += t * (on->p1.z - on->p0.z);
      const Visibility v = oracle.visibility(p);
      if (v == Visibility::Ambiguous) ++report.ambiguous;
      if (v == Visibility::Hidden) {
        ++report.drawn_hidden;
        fail("an intersection piece drawn where it is hidden");
      }
    }
  }
  // Candidate edges: every visible sample is covered by a drawn piece of the edge.
  const int n = options.edge_samples;
  for (std::uint32_t o = 0; o < scene.objects.size(); ++o) {
    const Solid& solid = *scene.objects[o].solid;
    for (std::uint32_t k = 0; k < solid.edges.size(); ++k) {
      const SolidEdge& e = solid.edges[k];
      if (e.kind == EdgeKind::Flat) continue;
      if (e.kind == EdgeKind::Smooth) {
        const int l = oracle.facing(o, e.left), r = oracle.facing(o, e.right);
        if (l == 0 || r == 0 || l == r) continue;  // not on the contour, or edge-on
      }
      const Point3 a = solid.vertices[e.v0], b = solid.vertices[e.v1];
      const double slack = reach / std::max(distance(a, b), 1e-300);
      for (int i = 0; i < n; ++i) {
        const double t = (i + 0.5) / n;
        ++report.edge_samples;
        const Visibility v = oracle.visibility(exact_lerp(a, b, t));
        if (v == Visibility::Ambiguous) ++report.ambiguous;
        if (v != Visibility::Visible) continue;
        ++report.edge_visible;
        bool covered = false;
        for (const auto& [lo, hi] : drawn[o][k]) covered = covered || (t >= lo - slack && t <= hi + slack);
        // Or drawn once for two edges lying on one line of the picture (the engine's rule for coincident
        // lines): by any drawn piece through its picture point.
        if (!covered) {
          const Point2 at = camera.project(lerp(a, b, t));
          for (const VisibleSegment& s : result.segments)
            covered = covered || (!s.hidden && point_segment_distance(at, s.s0, s.s1) <= picture_reach);
        }
        if (!covered) {
          ++report.edge_missing;
          std::ostringstream m;
          m << "visible but not drawn: object " << o << " edge " << k << " at t = " << t;
          fail(m.str());
        }
      }
    }
  }
  // Crossings: every visible sample lies on a drawn intersection piece of the two objects.
  for (const ExactCrossing& x : crossings) {
    for (int i = 0; i < n; ++i) {
      const mpq_class t((i + 0.5) / n);
      ExactPoint p = x.p0;
      p.x += t * (x.p1.x - x.p0.x);
      p.y += t * (x.p1.y - x.p0.y);
      p.z += t * (x.p1.z - x.p0.z);
      ++report.crossing_samples;
      const Visibility v = oracle.visibility(p);
      if (v == Visibility::Ambiguous) ++report.ambiguous;
      if (v != Visibility::Visible) continue;
      ++report.crossing_visible;
      const Point3 q = p.approx();
      bool covered = false;
      for (const VisibleSegment& s : result.segments)
        covered = covered || (!s.hidden && s.source == SegmentSource::Intersection &&
                              ((s.object == x.object0 && s.other == x.object1) ||
                               (s.object == x.object1 && s.other == x.object0)) &&
                              point_segment_distance3(q, s.p0, s.p1) <= reach);
      if (!covered) {
        ++report.crossing_missing;
        std::ostringstream m;
        m << "visible crossing not drawn: object " << x.object0 << " face " << x.face0 << " with object "
          << x.object1 << " face " << x.face1 << " at (" << q.x << ", " << q.y << ", " << q.z << ")";
        fail(m.str());
      }
    }
  }
  return report;
}

}  // namespace hlr::test
