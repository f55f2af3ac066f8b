// The brute-force oracle (see ray_caster.hpp for the tolerance rules). Deliberately plain: one loop over
// every face per query, no spatial index, no code shared with core/hlr.
#include "tests/support/ray_caster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace hlr::test {

const char* to_string(Visibility v) {
  switch (v) {
    case Visibility::Visible:
      return "Visible";
    case Visibility::Hidden:
      return "Hidden";
    case Visibility::Ambiguous:
      return "Ambiguous";
  }
  return "?";
}

double point_segment_distance(Point2 p, Point2 a, Point2 b) {
  const Vector2 ab = b - a, ap = p - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(ap, ab) / len2, 0.0, 1.0) : 0.0;
  return distance(p, a + t * ab);
}

double segment_distance(Point2 a, Point2 b, Point2 c, Point2 d) {
  const double o1 = cross(b - a, c - a), o2 = cross(b - a, d - a);
  const double o3 = cross(d - c, a - c), o4 = cross(d - c, b - c);
  const bool proper =
      ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
  if (proper) return 0;
  // Touching and collinear cases come out as a zero point distance below.
  return std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d),
                   point_segment_distance(c, a, b), point_segment_distance(d, a, b)});
}

bool inside_even_odd(const std::vector<std::vector<Point2>>& rings, Point2 p) {
  bool inside = false;
  for (const auto& ring : rings) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const Point2 a = ring[i], b = ring[(i + 1) % n];
      if ((a.y > p.y) != (b.y > p.y)) {
        const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
        if (p.x < x) inside = !inside;
      }
    }
  }
  return inside;
}

RayCaster::RayCaster(const Scene& scene, const Camera& camera, double relative_tolerance) : camera_(camera) {
  // Scene extent: bounding box of all vertices, plus the eye for perspective views.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Point3 lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};
  auto grow = [&](Point3 p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  };
  for (const auto& o : scene.objects)
    for (const Point3& p : o.solid->vertices) grow(p);
  if (camera.projection == Projection::Perspective) grow(camera.eye_world());
  if (lo.x > hi.x) lo = hi = Point3{};
  extent_ = std::max(distance(lo, hi), 1e-12);
  center_ = lerp(lo, hi, 0.5);
  tol_ = relative_tolerance * extent_;
  on_plane_ = 1e-10 * extent_;

  for (std::uint32_t oi = 0; oi < scene.objects.size(); ++oi) {
    const Solid& s = *scene.objects[oi].solid;
    first_face_.push_back(faces_.size());
    for (std::uint32_t fi = 0; fi < s.faces.size(); ++fi) {
      const Face& face = s.faces[fi];
      FaceRecord r;
      r.object = oi;
      r.face = fi;
      // Newell's normal of the outer ring, computed here rather than taken from Solid::planes.
      Vector3 nw{};
      Vector3 sum{};
      const auto& outer = face.rings.at(0).vertices;
      for (std::size_t i = 0; i < outer.size(); ++i) {
        const Point3 a = s.vertices[outer[i]], b = s.vertices[outer[(i + 1) % outer.size()]];
        nw += Vector3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
        sum += to_vector(a);
      }
      r.n = normalize(nw);
      r.origin = to_point(sum / static_cast<double>(outer.size()));
      r.d = -dot(r.n, to_vector(r.origin));
      // In-plane basis from the coordinate axis least aligned with the normal.
      const Vector3 ax = std::abs(r.n.x) <= std::abs(r.n.y) && std::abs(r.n.x) <= std::abs(r.n.z)
                             ? Vector3{1, 0, 0}
                             : (std::abs(r.n.y) <= std::abs(r.n.z) ? Vector3{0, 1, 0} : Vector3{0, 0, 1});
      r.u = normalize(cross(r.n, ax));
      r.v = cross(r.n, r.u);
      r.lo = {kInf, kInf, kInf};
      r.hi = {-kInf, -kInf, -kInf};
      for (const Ring& ring : face.rings) {
        std::vector<Point2> pts;
        for (VertexIndex vi : ring.vertices) {
          const Point3 p = s.vertices[vi];
          const Vector3 q = p - r.origin;
          pts.push_back({dot(q, r.u), dot(q, r.v)});
          r.lo = {std::min(r.lo.x, p.x), std::min(r.lo.y, p.y), std::min(r.lo.z, p.z)};
          r.hi = {std::max(r.hi.x, p.x), std::max(r.hi.y, p.y), std::max(r.hi.z, p.z)};
        }
        r.rings.push_back(std::move(pts));
      }
      r.lo = r.lo - Vector3{tol_, tol_, tol_};
      r.hi = r.hi + Vector3{tol_, tol_, tol_};
      faces_.push_back(std::move(r));
    }
  }
}

