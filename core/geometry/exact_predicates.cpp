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

namespace {

// Where the determinant, affine in its last point, changes sign along p + t·(q − p): dp / (dp − dq).
double crossing_of(const mpq_class& dp, const mpq_class& dq) {
  if (sgn(dp) * sgn(dq) >= 0) return sgn(dp) == 0 ? 0.0 : 1.0;
  const mpq_class t = dp / (dp - dq);
  return t.get_d();
}

mpq_class along_direction_rational(Point3 a, Point3 b, Vector3 dir, Point3 p) {
  const mpq_class ax(a.x), ay(a.y), az(a.z);
  const mpq_class bx = mpq_class(b.x) - ax, by = mpq_class(b.y) - ay, bz = mpq_class(b.z) - az;
  const mpq_class cx(dir.x), cy(dir.y), cz(dir.z);
  const mpq_class dx = mpq_class(p.x) - ax, dy = mpq_class(p.y) - ay, dz = mpq_class(p.z) - az;
  return dx * (by * cz - bz * cy) + dy * (bz * cx - bx * cz) + dz * (bx * cy - by * cx);
}

}  // namespace

double plane_crossing(Point3 a, Point3 b, Point3 c, Point3 p, Point3 q) {
  return crossing_of(orient3d_rational(a, b, c, p), orient3d_rational(a, b, c, q));
}

double plane_crossing_along_direction(Point3 a, Point3 b, Vector3 dir, Point3 p, Point3 q) {
  return crossing_of(along_direction_rational(a, b, dir, p), along_direction_rational(a, b, dir, q));
}

namespace {

// Sign of det[b − a; w; p0 + t·(p1 − p0) − a], w = c − a or a direction. In doubles first, against a bound
// of 32ε times the determinant's permanent taken over the rows' inputs' magnitudes (each entry's rounding is
// within a few ε of those; 32ε covers the whole evaluation with room), then in rationals.
int sign_along(Point3 a, Point3 b, const Point3* c, Vector3 dir, Point3 p0, Point3 p1, double t) {
  const double r1[3] = {b.x - a.x, b.y - a.y, b.z - a.z};
  const double m1[3] = {std::abs(b.x) + std::abs(a.x), std::abs(b.y) + std::abs(a.y),
                        std::abs(b.z) + std::abs(a.z)};
  double r2[3], m2[3];
  if (c) {
    r2[0] = c->x - a.x, r2[1] = c->y - a.y, r2[2] = c->z - a.z;
    m2[0] = std::abs(c->x) + std::abs(a.x), m2[1] = std::abs(c->y) + std::abs(a.y);
    m2[2] = std::abs(c->z) + std::abs(a.z);
  } else {
    r2[0] = dir.x, r2[1] = dir.y, r2[2] = dir.z;
    m2[0] = std::abs(dir.x), m2[1] = std::abs(dir.y), m2[2] = std::abs(dir.z);
  }
  const double at = std::abs(t);
  const double r3[3] = {p0.x + t * (p1.x - p0.x) - a.x, p0.y + t * (p1.y - p0.y) - a.y,
                        p0.z + t * (p1.z - p0.z) - a.z};
  const double m3[3] = {std::abs(p0.x) + at * (std::abs(p1.x) + std::abs(p0.x)) + std::abs(a.x),
                        std::abs(p0.y) + at * (std::abs(p1.y) + std::abs(p0.y)) + std::abs(a.y),
                        std::abs(p0.z) + at * (std::abs(p1.z) + std::abs(p0.z)) + std::abs(a.z)};
  const double det = r3[0] * (r1[1] * r2[2] - r1[2] * r2[1]) + r3[1] * (r1[2] * r2[0] - r1[0] * r2[2]) +
                     r3[2] * (r1[0] * r2[1] - r1[1] * r2[0]);
  const double permanent = m3[0] * (m1[1] * m2[2] + m1[2] * m2[1]) + m3[1] * (m1[2] * m2[0] + m1[0] * m2[2]) +
                           m3[2] * (m1[0] * m2[1] + m1[1] * m2[0]);
  if (permanent > kUnderflow && std::isfinite(permanent)) {
    const double bound = 32 * kEpsilon * permanent;
    if (det > bound) return 1;
    if (det < -bound) return -1;
  }
  const mpq_class ax(a.x), ay(a.y), az(a.z), q(t);
  const mpq_class bx = mpq_class(b.x) - ax, by = mpq_class(b.y) - ay, bz = mpq_class(b.z) - az;
  const mpq_class cx = c ? mpq_class(c->x) - ax : mpq_class(dir.x),
                  cy = c ? mpq_class(c->y) - ay : mpq_class(dir.y),
                  cz = c ? mpq_class(c->z) - az : mpq_class(dir.z);
  const mpq_class px(p0.x), py(p0.y), pz(p0.z);
  const mpq_class dx = px + q * (mpq_class(p1.x) - px) - ax, dy = py + q * (mpq_class(p1.y) - py) - ay,
                  dz = pz + q * (mpq_class(p1.z) - pz) - az;
  return sgn(mpq_class(dx * (by * cz - bz * cy) + dy * (bz * cx - bx * cz) + dz * (bx * cy - by * cx)));
}

}  // namespace

int orient3d_along(Point3 a, Point3 b, Point3 c, Point3 p0, Point3 p1, double t) {
  return sign_along(a, b, &c, {}, p0, p1, t);
}

int orient3d_along_direction(Point3 a, Point3 b, Vector3 dir, Point3 p0, Point3 p1, double t) {
  return sign_along(a, b, nullptr, dir, p0, p1, t);
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
