#include "core/solid/face_geometry.hpp"

#include <cmath>
#include <numbers>

#include "core/tolerance.hpp"

namespace hlr::solid_detail {

Plane newell_plane(const std::vector<Point3>& vertices, const Ring& ring, double* twice_area) {
  const Vector3 n = newell_normal(vertices, ring);
  if (twice_area) *twice_area = length(n);
  return newell_plane(vertices, ring, n);
}

Plane newell_plane(const std::vector<Point3>& vertices, const Ring& ring, Vector3 n) {
  const double len = length(n);
  Vector3 sum{};
  for (VertexIndex i : ring.vertices) sum += to_vector(vertices[i]);
  const Vector3 centroid =
      ring.vertices.empty() ? Vector3{} : sum / static_cast<double>(ring.vertices.size());
  Plane plane;
  plane.normal = len > 0 ? n / len : Vector3{};
  plane.offset = -dot(plane.normal, centroid);
  return plane;
}

FaceFrame FaceFrame::from_normal(Vector3 n, Point3 origin) {
  // Cross with the axis least aligned with n, so u is well conditioned.
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  const Vector3 axis =
      (ax <= ay && ax <= az) ? Vector3{1, 0, 0} : (ay <= az ? Vector3{0, 1, 0} : Vector3{0, 0, 1});
  FaceFrame f;
  f.origin = origin;
  f.u = normalize(cross(n, axis));
  f.v = cross(n, f.u);
  return f;
}

double signed_area(const Polygon2& ring) {
  if (ring.size() < 3) return 0;
  double twice = 0;
  const Point2 o = ring[0];
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) twice += cross(ring[i] - o, ring[i + 1] - o);
  return twice / 2;
}

namespace {

double distance_to_segment(Point2 p, Point2 a, Point2 b) {
  const Vector2 ab = b - a, ap = p - a;
  const double len2 = dot(ab, ab);
  if (len2 == 0) return length(ap);
  double t = dot(ap, ab) / len2;
  t = t < 0 ? 0 : (t > 1 ? 1 : t);
  return distance(p, a + t * ab);
}

// Signed distance of p from the line through a and b (positive on the left of a→b).
double side(Point2 a, Point2 b, Point2 p) { return cross(b - a, p - a) / length(b - a); }

}  // namespace

Containment classify_point(Point2 p, const std::vector<Polygon2>& rings, double tolerance) {
  bool inside = false;
  for (const Polygon2& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point2 a = ring[i], b = ring[(i + 1) % ring.size()];
      if (distance_to_segment(p, a, b) <= tolerance) return Containment::Boundary;
      // Even-odd: count crossings of the ray from p towards +x (half-open in y, so vertices count once).
      if ((a.y > p.y) != (b.y > p.y)) {
        const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
        if (p.x < x) inside = !inside;
      }
    }
  }
  return inside ? Containment::Inside : Containment::Outside;
}

bool segments_cross(Point2 a, Point2 b, Point2 c, Point2 d, double tolerance) {
  if (a == b || c == d) return false;
  const double s1 = side(a, b, c), s2 = side(a, b, d);
  if (std::abs(s1) <= tolerance || std::abs(s2) <= tolerance || (s1 > 0) == (s2 > 0)) return false;
  const double t1 = side(c, d, a), t2 = side(c, d, b);
  if (std::abs(t1) <= tolerance || std::abs(t2) <= tolerance || (t1 > 0) == (t2 > 0)) return false;
  return true;
}

DihedralClass classify_dihedral(Vector3 direction, Vector3 nl, Vector3 nr, double crease_angle_deg) {
  const Vector3 c = cross(nl, nr);
  const double sine = length(c), cosine = dot(nl, nr);
  // Most edges are plainly not flat (the angle between the normals is over twice kCoplanarAngle:
  // sine > 2·tan(kCoplanarAngle)·cosine), and with no crease angle that settles them without atan2.
  static const double kTwiceFlatSlope = 2 * std::tan(Tolerance::kCoplanarAngle);
  const bool plainly_bent = cosine <= 0 || sine > kTwiceFlatSlope * cosine;
  const bool concave = dot(direction, c) < 0;  // see below
  if (plainly_bent && crease_angle_deg <= 0) return {EdgeKind::Feature, concave};
  const double angle = std::atan2(sine, cosine);  // in [0, π]
  if (angle < Tolerance::kCoplanarAngle) return {EdgeKind::Flat, false};
  // Concavity (Pfister's test, adapted). Seen from outside, the left face L runs along e = v1 − v0 and
  // lies on the left of it, so it extends from the edge in direction dL = nL × e; the right face runs
  // along −e and extends in dR = nR × (−e) = e × nR. The edge is convex when R bends away from L's
  // outward side, dR·nL < 0, and dR·nL = (e × nR)·nL = −e·(nL × nR). So: convex ⇔ e·(nL × nR) > 0 and
  // concave ⇔ e·(nL × nR) < 0. (Cube check: top face L with nL = +z runs along e = +x over front face R
  // with nR = −y: nL × nR = +x, e·(+x) > 0, convex.) Pfister uses inward normals and clockwise faces,
  // i.e. his j1 is our R and his normals are negated, so his c = e·(nR × nL) = −e·(nL × nR): his
  // "c > 0 → concave" is the same test. |nL × nR| = sin(angle) ≥ sin(kCoplanarAngle) here, so the sign
  // is not noise.
  const double crease = crease_angle_deg * std::numbers::pi / 180;
  return {angle <= crease ? EdgeKind::Smooth : EdgeKind::Feature, concave};
}

}  // namespace hlr::solid_detail