const RayCaster::FaceRecord& RayCaster::record(std::uint32_t object, std::uint32_t face) const {
  return faces_.at(first_face_.at(object) + face);
}

double RayCaster::signed_distance(std::uint32_t object, std::uint32_t face, Point3 p) const {
  const FaceRecord& f = record(object, face);
  return dot(f.n, to_vector(p)) + f.d;
}

Vector3 RayCaster::normal(std::uint32_t object, std::uint32_t face) const { return record(object, face).n; }

RayCaster::FaceProximity RayCaster::proximity(std::uint32_t object, std::uint32_t face, Point3 p) const {
  const FaceRecord& f = record(object, face);
  FaceProximity r;
  r.plane_distance = std::abs(dot(f.n, to_vector(p)) + f.d);
  const Vector3 q = p - f.origin;
  const Point2 p2{dot(q, f.u), dot(q, f.v)};
  r.boundary_distance = std::numeric_limits<double>::infinity();
  for (const auto& ring : f.rings)
    for (std::size_t i = 0; i < ring.size(); ++i)
      r.boundary_distance =
          std::min(r.boundary_distance, point_segment_distance(p2, ring[i], ring[(i + 1) % ring.size()]));
  r.inside = inside_even_odd(f.rings, p2);
  return r;
}

// One face against the sight segment eye→p. `near_l` is the distance along the ray where the near plane
// lies (occluders before it are clipped away) and `near_band` its tolerance band, both in world units.
RayCaster::Hit RayCaster::test_face(const FaceRecord& f, Point3 eye, Point3 p, double near_l,
                                    double near_band, std::string* why) const {
  const double sp = dot(f.n, to_vector(p)) + f.d;
  if (std::abs(sp) <= on_plane_) return Hit::None;  // p on this plane: a line crosses a plane only once
  const double se = dot(f.n, to_vector(eye)) + f.d;
  const Vector3 ray = p - eye;
  const double len = length(ray);
  const Vector3 dir = ray / len;
  const double lo_lim = near_l - near_band, hi_lim = len - tol_;
  if (hi_lim <= lo_lim) return Hit::None;
  // The ray points within tol of the plane: the band [l* − w, l* + w], or all or nothing when parallel.
  const double rate = (sp - se) / len;
  double band_lo, band_hi;
  if (rate == 0) {
    if (std::abs(se) > tol_) return Hit::None;
    band_lo = lo_lim;
    band_hi = hi_lim;
  } else {
    const double l_star = -se / rate, w = tol_ / std::abs(rate);
    band_lo = l_star - w;
    band_hi = l_star + w;
  }
  const double j_lo = std::max(band_lo, lo_lim), j_hi = std::min(band_hi, hi_lim);
  if (j_lo > j_hi) return Hit::None;
  const Point3 x0 = eye + j_lo * dir, x1 = eye + j_hi * dir;
  if (std::max(x0.x, x1.x) < f.lo.x || std::min(x0.x, x1.x) > f.hi.x || std::max(x0.y, x1.y) < f.lo.y ||
      std::min(x0.y, x1.y) > f.hi.y || std::max(x0.z, x1.z) < f.lo.z || std::min(x0.z, x1.z) > f.hi.z)
    return Hit::None;
  const Vector3 q0 = x0 - f.origin, q1 = x1 - f.origin;
  const Point2 a{dot(q0, f.u), dot(q0, f.v)}, b{dot(q1, f.u), dot(q1, f.v)};
  double dmin = std::numeric_limits<double>::infinity();
  for (const auto& ring : f.rings)
    for (std::size_t i = 0; i < ring.size(); ++i)
      dmin = std::min(dmin, segment_distance(a, b, ring[i], ring[(i + 1) % ring.size()]));
  auto explain = [&](const char* what) {
    if (!why) return;
    std::ostringstream m;
    m << what << " (object " << f.object << " face " << f.face << ": crossing at " << 0.5 * (j_lo + j_hi)
      << " of " << len << " along the ray, eye/point plane distances " << se << "/" << sp
      << ", distance to the face boundary " << dmin << ", tol " << tol_ << ")";
    *why = m.str();
  };
  if (dmin <= tol_) {
    explain("ray passes within tol of a face boundary");
    return Hit::Ambiguous;
  }
  if (!inside_even_odd(f.rings, a)) return Hit::None;
  // Clearly inside the polygon: a hiding crossing if it is transversal and clear of both range ends.
  const bool transversal = std::abs(se) > tol_ && std::abs(sp) > tol_ && ((se > 0) != (sp > 0));
  const bool clear = band_lo > near_l + near_band && band_hi < len - tol_;
  if (transversal && clear) {
    explain("hidden by a face");
    return Hit::Hidden;
  }
  explain("crossing within tol of the point, the near plane or a grazing plane");
  return Hit::Ambiguous;
}

