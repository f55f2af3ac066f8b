// sweep(): a 2-D profile swept along a polyline with mitred joints. Each segment is a prism of the
// profile cut by the planes bisecting the corners at its ends. The profile's frame is carried from one
// segment to the next by the minimal rotation turning one direction into the other (parallel transport);
// with exactly that frame the two prisms meeting at a corner cut the bisecting plane in the same polygon,
// so the sections are shared and every side face is a planar quad (two parallel edges along the
// segment). Proof sketch: in the plane of the two directions, a profile point at height c above the
// first segment's axis and its rotated image both meet the bisector at (−c·tan(α/2), c).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "core/format_number.hpp"
#include "core/tolerance.hpp"
#include "stdlib/generator_detail.hpp"
#include "stdlib/generators.hpp"
#include "stdlib/shapes.hpp"

namespace hlr::stdlib {

using detail::require;

namespace {

// The rotation about a × b taking unit vector a to unit vector b, applied to v (Rodrigues' formula in
// the form without trigonometry; a · b > −1).
Vector3 rotate_between(Vector3 v, Vector3 a, Vector3 b) {
  const Vector3 w = cross(a, b);
  const double c = dot(a, b);
  return c * v + cross(w, v) + (dot(w, v) / (1 + c)) * w;
}

// The profile's axes for a segment with unit direction t: X × Y = t.
struct Frame {
  Vector3 x, y;
};

// Re-orthonormalises against t, so rounding does not accumulate along long paths.
Frame orthonormal(Vector3 x, Vector3 t) {
  const Vector3 u = normalize(x - dot(x, t) * t);
  return {u, cross(t, u)};
}

Frame initial_frame(Vector3 t) {
  Vector3 up{0, 0, 1};
  // A vertical start keeps the profile's x–y.
  if (length(up - dot(up, t) * t) < Tolerance::kSweepVertical) up = {0, 1, 0};
  const Vector3 y = normalize(up - dot(up, t) * t);
  return {cross(y, t), y};
}

}  // namespace

Solid sweep(const std::vector<Point2>& profile_in, const std::vector<Point3>& path_in,
            double crease_angle_deg) {
  const char* fn = "sweep";
  require(std::isfinite(crease_angle_deg) && crease_angle_deg >= 0 && crease_angle_deg <= 180, fn,
          "crease must lie in [0, 180]");
  std::vector<Point2> profile = profile_in;
  if (profile.size() > 3 && profile.front() == profile.back()) profile.pop_back();
  require(profile.size() >= 3, fn, "profile needs at least 3 points");
  for (const Point2& q : profile)
    require(std::isfinite(q.x) && std::isfinite(q.y), fn, "profile points must be finite");
  if (const auto defect = find_ring_defect({profile}))
    require(false, fn, describe_ring_defect(*defect, {"profile"}, {profile}));
  // Counter-clockwise in (x, y), hence counter-clockwise seen from ahead along the path.
  if (detail::signed_area2(profile) < 0) std::reverse(profile.begin(), profile.end());
  double profile_size = 0;
  for (const Point2& q : profile)
    for (const Point2& r : profile) profile_size = std::max(profile_size, distance(q, r));

  std::vector<Point3> path = path_in;
  for (const Point3& q : path) require(is_finite(q), fn, "path points must be finite");
  const bool closed = path.size() > 2 && path.front() == path.back();
  if (closed) path.pop_back();
  require(path.size() >= (closed ? 3u : 2u), fn,
          closed ? "a closed path needs at least 3 distinct points" : "path needs at least 2 points");
  const std::size_t m = path.size(), segments = closed ? m : m - 1;
  double extent = profile_size;
  for (const Point3& q : path) extent = std::max({extent, std::abs(q.x), std::abs(q.y), std::abs(q.z)});
  // Far from the origin a tiny profile's corners would merge into one vertex.
  require(profile_size > Tolerance::kGeneratorFeature * extent, fn,
          "profile is too small next to the path's coordinates");

  std::vector<Vector3> t(segments);
  for (std::size_t i = 0; i < segments; ++i) {
    const Vector3 d = path[(i + 1) % m] - path[i];
    require(length(d) > 10 * Tolerance::kRelative * extent, fn,
            "path has a zero-length segment at point " + std::to_string(i));
    t[i] = normalize(d);
  }
  // Joint j joins segment j − 1 to segment j (all joints of a closed path, the inner ones otherwise).
  auto incoming = [&](std::size_t j) { return (j + segments - 1) % segments; };
  for (std::size_t j = closed ? 0 : 1; j < (closed ? m : m - 1); ++j)
    require(dot(t[incoming(j)], t[j]) > -1 + Tolerance::kSweepReversal, fn,
            "path reverses at point " + std::to_string(j));

  std::vector<Frame> frames = {initial_frame(t[0])};
  for (std::size_t i = 1; i < segments; ++i)
    frames.push_back(orthonormal(rotate_between(frames[i - 1].x, t[i - 1], t[i]), t[i]));
  if (closed) {
    // Round the loop the frame must come back to itself, or the last section would not match the first.
    const Vector3 back = orthonormal(rotate_between(frames.back().x, t.back(), t[0]), t[0]).x;
    const double twist = std::atan2(dot(cross(frames[0].x, back), t[0]), dot(frames[0].x, back));
    require(std::abs(twist) < Tolerance::kSweepTwist, fn,
            "path is closed but twists the profile by " + format_for_message(twist * 180 / std::numbers::pi) +
                "\u00b0 round the loop (it is not planar), so no mitred ring with flat faces exists; use an "
                "open path or a planar closed one");
  }

  // Section at joint j: the profile in the frame of the segment leaving j (of the one arriving, at the end
  // of an open path), moved within its segment's prism onto the plane bisecting the corner.
  const std::size_t n = profile.size();
  std::vector<Point3> vertices;
  for (std::size_t j = 0; j < m; ++j) {
    const bool end = !closed && j == m - 1, corner = closed || (j > 0 && !end);
    const std::size_t s = end ? segments - 1 : j;
    const Vector3 mitre = corner ? t[incoming(j)] + t[j] : t[s];
    for (const Point2& q : profile) {
      const Vector3 o = q.x * frames[s].x + q.y * frames[s].y;
      vertices.push_back(path[j] + o - (dot(o, mitre) / dot(t[s], mitre)) * t[s]);
    }
  }
  // Each lateral line must run forward between its segment's two sections, else the mitres cross.
  for (std::size_t i = 0; i < segments; ++i) {
    const std::size_t next = (i + 1) % m;
    for (std::size_t k = 0; k < n; ++k) {
      const double from = dot(vertices[i * n + k] - path[i], t[i]);
      const double to = dot(vertices[next * n + k] - path[i], t[i]);
      require(to - from > Tolerance::kSweepMitre * profile_size, fn,
              "path segment " + std::to_string(i) + "\u2013" + std::to_string(next) +
                  " is too short for the profile at its corners: the mitred ends would cross");
    }
  }

  auto id = [n](std::size_t joint, std::size_t k) { return static_cast<std::uint32_t>(joint * n + k % n); };
  std::vector<IndexedFace> faces;
  for (std::size_t i = 0; i < segments; ++i)
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t next = (i + 1) % m;
      faces.push_back(IndexedFace{{id(i, k), id(i, k + 1), id(next, k + 1), id(next, k)}});
    }
  if (!closed) {
    IndexedFace start(1), finish(1);
    for (std::size_t k = 0; k < n; ++k) {
      start[0].push_back(id(0, n - 1 - k));  // faces back along the path
      finish[0].push_back(id(m - 1, k));
    }
    faces.push_back(std::move(start));
    faces.push_back(std::move(finish));
  }
  return solid_from_indexed(vertices, faces, crease_angle_deg);
}

}  // namespace hlr::stdlib
