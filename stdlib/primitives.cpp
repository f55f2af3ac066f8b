// Prismatic primitives: boxes, prisms with holes, the L-block, stairs, plates with holes, open and
// marked boxes. All of them are extrusions or small explicit vertex lists fed to SolidBuilder.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/solid/solid_builder.hpp"
#include "stdlib/generator_detail.hpp"
#include "stdlib/generators.hpp"
#include "stdlib/shapes.hpp"

namespace hlr::stdlib {

namespace detail {

void require(bool ok, const char* function, const std::string& what) {
  if (!ok) throw std::invalid_argument(std::string(function) + "(): " + what);
}

double signed_area2(const std::vector<Point2>& polygon) {
  double a = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point2 p = polygon[i], q = polygon[(i + 1) % polygon.size()];
    a += p.x * q.y - q.x * p.y;
  }
  return a;
}

Solid extrude(std::vector<Point2> outer, std::vector<std::vector<Point2>> holes, double w0, double w1,
              const Affine3& worldFromLocal, double crease_angle_deg) {
  require(outer.size() >= 3, "prism", "the polygon needs at least 3 corners");
  require(w0 < w1, "prism", "z0 must be below z1");
  require(worldFromLocal.determinant() > 0, "prism", "the placement must not mirror");
  {  // A self-crossing (bow-tie) outline, or a hole crossing it, said as such, by the points as given.
    std::vector<std::vector<Point2>> given = {outer};
    std::vector<std::string> names = {"outline"};
    for (std::size_t k = 0; k < holes.size(); ++k) {
      given.push_back(holes[k]);
      names.push_back("hole " + std::to_string(k));
    }
    if (const std::optional<RingDefect> defect = find_ring_defect(given))
      require(false, "prism", describe_ring_defect(*defect, names, given));
  }
  // Orientation as seen from +w: outer counter-clockwise, holes clockwise.
  if (signed_area2(outer) < 0) std::reverse(outer.begin(), outer.end());
  for (auto& h : holes) {
    require(h.size() >= 3, "prism", "every hole needs at least 3 corners");
    if (signed_area2(h) > 0) std::reverse(h.begin(), h.end());
  }
  std::vector<std::vector<Point2>> rings;
  rings.push_back(std::move(outer));
  for (auto& h : holes) rings.push_back(std::move(h));

  // Vertex k of the concatenated rings sits at index k (bottom, w0) and n + k (top, w1).
  std::vector<Point3> vertices;
  std::vector<std::vector<std::uint32_t>> ring_ids;
  std::uint32_t n = 0;
  for (const auto& r : rings) n += static_cast<std::uint32_t>(r.size());
  vertices.resize(2 * static_cast<std::size_t>(n));
  std::uint32_t k = 0;
  for (const auto& r : rings) {
    std::vector<std::uint32_t> ids;
    for (const Point2& p : r) {
      vertices[k] = worldFromLocal.apply(Point3{p.x, p.y, w0});
      vertices[n + k] = worldFromLocal.apply(Point3{p.x, p.y, w1});
      ids.push_back(k++);
    }
    ring_ids.push_back(std::move(ids));
  }

  std::vector<IndexedFace> faces;
  IndexedFace bottom, top;
  for (const auto& ids : ring_ids) {
    // Seen from below (outside the bottom) every ring's orientation flips.
    bottom.emplace_back(ids.rbegin(), ids.rend());
    std::vector<std::uint32_t> up;
    for (std::uint32_t id : ids) up.push_back(n + id);
    top.push_back(std::move(up));
  }
  faces.push_back(std::move(bottom));
  faces.push_back(std::move(top));
  // Side a→b: the normal (b − a) × w points to the right of the ring's direction, which is away from the
  // material for a counter-clockwise outer ring and for a clockwise hole alike.
  for (const auto& ids : ring_ids) {
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const std::uint32_t a = ids[i], b = ids[(i + 1) % ids.size()];
      faces.push_back(IndexedFace{{a, b, n + b, n + a}});
    }
  }
  return solid_from_indexed(vertices, faces, crease_angle_deg);
}

void orient_face(const std::vector<Point3>& vertices, IndexedFace& face, Vector3 outward) {
  Ring ring;
  ring.vertices.assign(face[0].begin(), face[0].end());
  if (dot(newell_normal(vertices, ring), outward) < 0)
    for (auto& r : face) std::reverse(r.begin(), r.end());
}

}  // namespace detail

