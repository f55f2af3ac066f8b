// The edge table: every undirected ring edge once with the faces on its two sides, lines on faces, and
// free lines, in first-seen order (for the theses' data this is exactly Desens' LINES numbering).
#include <algorithm>
#include <cmath>

#include "core/solid/builder_detail.hpp"

namespace hlr::solid_detail {

std::uint64_t EdgeEntries::key(VertexIndex a, VertexIndex b) {
  const auto [lo, hi] = std::minmax(a, b);
  return (std::uint64_t{lo} << 32) | hi;
}

EdgeEntry& EdgeEntries::get(VertexIndex a, VertexIndex b) {
  const auto [it, fresh] = index_.try_emplace(key(a, b), list_.size());
  if (fresh) {
    EdgeEntry e;
    e.lo = std::min(a, b);
    e.hi = std::max(a, b);
    list_.push_back(e);
  }
  return list_[it->second];
}

const EdgeEntry* EdgeEntries::find(VertexIndex a, VertexIndex b) const {
  const auto it = index_.find(key(a, b));
  return it == index_.end() ? nullptr : &list_[it->second];
}

std::string edge_name(const VertexTable& vertices, VertexIndex a, VertexIndex b) {
  return vertices.ids[std::min(a, b)] + "\u2013" + vertices.ids[std::max(a, b)];
}

EdgeEntries collect_edges(const std::vector<PreparedFace>& faces, const VertexTable& vertices,
                          Diagnostics& diagnostics) {
  EdgeEntries edges;
  for (std::size_t fi = 0; fi < faces.size(); ++fi) {
    const PreparedFace& face = faces[fi];
    if (!face.valid) continue;
    // Enter edges in the order the input traverses them, rings and on-face lines interleaved.
    for (const std::vector<VertexIndex>& loop : face.traversal)
      for (std::size_t i = 0; i < loop.size(); ++i) edges.get(loop[i], loop[(i + 1) % loop.size()]);
    for (const Ring& r : face.rings)
      for (std::size_t i = 0; i < r.vertices.size(); ++i) {
        const VertexIndex a = r.vertices[i], b = r.vertices[(i + 1) % r.vertices.size()];
        edges.get(a, b).uses.push_back({static_cast<FaceIndex>(fi), a < b});
      }
    for (const auto& [a, b] : face.lines) {
      EdgeEntry& e = edges.get(a, b);
      if (e.marking_face == kNoFace) e.marking_face = static_cast<FaceIndex>(fi);
    }
  }
  for (const EdgeEntry& e : edges.list()) {
    if (e.uses.size() <= 2) continue;
    std::string names;
    for (const EdgeUse& u : e.uses)
      names += (names.empty() ? "" : ", ") + std::to_string(faces[static_cast<std::size_t>(u.face)].number);
    diagnostics.error("non-manifold-edge",
                      "edge " + edge_name(vertices, e.lo, e.hi) + " is used by " + std::to_string(e.uses.size()) +
                          " faces (" + names + "); an edge may border at most two faces",
                      faces[static_cast<std::size_t>(e.uses[2].face)].tag);
  }
  return edges;
}

namespace {

// The first face on which both end points lie: within the planarity tolerance of its plane and inside
// or on its polygon. (Only the end points are tested: a line between two points of a non-convex face
// may still leave it.)
FaceIndex face_holding(Point3 a, Point3 b, const Solid& solid, const std::vector<PreparedFace>& faces,
                       const SolidBuildOptions& options) {
  for (std::size_t fi = 0; fi < faces.size(); ++fi) {
    const PreparedFace& face = faces[fi];
    if (!face.valid) continue;
    const double tolerance = options.planarity_tolerance * face.size;
    const Plane& plane = solid.planes[fi];
    if (std::abs(plane.signed_distance(a)) > tolerance || std::abs(plane.signed_distance(b)) > tolerance) continue;
    const FaceFrame frame = FaceFrame::from_normal(plane.normal, solid.vertices[face.rings[0].vertices[0]]);
    std::vector<Polygon2> flat;
    for (const Ring& r : face.rings) {
      Polygon2 p;
      for (VertexIndex v : r.vertices) p.push_back(frame.to_2d(solid.vertices[v]));
      flat.push_back(std::move(p));
    }
    if (classify_point(frame.to_2d(a), flat, tolerance) != Containment::Outside &&
        classify_point(frame.to_2d(b), flat, tolerance) != Containment::Outside)
      return static_cast<FaceIndex>(fi);
  }
  return kNoFace;
}

}  // namespace

void build_edge_table(Solid& solid, EdgeEntries& edges, const std::vector<PreparedFace>& faces,
                      const std::vector<LineSpec>& lines, const VertexTable& vertices,
                      const SolidBuildOptions& options, Diagnostics& diagnostics) {
  for (std::size_t li = 0; li < lines.size(); ++li) {
    const LineSpec& line = lines[li];
    const std::string name = "line " + std::to_string(li + 1);
    VertexIndex ends[2] = {0, 0};
    bool resolved = true;
    const std::string* ids[2] = {&line.a, &line.b};
    for (int k = 0; k < 2; ++k) {
      const auto it = vertices.index_of.find(*ids[k]);
      if (it == vertices.index_of.end()) {
        if (k == 0 || line.b != line.a)
          diagnostics.error("unknown-vertex",
                            name + " names vertex '" + *ids[k] + "' which is not declared; declare it with 'vertex " +
                                *ids[k] + " = (x, y, z)' before the line",
                            line.tag);
        resolved = false;
        continue;
      }
      if (!vertices.usable[it->second]) resolved = false;  // non-finite: reported with the vertex
      ends[k] = it->second;
    }
    if (!resolved) continue;
    if (ends[0] == ends[1]) {
      diagnostics.warning("degenerate-line", name + " joins vertex '" + line.a + "' to itself; dropped it", line.tag);
      continue;
    }
    if (edges.find(ends[0], ends[1])) continue;  // already an edge or a line: keep one
    const FaceIndex on = face_holding(solid.vertices[ends[0]], solid.vertices[ends[1]], solid, faces, options);
    EdgeEntry& e = edges.get(ends[0], ends[1]);
    if (on != kNoFace)
      e.marking_face = on;
    else
      e.free_line = true;
  }

  for (const EdgeEntry& entry : edges.list()) {
    SolidEdge e;
    e.v0 = entry.lo;
    e.v1 = entry.hi;
    if (entry.uses.size() == 2) {
      // left runs v0→v1; after orientation the other use runs v1→v0.
      const EdgeUse& l = entry.uses[0].forward ? entry.uses[0] : entry.uses[1];
      const EdgeUse& r = &l == &entry.uses[0] ? entry.uses[1] : entry.uses[0];
      e.left = l.face;
      e.right = r.face;
      const DihedralClass c = classify_dihedral(solid.vertices[e.v1] - solid.vertices[e.v0],
                                                solid.planes[static_cast<std::size_t>(e.left)].normal,
                                                solid.planes[static_cast<std::size_t>(e.right)].normal,
                                                options.crease_angle_deg);
      e.kind = c.kind;
      e.concave = c.concave;
    } else if (entry.uses.size() == 1) {
      if (!entry.uses[0].forward) std::swap(e.v0, e.v1);  // keep the face on the left
      e.left = entry.uses[0].face;
      e.kind = EdgeKind::Boundary;
    } else if (entry.uses.size() > 2) {
      continue;  // reported as non-manifold; no solid is returned
    } else if (entry.marking_face != kNoFace) {
      e.left = e.right = entry.marking_face;
      e.kind = EdgeKind::Marking;
    } else if (entry.free_line) {
      e.kind = EdgeKind::Free;
    } else {
      continue;
    }
    solid.edges.push_back(e);
  }
}

}  // namespace hlr::solid_detail
