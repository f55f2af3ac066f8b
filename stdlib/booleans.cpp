// Booleans through CGAL's corefinement (booleans.hpp). The only file that includes CGAL.
#include "stdlib/booleans.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <numeric>
#include <sstream>

#include "core/solid/solid_builder.hpp"
#include "core/tolerance.hpp"

namespace hlr::stdlib {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Exact::Point_3>;
using MeshVertex = Mesh::Vertex_index;
using Rounded = CGAL::Exact_predicates_inexact_constructions_kernel;
using RoundedMesh = CGAL::Surface_mesh<Rounded::Point_3>;

// Triangulating a face in its plane: exact predicates; the points are the face's own, projected.
using Plane2 = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexIndex, Plane2>;
using Fb = CGAL::Constrained_triangulation_face_base_2<Plane2>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Plane2, Tds, CGAL::Exact_predicates_tag>;

// The two coordinates a face keeps when projected along its normal's largest component, in the order
// that keeps its turn: (x, y) along z, (y, z) along x, (z, x) along y.
std::pair<int, int> projection_axes(Vector3 n) {
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  if (az >= ax && az >= ay) return {0, 1};
  if (ax >= ay) return {1, 2};
  return {2, 0};
}

double coordinate(Point3 p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

// Even-odd containment of p in the rings (as Solid faces are filled).
bool inside_rings(const std::vector<std::vector<Plane2::Point_2>>& rings, const Plane2::Point_2& p) {
  bool in = false;
  for (const auto& ring : rings)
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const auto& a = ring[i];
      const auto& b = ring[(i + 1) % n];
      if ((a.y() > p.y()) != (b.y() > p.y()) &&
          p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
        in = !in;
    }
  return in;
}

}  // namespace

void face_triangles(const Solid& s, std::size_t f, std::vector<std::array<VertexIndex, 3>>& out) {
  const Face& face = s.faces[f];
  if (face.rings.size() == 1 && face.rings[0].vertices.size() == 3) {
    const auto& r = face.rings[0].vertices;
    out.push_back({r[0], r[1], r[2]});
    return;
  }
  const Vector3 n = s.planes[f].normal;
  const auto [u, v] = projection_axes(n);
  const double turn = (u == 0 ? n.z : u == 1 ? n.x : n.y) >= 0 ? 1 : -1;
  Cdt cdt;
  std::vector<std::vector<Plane2::Point_2>> rings;
  for (const Ring& ring : face.rings) {
    rings.emplace_back();
    std::vector<Cdt::Vertex_handle> handles;
    for (const VertexIndex vi : ring.vertices) {
      const Point3 p = s.vertices[vi];
      const Plane2::Point_2 q(coordinate(p, u), coordinate(p, v));
      rings.back().push_back(q);
      Cdt::Vertex_handle h = cdt.insert(q);
      h->info() = vi;
      handles.push_back(h);
    }
    for (std::size_t i = 0; i < handles.size(); ++i)
      if (handles[i] != handles[(i + 1) % handles.size()])
        cdt.insert_constraint(handles[i], handles[(i + 1) % handles.size()]);
  }
  for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh) {
    const auto& a = fh->vertex(0)->point();
    const auto& b = fh->vertex(1)->point();
    const auto& c = fh->vertex(2)->point();
    const Plane2::Point_2 centre((a.x() + b.x() + c.x()) / 3, (a.y() + b.y() + c.y()) / 3);
    if (!inside_rings(rings, centre)) continue;
    const VertexIndex i0 = fh->vertex(0)->info(), i1 = fh->vertex(1)->info(), i2 = fh->vertex(2)->info();
    // The triangulation's faces turn counter-clockwise in the projection; the projection keeps the face's
    // turn when the normal's kept component is positive.
    if (turn > 0)
      out.push_back({i0, i1, i2});
    else
      out.push_back({i0, i2, i1});
  }
}