std::optional<RayCaster::SightLine> RayCaster::sight_line(Point3 p, Verdict& verdict) const {
  SightLine line;
  if (camera_.projection == Projection::Perspective) {
    // World distance from p to the near plane is (depth − near)/|∇depth|.
    const double g = length(camera_.viewFromWorld.row(2));
    const double depth = camera_.view(p).z;
    if (depth < camera_.near_depth - tol_ * g) {
      verdict.visibility = Visibility::Hidden;
      verdict.reason = "in front of the near plane (depth " + std::to_string(depth) + ")";
      return std::nullopt;
    }
    if (depth <= camera_.near_depth + tol_ * g) {
      verdict.visibility = Visibility::Ambiguous;
      verdict.reason = "within tol of the near plane";
      return std::nullopt;
    }
    line.eye = camera_.eye_world();
    const double len = distance(line.eye, p);
    line.near_l = len * camera_.near_depth / depth;
    line.near_band = tol_ * g * len / depth;
  } else {
    // Orthographic: start far enough out along −direction that every face lies ahead of the start.
    const double far = 4 * (extent_ + distance(p, center_));
    line.eye = p - far * camera_.direction_world();
  }
  return line;
}

Verdict RayCaster::classify(Point3 p) const { return classify(p, 0xffffffffu, {}); }

Verdict RayCaster::classify(Point3 p, std::uint32_t object, const std::vector<std::uint32_t>& ignore) const {
  Verdict verdict;
  const std::optional<SightLine> line = sight_line(p, verdict);
  if (!line) return verdict;
  bool ambiguous = false;
  for (const FaceRecord& f : faces_) {
    if (f.object == object && std::find(ignore.begin(), ignore.end(), f.face) != ignore.end()) continue;
    std::string why;
    const Hit h = test_face(f, line->eye, p, line->near_l, line->near_band, &why);
    if (h == Hit::Hidden) {
      verdict.visibility = Visibility::Hidden;
      verdict.object = static_cast<int>(f.object);
      verdict.face = static_cast<int>(f.face);
      verdict.reason = why;
      return verdict;
    }
    if (h == Hit::Ambiguous && !ambiguous) {
      ambiguous = true;
      verdict.object = static_cast<int>(f.object);
      verdict.face = static_cast<int>(f.face);
      verdict.reason = why;
    }
  }
  verdict.visibility = ambiguous ? Visibility::Ambiguous : Visibility::Visible;
  return verdict;
}

std::optional<int> RayCaster::surfaces_in_front(Point3 p) const {
  Verdict verdict;
  const std::optional<SightLine> line = sight_line(p, verdict);
  if (!line) return std::nullopt;  // at or before the near plane: no count to give
  int count = 0;
  for (const FaceRecord& f : faces_) {
    const Hit h = test_face(f, line->eye, p, line->near_l, line->near_band, nullptr);
    if (h == Hit::Ambiguous) return std::nullopt;
    count += h == Hit::Hidden;
  }
  return count;
}

}  // namespace hlr::test
