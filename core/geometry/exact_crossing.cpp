#include "core/geometry/exact_crossing.hpp"

#include <gmpxx.h>

#include <vector>

namespace hlr {
namespace {

struct Q3 {
  mpq_class x, y, z;
};

Q3 rational(Point3 p) { return {mpq_class(p.x), mpq_class(p.y), mpq_class(p.z)}; }
Q3 minus(const Q3& a, const Q3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Q3 cross(const Q3& u, const Q3& v) {
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}
mpq_class dot(const Q3& u, const Q3& v) { return u.x * v.x + u.y * v.y + u.z * v.z; }

// The points where triangle v meets the plane its corners' values s are taken against: corners on it, and
// the crossings of edges whose ends lie strictly on opposite sides.
std::vector<Q3> meet_plane(const Q3* v, const mpq_class* s) {
  std::vector<Q3> out;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (sgn(s[i]) == 0) out.push_back(v[i]);
    if (sgn(s[i]) * sgn(s[j]) < 0) {
      const mpq_class t = s[i] / (s[i] - s[j]);
      out.push_back(
          {v[i].x + t * (v[j].x - v[i].x), v[i].y + t * (v[j].y - v[i].y), v[i].z + t * (v[j].z - v[i].z)});
    }
  }
  return out;
}

bool one_side(const mpq_class* s) {
  return (sgn(s[0]) > 0 && sgn(s[1]) > 0 && sgn(s[2]) > 0) ||
         (sgn(s[0]) < 0 && sgn(s[1]) < 0 && sgn(s[2]) < 0);
}

}  // namespace

std::optional<std::array<Point3, 2>> exact_triangle_crossing(const Triangle3& a, const Triangle3& b) {
  const Q3 va[3] = {rational(a[0]), rational(a[1]), rational(a[2])};
  const Q3 vb[3] = {rational(b[0]), rational(b[1]), rational(b[2])};
  const Q3 na = cross(minus(va[1], va[0]), minus(va[2], va[0]));
  const Q3 nb = cross(minus(vb[1], vb[0]), minus(vb[2], vb[0]));
  mpq_class sa[3], sb[3];  // a's corners against b's plane, b's against a's
  for (int k = 0; k < 3; ++k) {
    sa[k] = dot(nb, minus(va[k], vb[0]));
    sb[k] = dot(na, minus(vb[k], va[0]));
  }
  if (one_side(sa) || one_side(sb)) return std::nullopt;
  const Q3 d = cross(na, nb);
  if (sgn(d.x) == 0 && sgn(d.y) == 0 && sgn(d.z) == 0) return std::nullopt;  // parallel or coplanar
  const std::vector<Q3> ma = meet_plane(va, sa), mb = meet_plane(vb, sb);
  if (ma.empty() || mb.empty()) return std::nullopt;
  // Both pieces lie on the planes' common line; their overlap, ordered along d.
  auto along = [&](const Q3& p) -> mpq_class { return dot(d, p); };
  auto lowest = [&](const std::vector<Q3>& m) {
    std::size_t k = 0;
    for (std::size_t i = 1; i < m.size(); ++i)
      if (along(m[i]) < along(m[k])) k = i;
    return k;
  };
  auto highest = [&](const std::vector<Q3>& m) {
    std::size_t k = 0;
    for (std::size_t i = 1; i < m.size(); ++i)
      if (along(m[i]) > along(m[k])) k = i;
    return k;
  };
  const Q3& la = ma[lowest(ma)];
  const Q3& lb = mb[lowest(mb)];
  const Q3& ha = ma[highest(ma)];
  const Q3& hb = mb[highest(mb)];
  const Q3& from = along(la) >= along(lb) ? la : lb;
  const Q3& to = along(ha) <= along(hb) ? ha : hb;
  if (along(from) >= along(to)) return std::nullopt;  // a point, or nothing
  auto rounded = [](const Q3& p) { return Point3{p.x.get_d(), p.y.get_d(), p.z.get_d()}; };
  return std::array<Point3, 2>{rounded(from), rounded(to)};
}

}  // namespace hlr