namespace {

Mesh to_mesh(const Solid& s, std::size_t operand) {
  if (!s.closed)
    throw BooleanOperandError(operand,
                              "is not closed: a boolean needs solids that enclose a volume (every edge "
                              "shared by two faces)");
  Mesh mesh;
  std::vector<MeshVertex> vertices;
  vertices.reserve(s.vertices.size());
  for (const Point3& p : s.vertices) vertices.push_back(mesh.add_vertex(Exact::Point_3(p.x, p.y, p.z)));
  std::vector<std::array<VertexIndex, 3>> triangles;
  for (std::size_t f = 0; f < s.faces.size(); ++f) face_triangles(s, f, triangles);
  for (const auto& t : triangles)
    if (mesh.add_face(vertices[t[0]], vertices[t[1]], vertices[t[2]]) == Mesh::null_face())
      throw BooleanOperandError(operand,
                                "cannot be made a closed surface of triangles (an edge would border "
                                "more than two of them)");
  // Vertices used by no face (markings' ends, hatch lines') are not part of the surface.
  for (const MeshVertex v : vertices)
    if (mesh.is_isolated(v)) mesh.remove_vertex(v);
  mesh.collect_garbage();
  if (!CGAL::is_closed(mesh))
    throw BooleanOperandError(operand, "is not closed once its faces are cut into triangles");
  if (PMP::does_self_intersect(mesh))
    throw BooleanOperandError(operand,
                              "crosses itself: a boolean needs solids whose faces meet only at "
                              "their edges");
  return mesh;
}

std::size_t find(std::vector<std::size_t>& parent, std::size_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// What the corefinement cut exactly can be too small for doubles: a point an ulp from another, a triangle
// whose corner lies within rounding of its opposite side. Within the tolerance the solid builder judges by
// (core/tolerance.hpp), such edges are collapsed and such caps flipped away, as long as the surface stays a
// closed manifold (the link condition); whatever is left with no area at all goes too.
// The diagonal of the mesh's box: the size the builder's tolerance is relative to.
double extent_of(const RoundedMesh& mesh) {
  CGAL::Bbox_3 box;
  for (const auto v : mesh.vertices()) box += mesh.point(v).bbox();
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

void collapse_slivers(RoundedMesh& mesh) {
  // Twice the builder's tolerance: what it would call one point, or no area, never reaches it.
  const double tol = 2 * Tolerance::for_extent(extent_of(mesh)).length;
  for (int pass = 0; pass < 8; ++pass) {
    bool changed = false;
    for (const auto e : mesh.edges()) {
      if (mesh.is_removed(e)) continue;
      const auto h = mesh.halfedge(e);
      if (std::sqrt(CGAL::squared_distance(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)))) > tol)
        continue;
      if (!CGAL::Euler::does_satisfy_link_condition(e, mesh)) continue;
      CGAL::Euler::collapse_edge(e, mesh);
      changed = true;
    }
    // Caps: a corner within tol of the opposite side, its longest. Flipping that side leaves two triangles
    // that both have area, moving the surface by no more than tol.
    for (const auto f : mesh.faces()) {
      if (mesh.is_removed(f)) continue;
      auto h = mesh.halfedge(f), longest = h;
      double best = 0;
      for (int k = 0; k < 3; ++k, h = mesh.next(h)) {
        const double l = CGAL::squared_distance(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)));
        if (l > best) best = l, longest = h;
      }
      const auto a = mesh.point(mesh.source(longest)), b = mesh.point(mesh.target(longest));
      const auto c = mesh.point(mesh.target(mesh.next(longest)));
      const double height = std::sqrt(CGAL::squared_distance(c, Rounded::Line_3(a, b)));
      if (height > tol || mesh.is_border(mesh.opposite(longest))) continue;
      const auto opposite_corner = mesh.target(mesh.next(mesh.opposite(longest)));
      if (mesh.target(mesh.next(longest)) == opposite_corner) continue;
      bool already = false;  // the flipped edge must not exist yet
      for (const auto g : CGAL::halfedges_around_target(mesh.next(longest), mesh))
        if (mesh.source(g) == opposite_corner) already = true;
      if (already) continue;
      CGAL::Euler::flip_edge(longest, mesh);
      changed = true;
    }
    if (!changed) break;
  }
  PMP::remove_degenerate_faces(mesh);
  mesh.collect_garbage();
}

