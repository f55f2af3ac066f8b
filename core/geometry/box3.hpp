// An axis-aligned box in 3-D, grown point by point: the broad phase of face crossings (between solids
// and within one) compares the boxes of faces and solids.
#pragma once

#include <algorithm>

#include "core/geometry/vector.hpp"

namespace hlr {

struct Box3 {
  Point3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};  // empty until a point is included

  void include(Point3 p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  // Overlap, the boxes grown by `tol` (touching counts).
  bool overlaps(const Box3& o, double tol) const {
    return lo.x <= o.hi.x + tol && o.lo.x <= hi.x + tol && lo.y <= o.hi.y + tol && o.lo.y <= hi.y + tol &&
           lo.z <= o.hi.z + tol && o.lo.z <= hi.z + tol;
  }
  double largest_side() const { return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}); }
};

}  // namespace hlr
