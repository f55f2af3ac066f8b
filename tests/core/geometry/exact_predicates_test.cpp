// The orientation predicates against an independent exact computation: coordinates that are whole
// multiples of a power of two, so that scaled to integers the determinant is computed exactly in 128-bit
// integer arithmetic here. Near-degenerate sets — points a few units in the last place off a line or a
// plane — are where plain floating point gets the sign wrong; the test counts such cases, so it is known
// to reach the exact path.
//   hlr_core_tests --gtest_filter='ExactPredicates*'
#include "core/geometry/exact_predicates.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "tests/support/seeded_rng.hpp"

namespace hlr::test {
namespace {

__extension__ typedef __int128 Int;  // a GNU extension (GCC, clang): exact here

int sign(Int v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

// A coordinate k·2^-s as a double (exact for |k| < 2^53).
double fixed(std::int64_t k, int s) { return std::ldexp(static_cast<double>(k), -s); }

int exact_orient2d(const std::int64_t (&p)[3][2]) {
  const Int bx = p[1][0] - p[0][0], by = p[1][1] - p[0][1];
  const Int cx = p[2][0] - p[0][0], cy = p[2][1] - p[0][1];
  return sign(bx * cy - by * cx);
}

int exact_orient3d(const std::int64_t (&p)[4][3]) {
  Int d[3][3];
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) d[r][k] = p[r + 1][k] - p[0][k];
  // rows: b − a, c − a, d − a; the sign of ((b − a) × (c − a)) · (d − a).
  const Int cx = d[0][1] * d[1][2] - d[0][2] * d[1][1];
  const Int cy = d[0][2] * d[1][0] - d[0][0] * d[1][2];
  const Int cz = d[0][0] * d[1][1] - d[0][1] * d[1][0];
  return sign(cx * d[2][0] + cy * d[2][1] + cz * d[2][2]);
}

int naive_sign(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

// Points on the line y = x near (0.5, 0.5), each moved by a few units of 2^-53: Kettner et al.'s
// classic failure of floating-point orientation ("Classroom examples of robustness problems").
TEST(ExactPredicates, Orient2dNearACollinearTriple) {
  constexpr int kShift = 53;
  const std::int64_t half = std::int64_t{1} << 52;  // 0.5 in units of 2^-53
  int checked = 0, naive_wrong = 0;
  for (int i = -16; i <= 16; ++i)
    for (int j = -16; j <= 16; ++j) {
      const std::int64_t p[3][2] = {
          {half + i, half + j}, {24 * (half * 2), 24 * (half * 2)}, {12 * (half * 2), 12 * (half * 2)}};
      const Point2 a{fixed(p[0][0], kShift), fixed(p[0][1], kShift)};
      const Point2 b{fixed(p[1][0], kShift), fixed(p[1][1], kShift)};
      const Point2 c{fixed(p[2][0], kShift), fixed(p[2][1], kShift)};
      const int expected = exact_orient2d(p);
      ASSERT_EQ(orient2d(a, b, c), expected) << "i " << i << " j " << j;
      // Its symmetries: a cyclic turn keeps the sign, a swap flips it.
      ASSERT_EQ(orient2d(b, c, a), expected);
      ASSERT_EQ(orient2d(b, a, c), -expected);
      const double naive = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
      naive_wrong += naive_sign(naive) != expected;
      ++checked;
    }
  EXPECT_EQ(checked, 33 * 33);
  EXPECT_GT(naive_wrong, 0) << "no case needed the exact path; the test would not notice its loss";
}

// Random points on planes through the origin with whole coefficients, moved off the plane by 0, ±1 or
// ±2 units of the grid (2^-40 of the coordinates' size): the sign of each, exactly.
TEST(ExactPredicates, Orient3dNearCoplanarPoints) {
  Rng rng(20261206);
  constexpr int kShift = 40;
  int naive_wrong = 0, zeros = 0;
  for (int n = 0; n < 20000; ++n) {
    // Plane z = u·x + v·y with small whole u, v, and points on it with coordinates up to 2^40 units.
    const std::int64_t u = rng.integer(-3, 3), v = rng.integer(-3, 3);
    std::int64_t p[4][3];
    for (auto& q : p) {
      q[0] = static_cast<std::int64_t>(rng(-1, 1) * 0x1p38);
      q[1] = static_cast<std::int64_t>(rng(-1, 1) * 0x1p38);
      q[2] = u * q[0] + v * q[1];
    }
    p[3][2] += rng.integer(-2, 2);
    Point3 pt[4];
    for (int k = 0; k < 4; ++k)
      pt[k] = {fixed(p[k][0], kShift), fixed(p[k][1], kShift), fixed(p[k][2], kShift)};
    const int expected = exact_orient3d(p);
    ASSERT_EQ(orient3d(pt[0], pt[1], pt[2], pt[3]), expected) << "case " << n;
    ASSERT_EQ(orient3d(pt[1], pt[2], pt[0], pt[3]), expected);  // a cyclic turn of the triangle
    ASSERT_EQ(orient3d(pt[1], pt[0], pt[2], pt[3]), -expected);
    naive_wrong += naive_sign(orient3d_value(pt[0], pt[1], pt[2], pt[3])) != expected;
    zeros += expected == 0;
  }
  EXPECT_GT(zeros, 1000);  // exactly coplanar sets are decided as such
  EXPECT_GT(naive_wrong, 0) << "no case needed the exact path; the test would not notice its loss";
}

// Far from degenerate, the floating-point value decides, and agrees with the exact sign.
TEST(ExactPredicates, OrdinaryPointsAgreeWithTheValue) {
  Rng rng(7);
  for (int n = 0; n < 1000; ++n) {
    const Point3 a = rng.point({-1, -1, -1}, {1, 1, 1}), b = rng.point({-1, -1, -1}, {1, 1, 1});
    const Point3 c = rng.point({-1, -1, -1}, {1, 1, 1}), d = rng.point({-1, -1, -1}, {1, 1, 1});
    const double value = orient3d_value(a, b, c, d);
    if (std::abs(value) < 1e-6) continue;
    EXPECT_EQ(orient3d(a, b, c, d), value > 0 ? 1 : -1);
  }
}

}  // namespace
}  // namespace hlr::test