Solid to_solid(Mesh mesh, double crease_angle_deg) {
  // Indices below run over the live elements only: the corefinement may leave removed ones behind.
  mesh.collect_garbage();
  if (mesh.number_of_faces() == 0)
    throw std::runtime_error("the result is empty: the solids have nothing in common");
  // Triangles exactly in one plane, joined across their common edges: one face of the drawing.
  std::vector<std::size_t> group(mesh.number_of_faces());
  std::iota(group.begin(), group.end(), 0);
  for (const auto e : mesh.edges()) {
    const auto h = mesh.halfedge(e), o = mesh.opposite(h);
    if (mesh.is_border(h) || mesh.is_border(o)) continue;
    const auto f = mesh.face(h), g = mesh.face(o);
    if (CGAL::coplanar(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                       mesh.point(mesh.target(mesh.next(h))), mesh.point(mesh.target(mesh.next(o)))))
      group[find(group, f.idx())] = find(group, g.idx());
  }

  // Rounded to doubles, a sliver the corefinement cut may have no area left: collapse such triangles (their
  // shortest edge, or the longest one's far corner onto it) so that the surface stays closed.
  RoundedMesh rounded;
  // Copied as a halfedge structure, not face by face: where the result touches itself at a vertex, adding
  // its faces one at a time could meet a fan the mesh cannot link in that order.
  std::vector<std::pair<Mesh::Face_index, RoundedMesh::Face_index>> faces;
  CGAL::copy_face_graph(mesh, rounded,
                        CGAL::parameters::face_to_face_output_iterator(std::back_inserter(faces)));
  auto plane_of = rounded.add_property_map<RoundedMesh::Face_index, std::size_t>("f:plane", 0).first;
  for (const auto& [exact, copy] : faces) plane_of[copy] = find(group, exact.idx());
  collapse_slivers(rounded);
  // Collapses round points where the result grazes itself can leave the mesh inconsistent; it is checked
  // before anything reads it.
  if (!CGAL::is_valid_polygon_mesh(rounded))
    throw std::runtime_error(
        "the result cannot be rounded to doubles without losing its shape: its parts "
        "touch or graze each other closer than rounding can tell apart");

  SolidBuildOptions options;
  options.crease_angle_deg = crease_angle_deg;
  SolidBuilder builder(options);
  // Where the result touches itself at a point (two notches meeting at a corner), the mesh has one vertex
  // per side of it; the solid has one vertex there, shared — and so do points the rounding left closer than
  // the builder tells apart (found in a grid of cells that size: a point's twin is in its cell or a
  // neighbour).
  const double tol = 2 * Tolerance::for_extent(extent_of(rounded)).length;
  std::map<std::array<long long, 3>, std::vector<std::pair<Point3, VertexIndex>>> cells;
  std::vector<VertexIndex> index(rounded.num_vertices());  // by index, removed ones included
  for (const auto v : rounded.vertices()) {
    const Rounded::Point_3& r = rounded.point(v);
    const Point3 p{r.x(), r.y(), r.z()};
    const std::array<long long, 3> cell = {std::llround(p.x / tol), std::llround(p.y / tol),
                                           std::llround(p.z / tol)};
    bool found = false;
    for (long long dx = -1; dx <= 1 && !found; ++dx)
      for (long long dy = -1; dy <= 1 && !found; ++dy)
        for (long long dz = -1; dz <= 1 && !found; ++dz) {
          const auto it = cells.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
          if (it == cells.end()) continue;
          for (const auto& [q, i] : it->second)
            if (distance(p, q) <= tol) {
              index[v.idx()] = i;
              found = true;
              break;
            }
        }
    if (!found) {
      index[v.idx()] = builder.add_vertex(p);
      cells[cell].emplace_back(p, index[v.idx()]);
    }
  }
  std::vector<std::size_t> face_plane;
  for (const auto f : rounded.faces()) {
    std::vector<std::uint32_t> ring;
    for (const auto v : CGAL::vertices_around_face(rounded.halfedge(f), rounded)) {
      if (v.idx() >= index.size() || rounded.is_removed(v))
        throw std::runtime_error("the result cannot be rounded to doubles without losing its shape");
      ring.push_back(index[v.idx()]);
    }
    if (ring[0] == ring[1] || ring[1] == ring[2] || ring[2] == ring[0]) continue;  // shrunk to a line
    builder.add_indexed_face_loop(ring);
    face_plane.push_back(plane_of[f]);
  }
  SolidBuildResult result = builder.build();
  if (!result.ok()) {
    std::ostringstream msg;
    msg << "the result is no valid solid once rounded to doubles:";
    for (const auto& d : result.diagnostics) msg << "\n  [" << d.code << "] " << d.message;
    throw std::runtime_error(msg.str());
  }
  Solid out = std::move(*result.solid);
  // Edges between triangles of one plane are Flat whatever rounding did to the triangles' normals. The
  // builder keeps the faces in the order given.
  if (out.faces.size() == face_plane.size())
    for (SolidEdge& e : out.edges)
      if (e.left >= 0 && e.right >= 0 &&
          face_plane[static_cast<std::size_t>(e.left)] == face_plane[static_cast<std::size_t>(e.right)])
        e.kind = EdgeKind::Flat;
  return out;
}

}  // namespace

