#include "core/geometry/exact_predicates.hpp"

#include <gmpxx.h>

#include <cmath>

namespace hlr {
namespace {

constexpr double kEpsilon = 0x1p-53;  // unit round-off of a double
// Relative error bounds of the floating-point determinants below, times their permanent (the same
// expression with every product's absolute value): Shewchuk's o3derrboundA = (7 + 56ε)ε and
// ccwerrboundA = (3 + 16ε)ε, rounded up to 8ε and 4ε.
constexpr double kOrient3dBound = 8 * kEpsilon;
constexpr double kOrient2dBound = 4 * kEpsilon;
// Below this permanent the products may have underflowed, where the relative bound no longer holds.
constexpr double kUnderflow = 0x1p-900;

mpq_class orient3d_rational(Point3 a, Point3 b, Point3 c, Point3 d) {
  const mpq_class ax(a.x), ay(a.y), az(a.z);
  const mpq_class bx = mpq_class(b.x) - ax, by = mpq_class(b.y) - ay, bz = mpq_class(b.z) - az;
  const mpq_class cx = mpq_class(c.x) - ax, cy = mpq_class(c.y) - ay, cz = mpq_class(c.z) - az;
  const mpq_class dx = mpq_class(d.x) - ax, dy = mpq_class(d.y) - ay, dz = mpq_class(d.z) - az;
  return dx * (by * cz - bz * cy) + dy * (bz * cx - bx * cz) + dz * (bx * cy - by * cx);
}

int orient3d_exact(Point3 a, Point3 b, Point3 c, Point3 d) {
  const mpq_class det = orient3d_rational(a, b, c, d);
  return sgn(det);
}

int orient2d_exact(Point2 a, Point2 b, Point2 c) {
  const mpq_class ax(a.x), ay(a.y);
  const mpq_class det =
      (mpq_class(b.x) - ax) * (mpq_class(c.y) - ay) - (mpq_class(b.y) - ay) * (mpq_class(c.x) - ax);
  return sgn(det);
}

// The determinant of orient3d in floating point, and its permanent (the same sum of products, each
// product's absolute value) that scales the error bound.
struct Orient3dSum {
  double value, permanent;
};

Orient3dSum orient3d_sum(Point3 a, Point3 b, Point3 c, Point3 d) {
  const double bx = b.x - a.x, by = b.y - a.y, bz = b.z - a.z;
  const double cx = c.x - a.x, cy = c.y - a.y, cz = c.z - a.z;
  const double dx = d.x - a.x, dy = d.y - a.y, dz = d.z - a.z;
  return {dx * (by * cz - bz * cy) + dy * (bz * cx - bx * cz) + dz * (bx * cy - by * cx),
          std::abs(dx) * (std::abs(by * cz) + std::abs(bz * cy)) +
              std::abs(dy) * (std::abs(bz * cx) + std::abs(bx * cz)) +
              std::abs(dz) * (std::abs(bx * cy) + std::abs(by * cx))};
}

}  // namespace

double orient3d_value(Point3 a, Point3 b, Point3 c, Point3 d) { return orient3d_sum(a, b, c, d).value; }

int orient3d(Point3 a, Point3 b, Point3 c, Point3 d) {
  const auto [det, permanent] = orient3d_sum(a, b, c, d);
  if (permanent > kUnderflow && std::isfinite(permanent)) {
    const double bound = kOrient3dBound * permanent;
    if (det > bound) return 1;
    if (det < -bound) return -1;
  }
  return orient3d_exact(a, b, c, d);
}

double plane_crossing(Point3 a, Point3 b, Point3 c, Point3 p, Point3 q) {
  // The determinant is affine in its last point: along p + t·(q − p) it is (1 − t)·D(p) + t·D(q).
  const mpq_class dp = orient3d_rational(a, b, c, p), dq = orient3d_rational(a, b, c, q);
  if (sgn(dp) * sgn(dq) >= 0) return sgn(dp) == 0 ? 0.0 : 1.0;
  const mpq_class t = dp / (dp - dq);
  return t.get_d();
}

int orient2d(Point2 a, Point2 b, Point2 c) {
  const double left = (b.x - a.x) * (c.y - a.y), right = (b.y - a.y) * (c.x - a.x);
  const double det = left - right;
  const double permanent = std::abs(left) + std::abs(right);
  if (permanent > kUnderflow && std::isfinite(permanent)) {
    const double bound = kOrient2dBound * permanent;
    if (det > bound) return 1;
    if (det < -bound) return -1;
  }
  return orient2d_exact(a, b, c);
}

}  // namespace hlr
