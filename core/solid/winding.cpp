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

// Six times the signed volume enclosed by the component's faces (divergence theorem: each planar face
// contributes p·A with p any point of it and A its area vector, holes subtracting), and the sum of the
// magnitudes of the terms, which bounds the rounding noise.
std::pair<double, double> six_volume(const std::vector<Face>& faces,
                                     const std::vector<std::uint32_t>& component,
                                     const std::vector<std::int8_t>& flip, const std::vector<Point3>& pos) {
  const Point3 origin = pos[faces[component[0]].rings[0].vertices[0]];
  double sum = 0, magnitude = 0;
  for (std::uint32_t f : component) {
    Vector3 area{};
    for (const Ring& r : faces[f].rings) area += newell_normal(pos, r);
    const double term = dot(pos[faces[f].rings[0].vertices[0]] - origin, area);
    sum += flip[f] ? -term : term;
    magnitude += std::abs(term);
  }
  return {sum, magnitude};
}

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

}  // namespace

bool orient_faces(std::vector<Face>& faces, std::vector<Plane>& planes, const std::vector<bool>& valid,
                  Tags face_tags, EdgeEntries& edges, const VertexTable& vertices,
                  const SolidBuildOptions& options, Diagnostics& diagnostics) {
  const std::size_t n = faces.size();
  std::vector<bool> open(n, false);  // on an edge not shared by exactly two faces
  for (std::uint32_t e = 0; e < edges.size(); ++e) {
    const EdgeEntry& entry = edges[e];
    if (entry.uses == 0 || (entry.uses == 2 && entry.face[0] != entry.face[1])) continue;  // a line, a seam
    for (int k = 0; k < std::min<int>(entry.uses, 2); ++k)
      open[static_cast<std::size_t>(entry.face[k])] = true;
  }
  for (const EdgeEntries::Extra& x : edges.extra()) open[static_cast<std::size_t>(x.use.face)] = true;

  std::vector<std::int8_t> flip(n, -1);                        // relative to the input; -1 = not reached yet
  std::vector<std::pair<std::uint32_t, std::string>> reports;  // (face, message), emitted in face order
  std::vector<std::uint32_t> component;
  std::vector<Link> links;
  bool all_closed = true, any_face = false;
  for (std::size_t root = 0; root < n; ++root) {
    if (!valid[root] || flip[root] != -1) continue;
    any_face = true;
    // Breadth-first (`component` in visiting order doubles as the queue): a neighbour sharing an edge in
    // the same direction gets the opposite flip.
    component.assign(1, static_cast<std::uint32_t>(root));
    flip[root] = 0;
    std::optional<Link> conflict;
    std::uint32_t conflict_face = 0;
    for (std::size_t head = 0; head < component.size(); ++head) {
      const std::uint32_t f = component[head];
      links_of(faces[f], f, edges, links);
      for (const Link& l : links) {
        const int want = flip[f] ^ static_cast<int>(l.same_direction);
        if (flip[l.other] == -1) {
          flip[l.other] = static_cast<std::int8_t>(want);
          component.push_back(l.other);
        } else if (flip[l.other] != want && !conflict) {
          conflict = l;
          conflict_face = f;
        }
      }
    }
    const bool closed =
        std::none_of(component.begin(), component.end(), [&](std::uint32_t f) { return open[f]; });
    if (conflict) {
      const std::uint32_t a = std::min(conflict_face, conflict->other),
                          b = std::max(conflict_face, conflict->other);
      const EdgeEntry& e = edges[conflict->edge];
      diagnostics.error("non-orientable",
                        "faces " + std::to_string(a + 1) + " and " + std::to_string(b + 1) +
                            " cannot be wound consistently around edge " + edge_name(vertices, e.lo, e.hi) +
                            ": the surface is one-sided (like a Möbius band); split it or remove a face",
                        face_tags[b]);
      all_closed = false;
      for (std::uint32_t f : component) flip[f] = 0;
      continue;
    }
    all_closed = all_closed && closed;

    // Which of the two consistent windings: a closed surface encloses positive volume; otherwise the
    // majority of the input wins (ties keep the first face as given).
    const auto flipped = static_cast<std::size_t>(
        std::count_if(component.begin(), component.end(), [&](std::uint32_t f) { return flip[f] == 1; }));
    bool invert = 2 * flipped > component.size();
    if (closed) {
      const auto [volume, noise] = six_volume(faces, component, flip, vertices.positions());
      if (std::abs(volume) > Tolerance::kRelative * noise) invert = volume < 0;
    }
    if (invert)
      for (std::uint32_t f : component) flip[f] ^= 1;
    const bool inside_out =
        std::all_of(component.begin(), component.end(), [&](std::uint32_t f) { return flip[f] == 1; });

    for (std::uint32_t f : component) {
      if (flip[f] != 1) continue;
      const std::string name = "face " + std::to_string(f + 1);
      std::string message;
      if (options.fix_winding)
        message = inside_out
                      ? name +
                            " was wound clockwise seen from outside, like every face of its solid (the solid "
                            "was inside out); reversed it"
                      : name + " was wound clockwise seen from outside, unlike its neighbours; reversed it";
      else
        message = inside_out
                      ? name +
                            " is wound clockwise seen from outside, like every face of its solid (the solid "
                            "is inside out); list its vertices counter-clockwise"
                      : name +
                            " is wound clockwise seen from outside, unlike its neighbours; list its "
                            "vertices in the opposite order";
      reports.emplace_back(f, std::move(message));
    }
  }

  std::sort(reports.begin(), reports.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& [f, message] : reports) {
    if (options.fix_winding)
      diagnostics.warning("reoriented", std::move(message), face_tags[f]);
    else
      diagnostics.error("reoriented", std::move(message), face_tags[f]);
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
  return all_closed && any_face;
}

}  // namespace hlr::solid_detail
