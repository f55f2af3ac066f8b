// Random numbers for seeded tests: uniform in [a, b) from mt19937's raw output, whose sequence the
// standard fixes (the <random> distributions' algorithms are implementation-defined, which would make
// seeds unportable).
#pragma once

#include <random>

#include "core/geometry/vector.hpp"

namespace hlr::test {

struct Rng {
  std::mt19937 engine;
  explicit Rng(unsigned seed) : engine(seed) {}
  double operator()(double a, double b) {
    return a + (b - a) * (static_cast<double>(engine()) / 4294967296.0);
  }
  int integer(int lo, int hi) { return lo + static_cast<int>(engine() % static_cast<unsigned>(hi - lo + 1)); }
  Point3 point(Point3 lo, Point3 hi) {
    return {(*this)(lo.x, hi.x), (*this)(lo.y, hi.y), (*this)(lo.z, hi.z)};
  }
  // A unit vector, from points drawn in the cube until one falls in the shell 0.2 < |v| ≤ 1.
  Vector3 direction() {
    for (;;) {
      const Vector3 v{(*this)(-1, 1), (*this)(-1, 1), (*this)(-1, 1)};
      if (length(v) > 0.2 && length(v) <= 1) return normalize(v);
    }
  }
};

}  // namespace hlr::test
