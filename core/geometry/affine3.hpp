// Affine map of 3-space: p' = M p + t (column-vector convention). Names follow pbrt's aFromB:
// `viewFromWorld.apply(p)` takes a world point to view coordinates; `a.then(b)` applies a, then b.
#pragma once

#include <array>

#include "core/geometry/vector.hpp"

namespace hlr {

struct Affine3 {
  // m[row][col]; identity by default.
  std::array<std::array<double, 3>, 3> m{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  Vector3 t{};

  static Affine3 identity() { return {}; }
  static Affine3 translation(Vector3 d) {
    Affine3 a;
    a.t = d;
    return a;
  }
  static Affine3 scaling(double sx, double sy, double sz) {
    Affine3 a;
    a.m = {{{sx, 0, 0}, {0, sy, 0}, {0, 0, sz}}};
    return a;
  }
  // Right-handed rotation by `radians` about the unit axis through the origin.
  static Affine3 rotation(Vector3 axis, double radians);
  // Rows of a 3x3 matrix given as column-vector linear part.
  static Affine3 from_rows(Vector3 r0, Vector3 r1, Vector3 r2, Vector3 translation = {}) {
    Affine3 a;
    a.m = {{{r0.x, r0.y, r0.z}, {r1.x, r1.y, r1.z}, {r2.x, r2.y, r2.z}}};
    a.t = translation;
    return a;
  }

  Point3 apply(Point3 p) const {
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + t.x,
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + t.y,
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + t.z};
  }
  Vector3 apply(Vector3 v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }
  Vector3 row(int i) const { return {m[i][0], m[i][1], m[i][2]}; }
  double determinant() const;
  // This map followed by `next`: (a.then(b)).apply(p) == b.apply(a.apply(p)).
  Affine3 then(const Affine3& next) const;
  // Throws std::domain_error when the linear part is singular.
  Affine3 inverse() const;
};

}  // namespace hlr
