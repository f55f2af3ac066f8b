// Points and vectors in 2-D and 3-D. Points and vectors are distinct types (pbrt): a point minus a point
// is a vector, a point plus a vector is a point, and two points cannot be added by accident.
#pragma once

#include <cmath>

namespace hlr {

struct Vector3 {
  double x = 0, y = 0, z = 0;
  constexpr Vector3() = default;
  constexpr Vector3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr Vector3 operator-() const { return {-x, -y, -z}; }
  constexpr Vector3& operator+=(const Vector3& v) { x += v.x; y += v.y; z += v.z; return *this; }
};

struct Point3 {
  double x = 0, y = 0, z = 0;
  constexpr Point3() = default;
  constexpr Point3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

struct Vector2 {
  double x = 0, y = 0;
  constexpr Vector2() = default;
  constexpr Vector2(double x_, double y_) : x(x_), y(y_) {}
};

struct Point2 {
  double x = 0, y = 0;
  constexpr Point2() = default;
  constexpr Point2(double x_, double y_) : x(x_), y(y_) {}
};

// 3-D
constexpr Vector3 operator+(Vector3 a, Vector3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr Vector3 operator-(Vector3 a, Vector3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr Vector3 operator*(double s, Vector3 v) { return {s * v.x, s * v.y, s * v.z}; }
constexpr Vector3 operator*(Vector3 v, double s) { return s * v; }
constexpr Vector3 operator/(Vector3 v, double s) { return {v.x / s, v.y / s, v.z / s}; }
constexpr Vector3 operator-(Point3 a, Point3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr Point3 operator+(Point3 p, Vector3 v) { return {p.x + v.x, p.y + v.y, p.z + v.z}; }
constexpr Point3 operator-(Point3 p, Vector3 v) { return {p.x - v.x, p.y - v.y, p.z - v.z}; }
constexpr bool operator==(Point3 a, Point3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
constexpr bool operator==(Vector3 a, Vector3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

constexpr double dot(Vector3 a, Vector3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vector3 cross(Vector3 a, Vector3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// std::fmax's result (a NaN loses to a number), inline: the library's fmax is a call.
constexpr double max_ignoring_nan(double a, double b) { return a > b || b != b ? a : b; }
// The largest |component|, NaN components ignored (NaN only if all are).
inline double largest_magnitude(Vector3 v) {
  return max_ignoring_nan(std::fabs(v.x), max_ignoring_nan(std::fabs(v.y), std::fabs(v.z)));
}
// Scaled by the largest component, so it neither overflows beyond 1e154 nor underflows below 1e-154.
inline double length(Vector3 v) {
  const double m = largest_magnitude(v);
  if (!(m > 0) || !std::isfinite(m)) return m;
  const Vector3 u{v.x / m, v.y / m, v.z / m};
  return m * std::sqrt(dot(u, u));
}
inline double distance(Point3 a, Point3 b) { return length(a - b); }
// Scaled by the largest component first, so vectors beyond 1e154 (whose squared length would overflow)
// or below 1e-154 (underflow) normalise too.
inline Vector3 normalize(Vector3 v) {
  const double m = largest_magnitude(v);
  if (!(m > 0) || !std::isfinite(m)) return Vector3{};
  const Vector3 u = v / m;
  return u / std::sqrt(dot(u, u));
}
constexpr Vector3 to_vector(Point3 p) { return {p.x, p.y, p.z}; }
constexpr Point3 to_point(Vector3 v) { return {v.x, v.y, v.z}; }
// Point on the segment a→b at parameter t (t=0 gives a, t=1 gives b).
constexpr Point3 lerp(Point3 a, Point3 b, double t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
}

// 2-D
constexpr Vector2 operator+(Vector2 a, Vector2 b) { return {a.x + b.x, a.y + b.y}; }
constexpr Vector2 operator-(Vector2 a, Vector2 b) { return {a.x - b.x, a.y - b.y}; }
constexpr Vector2 operator*(double s, Vector2 v) { return {s * v.x, s * v.y}; }
constexpr Vector2 operator-(Point2 a, Point2 b) { return {a.x - b.x, a.y - b.y}; }
constexpr Point2 operator+(Point2 p, Vector2 v) { return {p.x + v.x, p.y + v.y}; }
constexpr bool operator==(Point2 a, Point2 b) { return a.x == b.x && a.y == b.y; }
constexpr double dot(Vector2 a, Vector2 b) { return a.x * b.x + a.y * b.y; }
// z component of the 3-D cross product: twice the signed area of the triangle (0, a, b).
constexpr double cross(Vector2 a, Vector2 b) { return a.x * b.y - a.y * b.x; }
inline double length(Vector2 v) { return std::sqrt(dot(v, v)); }
inline double distance(Point2 a, Point2 b) { return length(a - b); }
constexpr Point2 lerp(Point2 a, Point2 b, double t) { return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; }

inline bool is_finite(Point3 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace hlr
