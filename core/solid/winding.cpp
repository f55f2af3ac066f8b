// Consistent orientation: faces sharing an edge must traverse it in opposite directions, and a closed
// surface must have its normals pointing out of the volume it encloses.
#include <algorithm>
#include <cmath>
#include <deque>

#include "core/solid/builder_detail.hpp"

namespace hlr::solid_detail {
namespace {

struct Link {
  std::size_t other;
  bool same_direction;  // both faces run the shared edge the same way: one of them must be reversed
  std::size_t edge;
};

// Six times the signed volume enclosed by the component's faces (divergence theorem: each planar face
// contributes p·A with p any point of it and A its area vector, holes subtracting), and the sum of the
// magnitudes of the terms, which bounds the rounding noise.
std::pair<double, double> six_volume(const std::vector<PreparedFace>& faces, const std::vector<std::size_t>& component,
                                     const std::vector<int>& flip, const std::vector<Point3>& pos) {
  const Point3 origin = pos[faces[component[0]].rings[0].vertices[0]];
  double sum = 0, magnitude = 0;
  for (std::size_t f : component) {
    Vector3 area{};
    for (const Ring& r : faces[f].rings) area += newell_normal(pos, r);
    const double term = dot(pos[faces[f].rings[0].vertices[0]] - origin, area);
    sum += flip[f] ? -term : term;
    magnitude += std::abs(term);
  }
  return {sum, magnitude};
}

void reverse_face(PreparedFace& face) {
  for (Ring& r : face.rings) std::reverse(r.vertices.begin(), r.vertices.end());
  face.plane.normal = -face.plane.normal;
  face.plane.offset = -face.plane.offset;
}

}  // namespace

bool orient_faces(std::vector<PreparedFace>& faces, EdgeEntries& edges, const VertexTable& vertices,
                  const SolidBuildOptions& options, Diagnostics& diagnostics) {
  const std::size_t n = faces.size();
  std::vector<std::vector<Link>> links(n);
  std::vector<bool> open(n, false);  // on an edge not shared by exactly two faces
  const std::vector<EdgeEntry>& list = edges.list();
  for (std::size_t e = 0; e < list.size(); ++e) {
    const std::vector<EdgeUse>& uses = list[e].uses;
    if (uses.empty()) continue;  // an on-face line
    if (uses.size() != 2 || uses[0].face == uses[1].face) {
      for (const EdgeUse& u : uses) open[static_cast<std::size_t>(u.face)] = true;
      continue;
    }
    const auto f = static_cast<std::size_t>(uses[0].face), g = static_cast<std::size_t>(uses[1].face);
    const bool same = uses[0].forward == uses[1].forward;
    links[f].push_back({g, same, e});
    links[g].push_back({f, same, e});
  }

  std::vector<int> flip(n, -1);  // relative to the input; -1 = not reached yet
  std::vector<std::pair<int, std::string>> reports;  // (face number, message), emitted in face order
  bool all_closed = true, any_face = false;
  for (std::size_t root = 0; root < n; ++root) {
    if (!faces[root].valid || flip[root] != -1) continue;
    any_face = true;
    // Breadth-first: a neighbour sharing an edge in the same direction gets the opposite flip.
    std::vector<std::size_t> component{root};
    std::deque<std::size_t> queue{root};
    flip[root] = 0;
    const Link* conflict = nullptr;
    std::size_t conflict_face = 0;
    while (!queue.empty()) {
      const std::size_t f = queue.front();
      queue.pop_front();
      for (const Link& l : links[f]) {
        const int want = flip[f] ^ static_cast<int>(l.same_direction);
        if (flip[l.other] == -1) {
          flip[l.other] = want;
          component.push_back(l.other);
          queue.push_back(l.other);
        } else if (flip[l.other] != want && !conflict) {
          conflict = &l;
          conflict_face = f;
        }
      }
    }
    const bool closed = std::none_of(component.begin(), component.end(), [&](std::size_t f) { return open[f]; });
    if (conflict) {
      const std::size_t a = std::min(conflict_face, conflict->other), b = std::max(conflict_face, conflict->other);
      const EdgeEntry& e = list[conflict->edge];
      diagnostics.error("non-orientable",
                        "faces " + std::to_string(faces[a].number) + " and " + std::to_string(faces[b].number) +
                            " cannot be wound consistently around edge " + edge_name(vertices, e.lo, e.hi) +
                            ": the surface is one-sided (like a Möbius band); split it or remove a face",
                        faces[b].tag);
      all_closed = false;
      for (std::size_t f : component) flip[f] = 0;
      continue;
    }
    all_closed = all_closed && closed;

    // Which of the two consistent windings: a closed surface encloses positive volume; otherwise the
    // majority of the input wins (ties keep the first face as given).
    const auto flipped = static_cast<std::size_t>(std::count_if(component.begin(), component.end(),
                                                                [&](std::size_t f) { return flip[f] == 1; }));
    bool invert = 2 * flipped > component.size();
    if (closed) {
      const auto [volume, noise] = six_volume(faces, component, flip, vertices.positions);
      if (std::abs(volume) > Tolerance::kRelative * noise) invert = volume < 0;
    }
    if (invert)
      for (std::size_t f : component) flip[f] ^= 1;
    const bool inside_out = std::all_of(component.begin(), component.end(), [&](std::size_t f) { return flip[f] == 1; });

    for (std::size_t f : component) {
      if (flip[f] != 1) continue;
      const std::string name = "face " + std::to_string(faces[f].number);
      std::string message;
      if (options.fix_winding)
        message = inside_out ? name + " was wound clockwise seen from outside, like every face of its solid (the solid "
                                      "was inside out); reversed it"
                             : name + " was wound clockwise seen from outside, unlike its neighbours; reversed it";
      else
        message = inside_out ? name + " is wound clockwise seen from outside, like every face of its solid (the solid "
                                      "is inside out); list its vertices counter-clockwise"
                             : name + " is wound clockwise seen from outside, unlike its neighbours; list its "
                                      "vertices in the opposite order";
      reports.emplace_back(static_cast<int>(f), std::move(message));
    }
  }

  std::sort(reports.begin(), reports.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& [f, message] : reports) {
    if (options.fix_winding)
      diagnostics.warning("reoriented", std::move(message), faces[static_cast<std::size_t>(f)].tag);
    else
      diagnostics.error("reoriented", std::move(message), faces[static_cast<std::size_t>(f)].tag);
  }
  if (options.fix_winding) {
    for (std::size_t f = 0; f < n; ++f)
      if (flip[f] == 1) reverse_face(faces[f]);
    for (EdgeEntry& e : edges.list())
      for (EdgeUse& u : e.uses)
        if (flip[static_cast<std::size_t>(u.face)] == 1) u.forward = !u.forward;
  }
  return all_closed && any_face;
}

}  // namespace hlr::solid_detail
