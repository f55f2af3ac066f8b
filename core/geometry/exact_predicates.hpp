// Orientation predicates that are never wrong: the sign of a determinant of input coordinates, computed in
// floating point with a certified error bound, and exactly (GMP rationals, which hold every double
// exactly) when the bound cannot tell the sign. No tolerance is involved: a zero means exactly coplanar
// (collinear). The bounds are Shewchuk's (1997) for this order of evaluation, rounded up; the exact path
// is taken only where they fail, so the cost on ordinary data is that of the floating-point formula.
#pragma once

#include "core/geometry/vector.hpp"

namespace hlr {

// Sign of ((b − a) × (c − a)) · (d − a): +1 when d lies on the side the normal of the triangle a, b, c
// (counter-clockwise) points to, −1 on the other side, 0 when the four points are coplanar.
int orient3d(Point3 a, Point3 b, Point3 c, Point3 d);

// Sign of (b − a) × (c − a): +1 when a, b, c turn counter-clockwise, −1 clockwise, 0 when collinear.
int orient2d(Point2 a, Point2 b, Point2 c);

// The same determinant of orient3d, its floating-point value (for constructions whose topology the sign
// already decided: the value is within Shewchuk's bound of the exact one).
double orient3d_value(Point3 a, Point3 b, Point3 c, Point3 d);

// orient3d(a, b, c, p) for the point p = p0 + t·(p1 − p0) of a segment, exactly: p is not rounded.
int orient3d_along(Point3 a, Point3 b, Point3 c, Point3 p0, Point3 p1, double t);
// The same with the plane through a and b along direction dir: sign of ((b − a) × dir) · (p − a).
int orient3d_along_direction(Point3 a, Point3 b, Vector3 dir, Point3 p0, Point3 p1, double t);

// Where segment p→q crosses the plane of a, b, c: the parameter t of p + t·(q − p), computed exactly and
// rounded, when p and q lie strictly on opposite sides (else 0 if p is on the plane, 1 otherwise).
double plane_crossing(Point3 a, Point3 b, Point3 c, Point3 p, Point3 q);
// The same for the plane through a and b along direction dir.
double plane_crossing_along_direction(Point3 a, Point3 b, Vector3 dir, Point3 p, Point3 q);

}  // namespace hlr