using detail::require;

Solid solid_from_indexed(const std::vector<Point3>& vertices, const std::vector<IndexedFace>& faces,
                         double crease_angle_deg, const std::vector<IndexedLine>& lines) {
  SolidBuildOptions options;
  options.crease_angle_deg = crease_angle_deg;
  options.fix_winding = false;  // a generator with inconsistent winding is a bug: let it fail loudly
  SolidBuilder builder(options);
  // Indexed input: vertex i has id "i" without a string per vertex or reference. No tags: the error
  // below reports diagnostics by message, and untagged input stores none.
  std::size_t references = 0;
  for (const IndexedFace& f : faces)
    for (const auto& ring : f) references += ring.size();
  builder.reserve(vertices.size(), faces.size(), references);
  for (const Point3& p : vertices) builder.add_vertex(p);
  for (const IndexedFace& f : faces) builder.add_indexed_face(f);
  for (const IndexedLine& l : lines) builder.add_indexed_line(l.a, l.b);
  SolidBuildResult result = builder.build();
  if (!result.ok()) {
    std::ostringstream msg;
    msg << "generator produced an invalid solid (a bug in stdlib):";
    for (const auto& d : result.diagnostics) msg << "\n  [" << d.code << "] " << d.message;
    throw std::runtime_error(msg.str());
  }
  return std::move(*result.solid);
}

std::vector<Point2> regular_polygon(int sides, double radius, Point2 center, double phase_deg) {
  require(sides >= 3, "regular_polygon", "needs at least 3 sides");
  require(radius > 0, "regular_polygon", "radius must be positive");
  std::vector<Point2> p;
  const double phase = phase_deg * std::numbers::pi / 180;
  for (int i = 0; i < sides; ++i) {
    const double a = phase + 2 * std::numbers::pi * i / sides;
    p.push_back({center.x + radius * std::cos(a), center.y + radius * std::sin(a)});
  }
  return p;
}

