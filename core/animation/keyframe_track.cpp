#include "core/animation/keyframe_track.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/tolerance.hpp"

namespace hlr {

namespace {

// Cubic Hermite between (p0, m0) and (p1, m1) over a stretch of length h, at s in [0, 1].
Vector3 hermite(Vector3 p0, Vector3 m0, Vector3 p1, Vector3 m1, double h, double s) {
  const double s2 = s * s, s3 = s2 * s;
  return p0 * (2 * s3 - 3 * s2 + 1) + m0 * (h * (s3 - 2 * s2 + s)) + p1 * (-2 * s3 + 3 * s2) +
         m1 * (h * (s3 - s2));
}

// Catmull-Rom tangents for uneven spacing: the slope across the neighbours; one-sided at the ends.
Vector3 catmull_rom_tangent(const std::vector<Keyframe>& k, std::size_t i) {
  const std::size_t n = k.size();
  if (n < 2) return {};
  const std::size_t a = i == 0 ? 0 : i - 1, b = i + 1 == n ? n - 1 : i + 1;
  return (k[b].value - k[a].value) / (k[b].time - k[a].time);
}

// The natural spline's second derivatives at the keys (zero at both ends): the tridiagonal system
// h[i−1]·M[i−1] + 2(h[i−1] + h[i])·M[i] + h[i]·M[i+1] = 6·(slope[i] − slope[i−1]), by elimination.
std::vector<Vector3> natural_second_derivatives(const std::vector<Keyframe>& k) {
  const std::size_t n = k.size();
  std::vector<Vector3> m(n);
  if (n < 3) return m;
  std::vector<double> diag(n), upper(n);
  std::vector<Vector3> rhs(n);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double h0 = k[i].time - k[i - 1].time, h1 = k[i + 1].time - k[i].time;
    diag[i] = 2 * (h0 + h1);
    upper[i] = h1;
    rhs[i] = ((k[i + 1].value - k[i].value) / h1 - (k[i].value - k[i - 1].value) / h0) * 6;
    if (i > 1) {  // eliminate the sub-diagonal h0
      const double f = h0 / diag[i - 1];
      diag[i] -= f * upper[i - 1];
      rhs[i] = rhs[i] - rhs[i - 1] * f;
    }
  }
  for (std::size_t i = n - 2; i >= 1; --i) {
    m[i] = (rhs[i] - m[i + 1] * upper[i]) / diag[i];
    if (i == 1) break;
  }
  return m;
}

std::vector<Keyframe> evenly_spaced(const std::vector<Point3>& points) {
  std::vector<Keyframe> keys;
  keys.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    keys.push_back({static_cast<double>(i), to_vector(points[i]), Easing::Linear});
  return keys;
}

}  // namespace

void check_keys(const std::vector<Keyframe>& keys) {
  if (keys.empty()) throw std::invalid_argument("a track needs at least one key");
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const Vector3& v = keys[i].value;
    if (!std::isfinite(keys[i].time) || !std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw std::invalid_argument("key " + std::to_string(i) + " is not finite");
    if (i > 0 && !(keys[i].time > keys[i - 1].time))
      throw std::invalid_argument("key " + std::to_string(i) + " must come after key " +
                                  std::to_string(i - 1) + ": key times increase");
  }
}

Vector3 evaluate_track(const std::vector<Keyframe>& keys, TrackCurve curve, double at) {
  if (at <= keys.front().time || keys.size() == 1) return keys.front().value;
  if (at >= keys.back().time) return keys.back().value;
  // The stretch [key i, key i + 1) holding `at`.
  const auto next =
      std::upper_bound(keys.begin(), keys.end(), at, [](double a, const Keyframe& k) { return a < k.time; });
  const std::size_t i = static_cast<std::size_t>(next - keys.begin()) - 1;
  const Keyframe& a = keys[i];
  const Keyframe& b = keys[i + 1];
  const double h = b.time - a.time;
  const double s = ease(a.ease, (at - a.time) / h);
  switch (curve) {
    case TrackCurve::Eased:
      return a.value + (b.value - a.value) * s;
    case TrackCurve::CatmullRom:
      return hermite(a.value, catmull_rom_tangent(keys, i), b.value, catmull_rom_tangent(keys, i + 1), h, s);
    case TrackCurve::Natural: {
      const std::vector<Vector3> m = natural_second_derivatives(keys);
      const double x = s * h;  // time since key i
      const double before = h - x;
      return m[i] * (before * before * before / (6 * h)) + m[i + 1] * (x * x * x / (6 * h)) +
             (a.value / h - m[i] * (h / 6)) * before + (b.value / h - m[i + 1] * (h / 6)) * x;
    }
  }
  return a.value;
}

Vector3 path_point(const std::vector<Point3>& points, TrackCurve curve, double u) {
  const double last = static_cast<double>(points.size() - 1);
  return evaluate_track(evenly_spaced(points), curve, std::clamp(u, 0.0, 1.0) * last);
}

Vector3 path_tangent(const std::vector<Point3>& points, TrackCurve curve, double u) {
  if (points.size() < 2) return {};
  // A central difference inside, one-sided at the ends; the step is small against one stretch (1/(n − 1)).
  const double h = Tolerance::kPathTangentStep / static_cast<double>(points.size() - 1);
  const double lo = std::max(0.0, u - h), hi = std::min(1.0, u + h);
  return (path_point(points, curve, hi) - path_point(points, curve, lo)) / (hi - lo);
}

}  // namespace hlr
