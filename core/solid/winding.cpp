// Consistent orientation: faces sharing an edge must traverse it in opposite directions, and a closed
// surface must have its normals pointing out of the volume it encloses.
#include <algorithm>
#include <cmath>
#include <optional>

#include "core/solid/builder_detail.hpp"

namespace hlr::solid_detail {
namespace {

struct Link {
  std::uint32_t edge;
  std::uint32_t other;
  bool same_direction;  // both faces run the shared edge the same way: one of them must be reversed
};

void reverse_face(Face& face, Plane& plane) {
  for (Ring& r : face.rings) {
    if (r.vertices.empty()) continue;
    // Reversed, edge j joins old vertices n−1−j and n−2−j: old edge (n−2−j) mod n.
    std::reverse(r.vertices.begin(), r.vertices.end());
    std::reverse(r.edges.begin(), r.edges.end());
    std::rotate(r.edges.begin(), r.edges.begin() + 1, r.edges.end());
  }
  plane.normal = -plane.normal;
  plane.offset = -plane.offset;
}

// A face's links to its neighbours across edges shared by exactly two faces, by edge number: the order
// in which the search meets them decides which conflict a non-orientable surface reports.
void links_of(const Face& face, std::uint32_t f, const EdgeEntries& edges, std::vector<Link>& links) {
  links.clear();
  for (const Ring& r : face.rings)
    for (std::uint32_t e : r.edges) {
      const EdgeEntry& entry = edges[e];
      if (entry.uses != 2 || entry.face[0] == entry.face[1]) continue;
      const auto other = static_cast<std::uint32_t>(
          entry.face[0] == static_cast<FaceIndex>(f) ? entry.face[1] : entry.face[0]);
      links.push_back({e, other, entry.use(0).forward == entry.use(1).forward});
    }
  std::sort(links.begin(), links.end(), [](const Link& a, const Link& b) { return a.edge < b.edge; });
}

// Faces grouped into connected components (across edges shared by exactly two faces), each with the flips
// that make its windings consistent, relative to the input and to its smallest face. Components are
// numbered in the order of their smallest faces; invalid faces have component -1.
struct Components {
  std::vector<std::int32_t> of;   // per face
  std::vector<std::int8_t> flip;  // per face: 1 = reverse relative to the input
  std::vector<bool> conflicted;   // per component: not orientable (reported; its flips are 0)
};

bool shared_by_two(const EdgeEntry& e) { return e.uses == 2 && e.face[0] != e.face[1]; }

// Union-find with parity over the shared edges, in edge order: no walk over the faces' rings, whose
// scattered allocations made the search below wait on memory. Returns false on the first conflict.
bool components_by_union(const std::vector<bool>& valid, const EdgeEntries& edges, Components& out) {
  const std::size_t n = valid.size();
  std::vector<std::uint32_t> parent(n);
  std::vector<std::int8_t> parity(n, 0);  // relative to the parent
  for (std::size_t f = 0; f < n; ++f) parent[f] = static_cast<std::uint32_t>(f);
  auto find = [&](std::uint32_t f) {  // root and f's parity to it, halving the path as it goes
    int p = 0;
    while (parent[f] != f) {
      const std::uint32_t up = parent[f];
      if (parent[up] != up) {  // skip a level: f's parity to its grandparent
        parity[f] = static_cast<std::int8_t>(parity[f] ^ parity[up]);
        parent[f] = parent[up];
      }
      p ^= parity[f];
      f = parent[f];
    }
    return std::pair<std::uint32_t, int>{f, p};
  };
  for (std::uint32_t e = 0; e < edges.size(); ++e) {
    const EdgeEntry& entry = edges[e];
    if (!shared_by_two(entry)) continue;
    const int want = entry.use(0).forward == entry.use(1).forward;  // same direction: opposite flips
    const auto [ra, pa] = find(static_cast<std::uint32_t>(entry.face[0]));
    const auto [rb, pb] = find(static_cast<std::uint32_t>(entry.face[1]));
    if (ra == rb) {
      if ((pa ^ pb) != want) return false;
      continue;
    }
    parent[std::max(ra, rb)] = std::min(ra, rb);  // the smaller root stays: roots are smallest faces
    parity[std::max(ra, rb)] = static_cast<std::int8_t>(pa ^ pb ^ want);
  }
  out.of.assign(n, -1);
  out.flip.assign(n, 0);
  std::int32_t count = 0;
  for (std::size_t f = 0; f < n; ++f) {
    if (!valid[f]) continue;
    const auto [root, p] = find(static_cast<std::uint32_t>(f));
    out.of[f] = root == f ? count++ : out.of[root];  // the root, the smallest face, came first
    out.flip[f] = static_cast<std::int8_t>(p);
  }
  out.conflicted.assign(static_cast<std::size_t>(count), false);
  return true;
}

// The same by breadth-first search from each smallest face, reporting the first conflict the search
// meets in each non-orientable component (edges of a face in edge order).
void components_by_search(const std::vector<Face>& faces, const std::vector<bool>& valid, Tags face_tags,
                          const EdgeEntries& edges, const VertexTable& vertices, Diagnostics& diagnostics,
                          Components& out) {
  const std::size_t n = faces.size();
  out.of.assign(n, -1);
  out.flip.assign(n, -1);  // -1 = not reached yet
  out.conflicted.clear();
  std::vector<std::uint32_t> component;
  std::vector<Link> links;
  for (std::size_t root = 0; root < n; ++root) {
    if (!valid[root] || out.flip[root] != -1) continue;
    const auto id = static_cast<std::int32_t>(out.conflicted.size());
    // Breadth-first (`component` in visiting order doubles as the queue): a neighbour sharing an edge in
    // the same direction gets the opposite flip.
    component.assign(1, static_cast<std::uint32_t>(root));
    out.flip[root] = 0;
    out.of[root] = id;
    std::optional<Link> conflict;
    std::uint32_t conflict_face = 0;
    for (std::size_t head = 0; head < component.size(); ++head) {
      const std::uint32_t f = component[head];
      links_of(faces[f], f, edges, links);
      for (const Link& l : links) {
        const int want = out.flip[f] ^ static_cast<int>(l.same_direction);
        if (out.flip[l.other] == -1) {
          out.flip[l.other] = static_cast<std::int8_t>(want);
          out.of[l.other] = id;
          component.push_back(l.other);
        } else if (out.flip[l.other] != want && !conflict) {
          conflict = l;
          conflict_face = f;
        }
      }
    }
    out.conflicted.push_back(conflict.has_value());
    if (!conflict) continue;
    const std::uint32_t a = std::min(conflict_face, conflict->other),
                        b = std::max(conflict_face, conflict->other);
    const EdgeEntry& e = edges[conflict->edge];
    diagnostics.error("non-orientable",
                      "faces " + std::to_string(a + 1) + " and " + std::to_string(b + 1) +
                          " cannot be wound consistently around edge " + edge_name(vertices, e.lo, e.hi) +
                          ": the surface is one-sided (like a Möbius band); split it or remove a face",
                      face_tags[b]);
    for (std::uint32_t f : component) out.flip[f] = 0;
  }
  for (std::int8_t& f : out.flip) f = f == -1 ? 0 : f;
}

}  // namespace

bool orient_faces(std::vector<Face>& faces, std::vector<Plane>& planes, const std::vector<bool>& valid,
                  const std::vector<Vector3>& areas, Tags face_tags, EdgeEntries& edges,
                  const VertexTable& vertices, const SolidBuildOptions& options, Diagnostics& diagnostics) {
  const std::size_t n = faces.size();
  std::vector<bool> open(n, false);  // on an edge not shared by exactly two faces
  for (std::uint32_t e = 0; e < edges.size(); ++e) {
    const EdgeEntry& entry = edges[e];
    if (entry.uses == 0 || shared_by_two(entry)) continue;  // a line, a seam
    for (int k = 0; k < std::min<int>(entry.uses, 2); ++k)
      open[static_cast<std::size_t>(entry.face[k])] = true;
  }
  for (const EdgeEntries::Extra& x : edges.extra()) open[static_cast<std::size_t>(x.use.face)] = true;

  Components comp;
  if (!components_by_union(valid, edges, comp))
    components_by_search(faces, valid, face_tags, edges, vertices, diagnostics, comp);
  std::vector<std::int8_t>& flip = comp.flip;

  // Per component: closed, how many faces the consistent winding flips, and six times the signed volume
  // it encloses (divergence theorem: each planar face contributes p·A with p any point of it and A its
  // area vector) with the sum of the terms' magnitudes, which bounds the rounding noise.
  struct Summary {
    bool closed = true;
    std::size_t faces = 0, flipped = 0;
    Point3 origin{};
    double volume = 0, noise = 0;
    bool invert = false, inside_out = false;
  };
  const std::vector<Point3>& pos = vertices.positions();
  std::vector<Summary> sums(comp.conflicted.size());
  for (std::size_t f = 0; f < n; ++f) {
    if (comp.of[f] < 0) continue;
    Summary& s = sums[static_cast<std::size_t>(comp.of[f])];
    const Point3 corner = pos[faces[f].rings[0].vertices[0]];
    if (s.faces++ == 0) s.origin = corner;
    s.flipped += flip[f] == 1;
    s.closed = s.closed && !open[f];
    const double term = dot(corner - s.origin, areas[f]);
    s.volume += flip[f] ? -term : term;
    s.noise += std::abs(term);
  }
  bool all_closed = !sums.empty();
  for (std::size_t c = 0; c < sums.size(); ++c) {
    Summary& s = sums[c];
    if (comp.conflicted[c]) {
      all_closed = false;
      continue;
    }
    all_closed = all_closed && s.closed;
    // Which of the two consistent windings: a closed surface encloses positive volume; otherwise the
    // majority of the input wins (ties keep the first face as given).
    s.invert = 2 * s.flipped > s.faces;
    if (s.closed && std::abs(s.volume) > Tolerance::kRelative * s.noise) s.invert = s.volume < 0;
    s.inside_out = (s.invert ? s.faces - s.flipped : s.flipped) == s.faces;
  }

  for (std::size_t f = 0; f < n; ++f) {
    if (comp.of[f] < 0) continue;
    const Summary& s = sums[static_cast<std::size_t>(comp.of[f])];
    flip[f] = static_cast<std::int8_t>(flip[f] ^ static_cast<int>(s.invert));
    if (flip[f] != 1) continue;
    const std::string name = "face " + std::to_string(f + 1);
    if (options.fix_winding)
      diagnostics.warning(
          "reoriented",
          s.inside_out
              ? name +
                    " was wound clockwise seen from outside, like every face of its solid (the solid "
                    "was inside out); reversed it"
              : name + " was wound clockwise seen from outside, unlike its neighbours; reversed it",
          face_tags[f]);
    else
      diagnostics.error("reoriented",
                        s.inside_out ? name +
                                           " is wound clockwise seen from outside, like every face of its "
                                           "solid (the solid is inside out); list its vertices "
                                           "counter-clockwise"
                                     : name +
                                           " is wound clockwise seen from outside, unlike its neighbours; "
                                           "list its vertices in the opposite order",
                        face_tags[f]);
  }
  if (options.fix_winding) {
    for (std::size_t f = 0; f < n; ++f)
      if (flip[f] == 1) reverse_face(faces[f], planes[f]);
    for (std::uint32_t e = 0; e < edges.size(); ++e) {
      EdgeEntry& entry = edges[e];
      for (int k = 0; k < std::min<int>(entry.uses, 2); ++k)
        if (flip[static_cast<std::size_t>(entry.face[k])] == 1)
          entry.forward ^= static_cast<std::uint8_t>(1u << k);
    }
    for (EdgeEntries::Extra& x : edges.extra())
      if (flip[static_cast<std::size_t>(x.use.face)] == 1) x.use.forward = !x.use.forward;
  }
  return all_closed;
}

}  // namespace hlr::solid_detail