namespace {

void require_box(Point3 min, Point3 max, const char* function) {
  require(is_finite(min) && is_finite(max), function, "corners must be finite");
  require(min.x < max.x && min.y < max.y && min.z < max.z, function, "min must be below max on every axis");
}

// The 8 corners of a box, bit 0 = x, bit 1 = y, bit 2 = z, and its 6 faces (outward, counter-clockwise).
std::vector<IndexedFace> box_faces() {
  return {{{0, 2, 3, 1}}, {{4, 5, 7, 6}}, {{0, 1, 5, 4}}, {{2, 6, 7, 3}}, {{0, 4, 6, 2}}, {{1, 3, 7, 5}}};
}

std::vector<Point3> box_corners(Point3 min, Point3 max) {
  std::vector<Point3> c;
  for (int i = 0; i < 8; ++i)
    c.push_back({(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z});
  return c;
}

}  // namespace

Solid box(Point3 min, Point3 max) {
  require_box(min, max, "box");
  return solid_from_indexed(box_corners(min, max), box_faces());
}

Solid rotated_box(Point3 center, Vector3 size, Vector3 axis, double angle_deg) {
  require(size.x > 0 && size.y > 0 && size.z > 0, "rotated_box", "sizes must be positive");
  require(length(axis) > 0, "rotated_box", "the axis must not be zero");
  const Affine3 rot = Affine3::rotation(axis, angle_deg * std::numbers::pi / 180);
  std::vector<Point3> c = box_corners(to_point(-0.5 * size), to_point(0.5 * size));
  for (Point3& p : c) p = center + to_vector(rot.apply(p));
  return solid_from_indexed(c, box_faces());
}

Solid prism(const std::vector<Point2>& polygon, const std::vector<std::vector<Point2>>& holes, double z0,
            double z1) {
  return detail::extrude(polygon, holes, z0, z1, Affine3::identity());
}

Solid l_block(Point3 origin, Vector3 size, double upright_width, double foot_height) {
  require(size.x > 0 && size.y > 0 && size.z > 0, "l_block", "sizes must be positive");
  require(upright_width > 0 && upright_width < size.x, "l_block", "upright_width must lie in (0, size.x)");
  require(foot_height > 0 && foot_height < size.z, "l_block", "foot_height must lie in (0, size.z)");
  // Outline in (u, v) = (x, z); extrusion w maps to −y, so (u, v, w) → (u, −w, v) keeps the handedness;
  // the translation puts w = 0 at y = origin.y + size.y.
  const std::vector<Point2> outline = {
      {0, 0},     {size.x, 0}, {size.x, foot_height}, {upright_width, foot_height}, {upright_width, size.z},
      {0, size.z}};
  const Affine3 frame =
      Affine3::from_rows({1, 0, 0}, {0, 0, -1}, {0, 1, 0}, {origin.x, origin.y + size.y, origin.z});
  return detail::extrude(outline, {}, 0, size.y, frame);
}

Solid stairs(int steps, double width, double rise, double run) {
  require(steps >= 1, "stairs", "needs at least one step");
  require(width > 0 && rise > 0 && run > 0, "stairs", "width, rise and run must be positive");
  // Profile in (x, z), counter-clockwise: along the floor, up the back, then down the treads.
  std::vector<Point2> profile = {{0, 0}, {steps * run, 0}};
  for (int i = steps - 1; i >= 0; --i) {
    profile.push_back({(i + 1) * run, (i + 1) * rise});
    profile.push_back({i * run, (i + 1) * rise});
  }
  // 2·steps + 2 corners: the floor, the back wall, then each tread and riser down to (0, rise).
  const Affine3 frame = Affine3::from_rows({1, 0, 0}, {0, 0, -1}, {0, 1, 0}, {0, width, 0});
  return detail::extrude(profile, {}, 0, width, frame);
}

Solid cylinder(Point3 base_center, double radius, double height, int sides, double crease_angle_deg) {
  require(height > 0, "cylinder", "height must be positive");
  return detail::extrude(regular_polygon(sides, radius, {base_center.x, base_center.y}), {}, base_center.z,
                         base_center.z + height, Affine3::identity(), crease_angle_deg);
}

Solid plate_with_holes(Point3 min, Point3 max, int holes_x, int holes_y, double hole_fraction,
                       int hole_sides) {
  require_box(min, max, "plate_with_holes");
  require(holes_x >= 0 && holes_y >= 0, "plate_with_holes", "hole counts must not be negative");
  require(hole_fraction > 0 && hole_fraction < 1, "plate_with_holes", "hole_fraction must lie in (0, 1)");
  const std::vector<Point2> outer = {{min.x, min.y}, {max.x, min.y}, {max.x, max.y}, {min.x, max.y}};
  std::vector<std::vector<Point2>> holes;
  const double cx = (max.x - min.x) / std::max(holes_x, 1), cy = (max.y - min.y) / std::max(holes_y, 1);
  const double radius = 0.5 * hole_fraction * std::min(cx, cy);
  for (int i = 0; i < holes_x; ++i)
    for (int j = 0; j < holes_y; ++j) {
      const Point2 c{min.x + (i + 0.5) * cx, min.y + (j + 0.5) * cy};
      // Squares are axis-aligned (phase 45°) so they read as a grid of windows.
      holes.push_back(regular_polygon(hole_sides, radius, c, hole_sides == 4 ? 45 : 90));
    }
  return detail::extrude(outer, holes, min.z, max.z, Affine3::identity());
}

Solid open_box(Point3 min, Point3 max) {
  require_box(min, max, "open_box");
  std::vector<IndexedFace> faces = box_faces();
  faces.erase(faces.begin() + 1);  // the top face (z = max)
  return solid_from_indexed(box_corners(min, max), faces);
}

Solid marked_box(Point3 min, Point3 max) {
  require_box(min, max, "marked_box");
  std::vector<Point3> v = box_corners(min, max);
  // Four points inset by a quarter on the top face for the X, and the mast's tip.
  const double x0 = min.x + 0.25 * (max.x - min.x), x1 = max.x - 0.25 * (max.x - min.x);
  const double y0 = min.y + 0.25 * (max.y - min.y), y1 = max.y - 0.25 * (max.y - min.y);
  v.push_back({x0, y0, max.z});  // 8
  v.push_back({x1, y1, max.z});  // 9
  v.push_back({x1, y0, max.z});  // 10
  v.push_back({x0, y1, max.z});  // 11
  // The mast starts at point 8 (on the top face) and ends above it: on no single face, so a free line.
  v.push_back({x0, y0, max.z + 0.5 * (max.z - min.z)});  // 12
  return solid_from_indexed(v, box_faces(), 0, {{8, 9}, {10, 11}, {8, 12}});
}

}  // namespace hlr::stdlib
