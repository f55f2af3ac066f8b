// One face: resolve its vertex ids, drop repeated vertices, split thesis-style loops into rings and
// on-face lines, pick the outer ring, fit the plane and check area, planarity and holes.
#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "core/solid/builder_detail.hpp"

namespace hlr::solid_detail {
namespace {

using Loop = std::vector<VertexIndex>;

std::uint64_t directed_key(VertexIndex a, VertexIndex b) { return (std::uint64_t{a} << 32) | b; }

struct SplitLoops {
  std::vector<Loop> rings;
  std::vector<std::pair<VertexIndex, VertexIndex>> lines;  // lower index first
  bool repeated = false;                                   // a directed edge left over more than once
  VertexIndex repeated_a = 0, repeated_b = 0;
};

// Splits closed loops into rings and on-face lines. An undirected edge traversed both ways is a line on
// the face (Desens' bridges to holes and deck markings): its opposite traversals cancel in pairs. The
// directed edges left over still enter and leave every vertex equally often, so they decompose into
// closed rings; we walk them and cut a ring off whenever the walk returns to a vertex already on the
// current path, so no ring repeats a vertex. Which outgoing edge is taken at a vertex with several does
// not matter: containment is even-odd over all rings.
SplitLoops split_loops(const std::vector<Loop>& loops) {
  SplitLoops out;
  Loop all;
  for (const Loop& l : loops) all.insert(all.end(), l.begin(), l.end());
  std::sort(all.begin(), all.end());
  if (std::adjacent_find(all.begin(), all.end()) == all.end()) {  // no shared vertex: nothing can cancel
    out.rings = loops;
    return out;
  }

  struct Directed {
    VertexIndex a, b;
  };
  std::vector<Directed> directed;
  std::unordered_map<std::uint64_t, int> count;
  for (const Loop& l : loops)
    for (std::size_t i = 0; i < l.size(); ++i) {
      directed.push_back({l[i], l[(i + 1) % l.size()]});
      ++count[directed_key(l[i], l[(i + 1) % l.size()])];
    }

  // Cancel opposite traversals; keep the surplus copies of each directed edge, in traversal order.
  std::unordered_map<std::uint64_t, int> surplus;
  std::unordered_set<std::uint64_t> line_seen;
  std::vector<Directed> kept;
  for (const Directed& d : directed) {
    const std::uint64_t fwd = directed_key(d.a, d.b);
    const auto rit = count.find(directed_key(d.b, d.a));
    const int r = rit == count.end() ? 0 : rit->second;
    if (r > 0) {
      const auto [lo, hi] = std::minmax(d.a, d.b);
      if (line_seen.insert(directed_key(lo, hi)).second) out.lines.emplace_back(lo, hi);
    }
    const auto it = surplus.try_emplace(fwd, std::max(0, count[fwd] - r)).first;
    if (it->second > 1 && !out.repeated) {
      out.repeated = true;
      out.repeated_a = d.a;
      out.repeated_b = d.b;
    }
    if (it->second > 0) {
      kept.push_back(d);
      --it->second;
    }
  }

  // Walk the kept edges.
  std::unordered_map<VertexIndex, std::vector<std::size_t>> outgoing;
  for (std::size_t i = 0; i < kept.size(); ++i) outgoing[kept[i].a].push_back(i);
  std::unordered_map<VertexIndex, std::size_t> cursor;
  std::vector<bool> used(kept.size(), false);
  auto next_unused = [&](VertexIndex v) -> std::size_t {
    auto& list = outgoing[v];
    std::size_t& c = cursor[v];
    while (c < list.size() && used[list[c]]) ++c;
    return c < list.size() ? list[c] : kept.size();
  };
  for (std::size_t start = 0; start < kept.size(); ++start) {
    if (used[start]) continue;
    Loop path{kept[start].a};
    std::unordered_map<VertexIndex, std::size_t> position{{kept[start].a, 0}};
    std::size_t edge = start;
    while (edge < kept.size()) {
      used[edge] = true;
      const VertexIndex v = kept[edge].b;
      if (auto it = position.find(v); it != position.end()) {
        const std::size_t k = it->second;
        out.rings.emplace_back(path.begin() + static_cast<std::ptrdiff_t>(k), path.end());
        for (std::size_t i = k + 1; i < path.size(); ++i) position.erase(path[i]);
        path.resize(k + 1);
      } else {
        position.emplace(v, path.size());
        path.push_back(v);
      }
      edge = next_unused(path.back());
      // Balanced degrees mean a walk can only stop where it started; if the data defeats that, the
      // unfinished path is dropped rather than trusted.
    }
  }
  return out;
}

std::string quoted(const std::string& id) { return "'" + id + "'"; }

// The first pair of edges (a[i], b[m]) that cross; bounding boxes skip most pairs of distant edges.
bool first_crossing(const Polygon2& a, const Polygon2& b, double tolerance, std::size_t& i, std::size_t& m) {
  auto box = [](Point2 p, Point2 q) {
    return std::array<double, 4>{std::min(p.x, q.x), std::min(p.y, q.y), std::max(p.x, q.x), std::max(p.y, q.y)};
  };
  for (i = 0; i < a.size(); ++i) {
    const Point2 p = a[i], q = a[(i + 1) % a.size()];
    const auto ba = box(p, q);
    for (m = 0; m < b.size(); ++m) {
      const Point2 r = b[m], t = b[(m + 1) % b.size()];
      const auto bb = box(r, t);
      if (ba[0] > bb[2] || bb[0] > ba[2] || ba[1] > bb[3] || bb[1] > ba[3]) continue;
      if (segments_cross(p, q, r, t, tolerance)) return true;
    }
  }
  return false;
}

}  // namespace

PreparedFace prepare_face(const std::vector<std::vector<std::string>>& input_rings, bool from_loop, int number,
                          std::int64_t tag, const VertexTable& vertices, const SolidBuildOptions& options,
                          Diagnostics& diagnostics) {
  PreparedFace face;
  face.number = number;
  face.tag = tag;
  const std::string name = "face " + std::to_string(number);
  auto ring_name = [&](std::size_t k) {
    return k == 0 ? name : "hole " + std::to_string(k) + " of " + name;
  };

  // Resolve ids; name each unknown id once.
  bool resolved = true;
  std::vector<std::string> unknown;
  std::vector<Loop> loops;
  for (const auto& ring : input_rings) {
    Loop loop;
    for (const std::string& id : ring) {
      const auto it = vertices.index_of.find(id);
      if (it == vertices.index_of.end()) {
        resolved = false;
        if (std::find(unknown.begin(), unknown.end(), id) == unknown.end()) {
          unknown.push_back(id);
          diagnostics.error("unknown-vertex",
                            name + " names vertex " + quoted(id) + " which is not declared; declare it with 'vertex " +
                                id + " = (x, y, z)' before the face",
                            tag);
        }
        continue;
      }
      if (!vertices.usable[it->second]) resolved = false;  // non-finite: reported with the vertex
      loop.push_back(it->second);
    }
    loops.push_back(std::move(loop));
  }
  if (!resolved) return face;
  if (loops.empty()) loops.emplace_back();

  // Drop a vertex repeated in a row (also last = first): it adds no edge.
  for (std::size_t k = 0; k < loops.size(); ++k) {
    Loop clean;
    auto warn = [&](VertexIndex v) {
      diagnostics.warning("repeated-vertex",
                          ring_name(k) + " lists vertex " + quoted(vertices.ids[v]) + " twice in a row; dropped the repeat",
                          tag);
    };
    for (VertexIndex v : loops[k]) {
      if (!clean.empty() && clean.back() == v) {
        warn(v);
        continue;
      }
      clean.push_back(v);
    }
    while (clean.size() > 1 && clean.back() == clean.front()) {
      warn(clean.back());
      clean.pop_back();
    }
    loops[k] = std::move(clean);
  }

  bool enough = true;
  for (std::size_t k = 0; k < loops.size(); ++k) {
    Loop distinct = loops[k];
    std::sort(distinct.begin(), distinct.end());
    const auto n = std::unique(distinct.begin(), distinct.end()) - distinct.begin();
    if (n < 3) {
      enough = false;
      diagnostics.error("too-few-vertices",
                        ring_name(k) + " has only " + std::to_string(n) + " distinct vertices; " +
                            (k == 0 ? "a face" : "a hole") + " needs at least 3",
                        tag);
    }
  }
  if (!enough) return face;
  face.traversal = loops;

  SplitLoops split = split_loops(loops);
  if (split.repeated) {
    diagnostics.error("non-manifold-edge",
                      name + " runs along edge " + edge_name(vertices, split.repeated_a, split.repeated_b) +
                          " twice in the same direction; each edge may appear once in a face's boundary",
                      tag);
    return face;
  }
  if (split.rings.empty()) {
    diagnostics.error("zero-area",
                      name + " has zero area: every edge of its " + (from_loop ? "loop" : "rings") +
                          " is traversed in both directions",
                      tag);
    return face;
  }

  // The outer ring encloses the others, so it has the largest area (for loops this is how it is found).
  const std::vector<Point3>& pos = vertices.positions;
  std::vector<Ring> rings;
  std::vector<double> twice_area;
  for (Loop& l : split.rings) {
    rings.push_back(Ring{std::move(l), {}});
    twice_area.push_back(length(newell_normal(pos, rings.back())));
  }
  const auto outer = static_cast<std::size_t>(std::max_element(twice_area.begin(), twice_area.end()) - twice_area.begin());
  std::rotate(rings.begin(), rings.begin() + static_cast<std::ptrdiff_t>(outer),
              rings.begin() + static_cast<std::ptrdiff_t>(outer) + 1);
  std::rotate(twice_area.begin(), twice_area.begin() + static_cast<std::ptrdiff_t>(outer),
              twice_area.begin() + static_cast<std::ptrdiff_t>(outer) + 1);

  // Every vertex the face names, for its size and the planarity check.
  Loop named;
  for (const Ring& r : rings) named.insert(named.end(), r.vertices.begin(), r.vertices.end());
  for (const auto& [a, b] : split.lines) named.insert(named.end(), {a, b});
  Point3 lo = pos[named[0]], hi = pos[named[0]];
  for (VertexIndex v : named) {
    lo = {std::min(lo.x, pos[v].x), std::min(lo.y, pos[v].y), std::min(lo.z, pos[v].z)};
    hi = {std::max(hi.x, pos[v].x), std::max(hi.y, pos[v].y), std::max(hi.z, pos[v].z)};
  }
  face.size = distance(lo, hi);
  // Twice the area against the size squared: below kRelative, the normal is rounding noise.
  const double area_floor = Tolerance::for_extent(face.size).length * face.size;
  if (twice_area[0] <= area_floor) {
    diagnostics.error("zero-area", name + " has zero area", tag);
    return face;
  }

  // Plane of the outer ring (holes do not change it); every named vertex must lie on it.
  face.plane = newell_plane(pos, rings[0]);
  double worst = -1;
  VertexIndex worst_vertex = 0;
  for (VertexIndex v : named) {
    const double dev = std::abs(face.plane.signed_distance(pos[v]));
    if (dev > worst) {
      worst = dev;
      worst_vertex = v;
    }
  }
  const double allowed = options.planarity_tolerance * face.size;
  if (worst > Tolerance::kPlanarity * face.size) {  // messages are built only when needed
    const std::string deviation = name + " is not planar: vertex " + vertices.ids[worst_vertex] + " lies " +
                                  format_number(worst) + " off the plane of the others";
    if (worst > allowed) {
      diagnostics.error("non-planar",
                        deviation + " (tolerance " + format_number(options.planarity_tolerance) +
                            " × face size); split it into planar faces",
                        tag);
      return face;
    }
    diagnostics.warning("non-planar",
                        deviation + " (more than " + format_number(Tolerance::kPlanarity) +
                            " × face size, accepted by the planarity tolerance " +
                            format_number(options.planarity_tolerance) + "); drawings may be slightly off near it",
                        tag);
  }

  // Holes: each inside the outer ring, no two rings crossing; orientation by nesting depth.
  if (rings.size() > 1) {
    const FaceFrame frame = FaceFrame::from_normal(face.plane.normal, pos[rings[0].vertices[0]]);
    std::vector<Polygon2> flat;
    for (const Ring& r : rings) {
      Polygon2 p;
      for (VertexIndex v : r.vertices) p.push_back(frame.to_2d(pos[v]));
      flat.push_back(std::move(p));
    }
    // Misplaced holes are errors, or warnings when the options accept them (legacy data).
    bool holes_ok = true;
    std::vector<bool> reported(rings.size(), false);  // one report per hole
    auto bad_hole = [&](const std::string& what, const char* rule) {
      if (options.allow_crossing_holes) {
        diagnostics.warning("bad-hole", what + "; kept it: the face is the even-odd region of its rings", tag);
      } else {
        diagnostics.error("bad-hole", what + "; " + rule, tag);
        holes_ok = false;
      }
    };
    for (std::size_t k = 1; k < rings.size(); ++k) {
      if (twice_area[k] <= area_floor) {
        diagnostics.error("zero-area", ring_name(k) + " has zero area", tag);
        holes_ok = false;
        continue;
      }
      for (std::size_t i = 0; i < flat[k].size(); ++i)
        if (classify_point(flat[k][i], {flat[0]}, allowed) == Containment::Outside) {
          reported[k] = true;
          bad_hole(ring_name(k) + " is not inside the face: vertex " + quoted(vertices.ids[rings[k].vertices[i]]) +
                       " lies outside its outer boundary",
                   "a hole must lie within the outer ring");
          break;
        }
    }
    for (std::size_t j = 1; j < rings.size(); ++j)
      for (std::size_t k = 0; k < j && !reported[j]; ++k) {
        std::size_t i = 0, m = 0;
        if (!first_crossing(flat[j], flat[k], allowed, i, m)) continue;
        reported[j] = true;
        const Loop &ra = rings[j].vertices, &rb = rings[k].vertices;
        bad_hole(ring_name(j) + " crosses " + (k == 0 ? std::string("its outer boundary") : ring_name(k)) + " (edges " +
                     edge_name(vertices, ra[i], ra[(i + 1) % ra.size()]) + " and " +
                     edge_name(vertices, rb[m], rb[(m + 1) % rb.size()]) + ")",
                 "holes must lie inside the face without crossing its boundary or each other");
      }
    if (!holes_ok) return face;

    // A ring inside an odd number of other rings bounds a hole (clockwise seen from outside); inside an
    // even number, an island in a hole (counter-clockwise like the outer ring). The outer ring is
    // counter-clockwise in the frame by construction of the frame from its normal.
    for (std::size_t k = 1; k < rings.size(); ++k) {
      int depth = 1;
      for (std::size_t j = 1; j < rings.size(); ++j) {
        if (j == k) continue;
        Containment c = Containment::Boundary;
        for (std::size_t i = 0; i < flat[k].size() && c == Containment::Boundary; ++i) {
          c = classify_point(flat[k][i], {flat[j]}, allowed);
          if (c == Containment::Boundary) {  // try the middle of the edge leaving that vertex
            const Point2 a = flat[k][i], b = flat[k][(i + 1) % flat[k].size()];
            c = classify_point(lerp(a, b, 0.5), {flat[j]}, allowed);
          }
        }
        if (c == Containment::Inside) ++depth;
      }
      const bool want_clockwise = depth % 2 == 1;
      if ((signed_area(flat[k]) < 0) != want_clockwise)
        std::reverse(rings[k].vertices.begin(), rings[k].vertices.end());
    }
  }

  face.rings = std::move(rings);
  face.lines = std::move(split.lines);
  face.valid = true;
  return face;
}

}  // namespace hlr::solid_detail
