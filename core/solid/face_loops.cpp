// One face: resolve its vertex ids, drop repeated vertices, split thesis-style loops into rings and
// on-face lines, pick the outer ring, fit the plane and check area, planarity and holes.
#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <unordered_map>
#include <unordered_set>

#include "core/solid/builder_detail.hpp"

namespace hlr::solid_detail {
namespace {

std::uint64_t directed_key(VertexIndex a, VertexIndex b) { return (std::uint64_t{a} << 32) | b; }

struct Split {
  bool shared = false;    // a vertex on two loops, or twice on one: the loops were split into `rings`
  bool repeated = false;  // a directed edge left over more than once
  VertexIndex repeated_a = 0, repeated_b = 0;
};

// Splits closed loops into rings and on-face lines. Without a shared vertex nothing can cancel and the
// loops are the rings (left in `loops`). Otherwise, an undirected edge traversed both ways is a line on
// the face (Desens' bridges to holes and deck markings): its opposite traversals cancel in pairs. The
// directed edges left over still enter and leave every vertex equally often, so they decompose into
// closed rings; we walk them and cut a ring off whenever the walk returns to a vertex already on the
// current path, so no ring repeats a vertex. Which outgoing edge is taken at a vertex with several does
// not matter: containment is even-odd over all rings.
Split split_loops(const Loops& loops, Loops& rings, std::vector<std::pair<VertexIndex, VertexIndex>>& lines,
                  std::vector<VertexIndex>& scratch) {
  Split out;
  lines.clear();
  scratch.assign(loops.vertices.begin(), loops.vertices.end());
  std::sort(scratch.begin(), scratch.end());
  if (std::adjacent_find(scratch.begin(), scratch.end()) == scratch.end()) return out;
  out.shared = true;
  rings.clear();

  struct Directed {
    VertexIndex a, b;
  };
  std::vector<Directed> directed;
  std::unordered_map<std::uint64_t, int> count;
  for (std::size_t k = 0; k < loops.size(); ++k) {
    const std::span<const VertexIndex> l = loops[k];
    for (std::size_t i = 0; i < l.size(); ++i) {
      directed.push_back({l[i], l[(i + 1) % l.size()]});
      ++count[directed_key(l[i], l[(i + 1) % l.size()])];
    }
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
      if (line_seen.insert(directed_key(lo, hi)).second) lines.emplace_back(lo, hi);
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
    std::vector<VertexIndex> path{kept[start].a};
    std::unordered_map<VertexIndex, std::size_t> position{{kept[start].a, 0}};
    std::size_t edge = start;
    while (edge < kept.size()) {
      used[edge] = true;
      const VertexIndex v = kept[edge].b;
      if (auto it = position.find(v); it != position.end()) {
        const std::size_t k = it->second;
        rings.vertices.insert(rings.vertices.end(), path.begin() + static_cast<std::ptrdiff_t>(k),
                              path.end());
        rings.close();
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
    return std::array<double, 4>{std::min(p.x, q.x), std::min(p.y, q.y), std::max(p.x, q.x),
                                 std::max(p.y, q.y)};
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

// The diagonal of the bounding box of the vertices a face names: the scale of its tolerances.
double face_extent(const std::vector<Point3>& pos, std::span<const VertexIndex> named) {
  Point3 lo = pos[named[0]], hi = pos[named[0]];
  for (VertexIndex v : named) {
    lo = {std::min(lo.x, pos[v].x), std::min(lo.y, pos[v].y), std::min(lo.z, pos[v].z)};
    hi = {std::max(hi.x, pos[v].x), std::max(hi.y, pos[v].y), std::max(hi.z, pos[v].z)};
  }
  return distance(lo, hi);
}

// Twice the area against the size squared: below kRelative, the normal is rounding noise.
bool has_area(double twice_area, double face_size) {
  return !(twice_area <= Tolerance::for_extent(face_size).length * face_size);
}

// The common face — one loop of three distinct vertices — as prepare_face would leave it, by the same
// functions in the same order (the same bits): it needs none of the cleaning, splitting and hole checks.
// False, touching nothing the general path does not set again, when its area is too small: the general
// path then reports it.
bool prepare_triangle(FaceWork& work, VertexIndex a, VertexIndex b, VertexIndex c,
                      const std::vector<Point3>& pos) {
  work.rings.clear();
  work.rings.push_back(Ring{SmallVector<VertexIndex, 4>{a, b, c}, {}});
  const Ring& ring = work.rings[0];
  const Vector3 normal = newell_normal(pos, ring);
  const double size = face_extent(pos, std::span<const VertexIndex>(ring.vertices.data(), 3));
  if (!has_area(length(normal), size)) return false;
  work.lines.clear();
  work.rings_are_loops = true;
  work.size = size;
  work.plane = newell_plane(pos, ring, normal);
  work.area = normal;
  return true;
}

}  // namespace

bool prepare_face(FaceWork& work, bool from_loop, int number, std::int64_t tag, const VertexTable& vertices,
                  const SolidBuildOptions& options, Diagnostics& diagnostics) {
  if (work.loops.size() == 1 && work.loops.ends[0] == 3) {
    const VertexIndex a = work.loops.vertices[0], b = work.loops.vertices[1], c = work.loops.vertices[2];
    if (a != b && b != c && c != a && prepare_triangle(work, a, b, c, vertices.positions())) return true;
  }
  // Names are made only for messages: most faces have none.
  auto name = [&] { return "face " + std::to_string(number); };
  auto ring_name = [&](std::size_t k) {
    return k == 0 ? name() : "hole " + std::to_string(k) + " of " + name();
  };

  // Drop a vertex repeated in a row (also last = first): it adds no edge.
  Loops& clean = work.scratch_loops;
  clean.clear();
  std::vector<VertexIndex>& cv = clean.vertices;
  for (std::size_t k = 0; k < work.loops.size(); ++k) {
    auto warn = [&](VertexIndex v) {
      diagnostics.warning(
          "repeated-vertex",
          ring_name(k) + " lists vertex " + quoted(vertices.id(v)) + " twice in a row; dropped the repeat",
          tag);
    };
    const std::size_t begin = cv.size();
    for (VertexIndex v : work.loops[k]) {
      if (cv.size() > begin && cv.back() == v) {
        warn(v);
        continue;
      }
      cv.push_back(v);
    }
    while (cv.size() > begin + 1 && cv.back() == cv[begin]) {
      warn(cv.back());
      cv.pop_back();
    }
    clean.close();
  }
  std::swap(work.loops, clean);
  const Loops& loops = work.loops;  // from here on also the face's traversal: fixes edge order

  bool enough = true, repeats = loops.size() > 1;  // repeats: some vertex is named twice
  for (std::size_t k = 0; k < loops.size(); ++k) {
    // Cleaned, a ring of three names three distinct vertices (the common triangle skips the sort).
    auto n = static_cast<std::ptrdiff_t>(loops[k].size());
    if (n != 3) {
      std::vector<VertexIndex>& distinct = work.scratch;
      distinct.assign(loops[k].begin(), loops[k].end());
      std::sort(distinct.begin(), distinct.end());
      n = std::unique(distinct.begin(), distinct.end()) - distinct.begin();
      repeats = repeats || n != static_cast<std::ptrdiff_t>(loops[k].size());
    }
    if (n < 3) {
      enough = false;
      diagnostics.error("too-few-vertices",
                        ring_name(k) + " has only " + std::to_string(n) + " distinct vertices; " +
                            (k == 0 ? "a face" : "a hole") + " needs at least 3",
                        tag);
    }
  }
  if (!enough) return false;

  work.lines.clear();
  const Split split = repeats ? split_loops(loops, work.scratch_loops, work.lines, work.scratch) : Split{};
  const Loops& split_rings = split.shared ? work.scratch_loops : loops;
  if (split.repeated) {
    diagnostics.error("non-manifold-edge",
                      name() + " runs along edge " + edge_name(vertices, split.repeated_a, split.repeated_b) +
                          " twice in the same direction; each edge may appear once in a face's boundary",
                      tag);
    return false;
  }
  if (split_rings.size() == 0) {
    diagnostics.error("zero-area",
                      name() + " has zero area: every edge of its " + (from_loop ? "loop" : "rings") +
                          " is traversed in both directions",
                      tag);
    return false;
  }

  // The outer ring encloses the others, so it has the largest area (for loops this is how it is found).
  // The rings are allocated at their final size: they move into the solid.
  const std::vector<Point3>& pos = vertices.positions();
  SmallVector<Ring, 1>& rings = work.rings;
  rings.clear();
  rings.reserve(split_rings.size());
  std::vector<double>& twice_area = work.areas;
  twice_area.clear();
  std::size_t outer = 0;  // the first of the largest
  Vector3 outer_normal{};
  for (std::size_t k = 0; k < split_rings.size(); ++k) {
    const std::span<const VertexIndex> l = split_rings[k];
    rings.push_back(Ring{SmallVector<VertexIndex, 4>(l.begin(), l.end()), {}});
    const Vector3 normal = newell_normal(pos, rings.back());
    twice_area.push_back(length(normal));
    if (k == 0 || twice_area[outer] < twice_area[k]) {
      outer = k;
      outer_normal = normal;
    }
  }
  std::rotate(rings.begin(), rings.begin() + static_cast<std::ptrdiff_t>(outer),
              rings.begin() + static_cast<std::ptrdiff_t>(outer) + 1);
  std::rotate(twice_area.begin(), twice_area.begin() + static_cast<std::ptrdiff_t>(outer),
              twice_area.begin() + static_cast<std::ptrdiff_t>(outer) + 1);
  work.rings_are_loops = !split.shared && outer == 0;

  // Every vertex the face names, for its size and the planarity check (a one-ring face's are its ring's,
  // the common case, read in place).
  std::vector<VertexIndex>& gathered = work.scratch;
  gathered.clear();
  if (rings.size() > 1 || !work.lines.empty()) {
    for (const Ring& r : rings) gathered.insert(gathered.end(), r.vertices.begin(), r.vertices.end());
    for (const auto& [a, b] : work.lines) gathered.insert(gathered.end(), {a, b});
  }
  const std::span<const VertexIndex> named =
      gathered.empty() ? std::span<const VertexIndex>(rings[0].vertices.data(), rings[0].vertices.size())
                       : std::span<const VertexIndex>(gathered);
  const double face_size = face_extent(pos, named);
  work.size = face_size;
  if (!has_area(twice_area[0], face_size)) {
    diagnostics.error("zero-area", name() + " has zero area", tag);
    return false;
  }

  // Plane of the outer ring (holes do not change it); every named vertex must lie on it.
  const Plane plane = newell_plane(pos, rings[0], outer_normal);
  // Three points lie on their plane: a triangle's deviations are rounding, not warp (far from the origin
  // they could even exceed the tolerance), so only larger faces are measured.
  double worst = -1;
  VertexIndex worst_vertex = 0;
  if (named.size() > 3)
    for (VertexIndex v : named) {
      const double dev = std::abs(plane.signed_distance(pos[v]));
      if (dev > worst) {
        worst = dev;
        worst_vertex = v;
      }
    }
  const double allowed = options.planarity_tolerance * face_size;
  if (worst > Tolerance::kPlanarity * face_size) {  // messages are built only when needed
    const std::string deviation = name() + " is not planar: vertex " + vertices.id(worst_vertex) + " lies " +
                                  format_for_message(worst) + " off the face's mean plane";
    if (worst > allowed) {
      diagnostics.error("non-planar",
                        deviation + " (tolerance " + format_for_message(options.planarity_tolerance) +
                            " × face size); split it into planar faces",
                        tag);
      return false;
    }
    diagnostics.warning("non-planar",
                        deviation + " (more than " + format_for_message(Tolerance::kPlanarity) +
                            " × face size, accepted by the planarity tolerance " +
                            format_for_message(options.planarity_tolerance) +
                            "); drawings may be slightly off near it",
                        tag);
  }

  // Holes: each inside the outer ring, no two rings crossing; orientation by nesting depth.
  if (rings.size() > 1) {
    const FaceFrame frame = FaceFrame::from_normal(plane.normal, pos[rings[0].vertices[0]]);
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
        diagnostics.warning("bad-hole", what + "; kept it: the face is the even-odd region of its rings",
                            tag);
      } else {
        diagnostics.error("bad-hole", what + "; " + rule, tag);
        holes_ok = false;
      }
    };
    for (std::size_t k = 1; k < rings.size(); ++k) {
      if (!has_area(twice_area[k], face_size)) {
        diagnostics.error("zero-area", ring_name(k) + " has zero area", tag);
        holes_ok = false;
        continue;
      }
      for (std::size_t i = 0; i < flat[k].size(); ++i)
        if (classify_point(flat[k][i], {flat[0]}, allowed) == Containment::Outside) {
          reported[k] = true;
          bad_hole(ring_name(k) + " is not inside the face: vertex " +
                       quoted(vertices.id(rings[k].vertices[i])) + " lies outside its outer boundary",
                   "a hole must lie within the outer ring");
          break;
        }
    }
    for (std::size_t j = 1; j < rings.size(); ++j)
      for (std::size_t k = 0; k < j && !reported[j]; ++k) {
        std::size_t i = 0, m = 0;
        if (!first_crossing(flat[j], flat[k], allowed, i, m)) continue;
        reported[j] = true;
        const auto &ra = rings[j].vertices, &rb = rings[k].vertices;
        bad_hole(ring_name(j) + " crosses " + (k == 0 ? std::string("its outer boundary") : ring_name(k)) +
                     " (edges " + edge_name(vertices, ra[i], ra[(i + 1) % ra.size()]) + " and " +
                     edge_name(vertices, rb[m], rb[(m + 1) % rb.size()]) + ")",
                 "holes must lie inside the face without crossing its boundary or each other");
      }
    if (!holes_ok) return false;

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
      if ((signed_area(flat[k]) < 0) != want_clockwise) {
        std::reverse(rings[k].vertices.begin(), rings[k].vertices.end());
        work.rings_are_loops = false;
      }
    }
  }

  work.plane = plane;
  work.area = outer_normal;
  if (rings.size() > 1) {
    work.area = {};
    for (const Ring& r : rings) work.area += newell_normal(pos, r);
  }
  return true;
}

}  // namespace hlr::solid_detail
