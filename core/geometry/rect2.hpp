// Axis-aligned rectangle in the picture plane.
#pragma once

#include <algorithm>

#include "core/geometry/vector.hpp"

namespace hlr {

struct Rect2 {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
  bool contains(Point2 p) const { return p.x >= xmin && p.x <= xmax && p.y >= ymin && p.y <= ymax; }
  bool empty() const { return !(xmin <= xmax && ymin <= ymax); }
  double width() const { return xmax - xmin; }
  double height() const { return ymax - ymin; }
  bool overlaps(const Rect2& o) const { return xmin <= o.xmax && o.xmin <= xmax && ymin <= o.ymax && o.ymin <= ymax; }
  void include(Point2 p) {
    xmin = std::min(xmin, p.x);
    ymin = std::min(ymin, p.y);
    xmax = std::max(xmax, p.x);
    ymax = std::max(ymax, p.y);
  }
  // The empty rectangle that include() grows from.
  static Rect2 none() { return {1e300, 1e300, -1e300, -1e300}; }
};

}  // namespace hlr
