// Surfaces of revolution: revolve() and cone() (a revolved trapezoid). Between two profile points at two
// angles the face is an isosceles trapezoid, symmetric about the bisecting half-plane and hence planar;
// at an axis point it is a triangle around a single pole vertex; a profile segment at constant z gives one
// flat face (disk, annulus or sector) instead of a ring of coplanar pieces.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "core/format_number.hpp"
#include "core/tolerance.hpp"
#include "stdlib/generator_detail.hpp"
#include "stdlib/generators.hpp"
#include "stdlib/shapes.hpp"

namespace hlr::stdlib {

using detail::require;

namespace {

bool on_axis(Point2 p) { return p.x == 0; }

std::string point_text(Point2 p) {
  return "(" + format_for_message(p.x) + ", " + format_for_message(p.y) + ")";
}

// The profile in one of three normal forms (see shapes.hpp): a closed loop off the axis, an open polyline
// with both ends (and nothing else) on the axis, or any other open polyline (an open surface).
struct Profile {
  std::vector<Point2> points;
  bool loop = false;      // the last point connects back to the first
  bool encloses = false;  // a region (with the axis, for an open profile): the revolution is a solid
};

Profile normalize_profile(const std::vector<Point2>& input) {
  const char* fn = "revolve";
  require(input.size() >= 2, fn, "profile needs at least 2 points");
  for (const Point2& p : input) {
    require(std::isfinite(p.x) && std::isfinite(p.y), fn, "profile points must be finite");
    require(p.x >= 0, fn, "profile points need r \u2265 0 (got " + point_text(p) + ")");
  }
  Profile out;
  std::vector<Point2> p = input;
  if (p.size() > 2 && p.front() == p.back()) {
    p.pop_back();
    require(p.size() >= 3, fn, "a closed profile needs at least 3 distinct points");
    const std::size_t n = p.size();
    // Runs of axis points along the loop: none (a ring), or one of at least two points (an axis stretch).
    std::size_t runs = 0, start = n;
    for (std::size_t i = 0; i < n; ++i)
      if (on_axis(p[i]) && !on_axis(p[(i + n - 1) % n])) ++runs, start = i;
    const bool all_axis = std::all_of(p.begin(), p.end(), on_axis);
    require(!all_axis, fn, "profile lies on the axis");
    if (runs == 0) {
      out.points = std::move(p);
      out.loop = out.encloses = true;
      return out;
    }
    require(runs == 1, fn, "profile may touch the axis along one stretch only");
    std::size_t end = start;
    while (on_axis(p[(end + 1) % n])) end = (end + 1) % n;
    require(end != start, fn,
            "profile touches the axis at the single point " + point_text(p[start]) +
                ", where the surface would pinch; move it off the axis or touch the axis along a segment");
    // Open it along the axis stretch: from the stretch's last point round to its first.
    for (std::size_t i = end;; i = (i + 1) % n) {
      out.points.push_back(p[i]);
      if (i == start) break;
    }
  } else {
    // Leading and trailing runs of axis points add nothing but a segment on the axis: keep one each.
    std::size_t first = 0, last = p.size() - 1;
    while (first + 1 < p.size() && on_axis(p[first]) && on_axis(p[first + 1])) ++first;
    while (last > first && on_axis(p[last]) && on_axis(p[last - 1])) --last;
    require(last > first, fn, "profile lies on the axis");
    out.points.assign(p.begin() + static_cast<std::ptrdiff_t>(first),
                      p.begin() + static_cast<std::ptrdiff_t>(last) + 1);
  }
  for (std::size_t i = 1; i + 1 < out.points.size(); ++i)
    require(!on_axis(out.points[i]), fn,
            "profile meets the axis at " + point_text(out.points[i]) +
                " between its ends, where the surface would pinch; it may meet the axis only at its ends");
  out.encloses = on_axis(out.points.front()) && on_axis(out.points.back());
  return out;
}

}  // namespace

Solid revolve(const std::vector<Point2>& profile_in, int segments, double angle_deg,
              double crease_angle_deg) {
  const char* fn = "revolve";
  require(std::isfinite(angle_deg) && angle_deg > 0 && angle_deg <= 360, fn, "angle must lie in (0, 360]");
  const bool full = angle_deg == 360;
  require(segments >= (full ? 3 : 1), fn,
          full ? "segments must be at least 3" : "segments must be at least 1");
  require(full || angle_deg / segments < 180, fn, "segments must be more than angle / 180");
  require(std::isfinite(crease_angle_deg) && crease_angle_deg >= 0 && crease_angle_deg <= 180, fn,
          "crease must lie in [0, 180]");
  Profile profile = normalize_profile(profile_in);
  std::vector<Point2>& p = profile.points;
  const std::size_t n = p.size();
  if (const auto defect = find_ring_defect({p}, profile.encloses))
    require(false, fn, describe_ring_defect(*defect, {"profile"}, {p}, profile.encloses));
  // A region is revolved counter-clockwise in (r, z), so its material lies on the left of every segment.
  if (profile.encloses && detail::signed_area2(p) < 0) std::reverse(p.begin(), p.end());

  const double step = angle_deg * std::numbers::pi / 180 / segments;
  double extent = 0;
  for (const Point2& q : p) extent = std::max({extent, q.x, std::abs(q.y)});
  // Neighbouring copies of a point (and, for a partial angle, its first and last copy) must stay apart.
  const double spread =
      full ? std::sin(step / 2) : std::min(std::sin(step / 2), std::sin(angle_deg * std::numbers::pi / 360));
  for (const Point2& q : p)
    require(on_axis(q) || 2 * q.x * spread > Tolerance::kGeneratorFeature * extent, fn,
            "profile point " + point_text(q) + " is too close to the axis for " + std::to_string(segments) +
                " segments; put it on the axis (r = 0) or further away");

  // Vertices: the copies of each point off the axis first; poles are made on first use, so a pole that
  // only borders flat disks never becomes a vertex.
  const int columns = full ? segments : segments + 1;
  std::vector<std::vector<std::int64_t>> ids(
      n, std::vector<std::int64_t>(static_cast<std::size_t>(columns), -1));
  std::vector<Point3> vertices;
  auto vertex = [&](std::size_t k, int j) -> std::uint32_t {
    j = on_axis(p[k]) ? 0 : (full ? j % segments : j);
    std::int64_t& id = ids[k][static_cast<std::size_t>(j)];
    if (id < 0) {
      id = static_cast<std::int64_t>(vertices.size());
      const double phi = (!full && j == segments) ? angle_deg * std::numbers::pi / 180 : step * j;
      vertices.push_back(j == 0 ? Point3{p[k].x, 0, p[k].y}
                                : Point3{p[k].x * std::cos(phi), p[k].x * std::sin(phi), p[k].y});
    }
    return static_cast<std::uint32_t>(id);
  };
  // A point's copies at angles 0..end (forward) or end..0 (backward); one pole vertex on the axis.
  auto arc = [&](std::size_t k, bool forward) {
    if (on_axis(p[k])) return std::vector<std::uint32_t>{vertex(k, 0)};
    std::vector<std::uint32_t> r;
    const int last = full ? segments - 1 : segments;
    for (int j = 0; j <= last; ++j) r.push_back(vertex(k, forward ? j : last - j));
    return r;
  };

  for (std::size_t k = 0; k < n; ++k)
    if (!on_axis(p[k]))
      for (int j = 0; j < columns; ++j) vertex(k, j);  // predictable order: point by point, angle by angle

  // Segment a→b has the material on its left, so its outward normal in (r, z) is (Δz, −Δr). Walking the
  // copies of a forward then those of b backward turns counter-clockwise about that normal.
  std::vector<IndexedFace> faces;
  const std::size_t segment_count = profile.loop ? n : n - 1;
  for (std::size_t a = 0; a < segment_count; ++a) {
    const std::size_t b = (a + 1) % n;
    if (p[a].y == p[b].y) {                            // flat: one face
      if (full && (on_axis(p[a]) || on_axis(p[b]))) {  // a disk: its centre is no vertex
        faces.push_back(IndexedFace{on_axis(p[a]) ? arc(b, false) : arc(a, true)});
        continue;
      }
      std::vector<std::uint32_t> ra = arc(a, true), rb = arc(b, false);
      if (!full) {  // a sector, or a sector of an annulus: one ring
        ra.insert(ra.end(), rb.begin(), rb.end());
        faces.push_back(IndexedFace{std::move(ra)});
      } else {  // an annulus: the outer ring and the inner one as a hole
        faces.push_back(p[a].x > p[b].x ? IndexedFace{std::move(ra), std::move(rb)}
                                        : IndexedFace{std::move(rb), std::move(ra)});
      }
      continue;
    }
    for (int j = 0; j < segments; ++j) {
      if (on_axis(p[a]))
        faces.push_back(IndexedFace{{vertex(a, 0), vertex(b, j + 1), vertex(b, j)}});
      else if (on_axis(p[b]))
        faces.push_back(IndexedFace{{vertex(a, j), vertex(a, j + 1), vertex(b, 0)}});
      else
        faces.push_back(IndexedFace{{vertex(a, j), vertex(a, j + 1), vertex(b, j + 1), vertex(b, j)}});
    }
  }
  // A partial revolution of a region is closed by the profile itself at both ends: at angle 0 it faces
  // −y, where the counter-clockwise profile is seen counter-clockwise; at the far end it is reversed.
  if (!full && profile.encloses) {
    IndexedFace first(1), last(1);
    for (std::size_t k = 0; k < n; ++k) {
      first[0].push_back(vertex(k, 0));
      last[0].push_back(vertex(n - 1 - k, segments));
    }
    faces.push_back(std::move(first));
    faces.push_back(std::move(last));
  }
  return solid_from_indexed(vertices, faces, crease_angle_deg);
}

Solid cone(double radius, double height, double top_radius, int sides, double crease_angle_deg) {
  const char* fn = "cone";
  require(sides >= 3, fn, "sides must be at least 3");
  require(std::isfinite(radius) && radius >= 0, fn, "r must not be negative");
  require(std::isfinite(height) && height > 0, fn, "h must be positive");
  require(std::isfinite(top_radius) && top_radius >= 0, fn, "top must not be negative");
  require(radius > 0 || top_radius > 0, fn, "r and top must not both be 0");
  require(std::isfinite(crease_angle_deg) && crease_angle_deg >= 0 && crease_angle_deg <= 180, fn,
          "crease must lie in [0, 180]");
  // The profile runs round the region counter-clockwise; flat base and top become single polygons.
  std::vector<Point2> profile = {{0, 0}};
  if (radius > 0) profile.push_back({radius, 0});
  if (top_radius > 0) profile.push_back({top_radius, height});
  profile.push_back({0, height});
  return revolve(profile, sides, 360, crease_angle_deg);
}

}  // namespace hlr::stdlib