namespace {

CGAL::Bbox_3 box_of(const Solid& s) {
  CGAL::Bbox_3 box;
  for (const Point3& p : s.vertices) box += CGAL::Bbox_3(p.x, p.y, p.z, p.x, p.y, p.z);
  return box;
}

void combine(BooleanOp op, Mesh& result, Mesh& next) {
  Mesh out;
  bool ok = false;
  switch (op) {
    case BooleanOp::Union:
      ok = PMP::corefine_and_compute_union(result, next, out);
      break;
    case BooleanOp::Difference:
      ok = PMP::corefine_and_compute_difference(result, next, out);
      break;
    case BooleanOp::Intersection:
      ok = PMP::corefine_and_compute_intersection(result, next, out);
      break;
  }
  if (!ok)
    throw std::runtime_error(
        "the result would not be a solid: the operands meet only along an edge or at a "
        "point, where the surface would not be a manifold");
  result = std::move(out);
}

// The union of operands [first, first + count): solids whose boxes meet are joined one by one; groups
// whose boxes do not meet are apart, and their union is their meshes side by side (a hundred drills in a
// plate are a hundred such groups: no corefinement at all).
Mesh union_of(const std::vector<const Solid*>& operands, std::size_t first, std::size_t count) {
  std::vector<CGAL::Bbox_3> boxes;
  for (std::size_t k = 0; k < count; ++k) boxes.push_back(box_of(*operands[first + k]));
  std::vector<std::size_t> parent(count);
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t a = 0; a < count; ++a)
    for (std::size_t b = a + 1; b < count; ++b)
      if (CGAL::do_overlap(boxes[a], boxes[b])) parent[find(parent, a)] = find(parent, b);
  std::map<std::size_t, Mesh> groups;  // by the group's root
  for (std::size_t k = 0; k < count; ++k) {
    Mesh mesh = to_mesh(*operands[first + k], first + k);
    const auto [it, added] = groups.try_emplace(find(parent, k));
    if (added)
      it->second = std::move(mesh);
    else
      combine(BooleanOp::Union, it->second, mesh);
  }
  Mesh out;
  for (auto& [root, mesh] : groups) CGAL::copy_face_graph(mesh, out);
  return out;
}

}  // namespace

Solid boolean_solid(BooleanOp op, const std::vector<const Solid*>& operands) {
  if (operands.empty()) throw std::invalid_argument("a boolean needs at least one solid");
  double crease = 0;
  for (const Solid* s : operands) crease = std::max(crease, s->crease_angle_deg);
  if (op == BooleanOp::Union) return to_solid(union_of(operands, 0, operands.size()), crease);
  Mesh result = to_mesh(*operands[0], 0);
  if (operands.size() == 1) return to_solid(std::move(result), crease);
  if (op == BooleanOp::Difference) {
    // The first minus the others is the first minus their union: one cut instead of one per solid.
    Mesh cut = union_of(operands, 1, operands.size() - 1);
    combine(op, result, cut);
    return to_solid(std::move(result), crease);
  }
  for (std::size_t i = 1; i < operands.size(); ++i) {
    Mesh next = to_mesh(*operands[i], i);
    combine(op, result, next);
  }
  return to_solid(std::move(result), crease);
}

}  // namespace hlr::stdlib
