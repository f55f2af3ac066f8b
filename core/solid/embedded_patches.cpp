#include "core/solid/embedded_patches.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <utility>

#include "core/geometry/exact_predicates.hpp"
#include "core/parallel.hpp"

namespace hlr {
namespace {

// Faces are grown into patches within runs of this many (in parallel, each run on its own), and a patch
// stops at kPatchFaces: larger patches leave fewer pairs across their borders to search, but have longer
// outlines to test and fail more often on a fold. Measured (bench/README.md, stop 48): 2 048 against 512
// takes a sixth off a smooth 10⁶-triangle torus's search; 8 192 fails on a scan's folds often enough to lose.
constexpr std::size_t kRunFaces = 8192;
constexpr std::size_t kPatchFaces = 2048;
// A neighbour joins a patch when its unit normal's component along the patch's axis exceeds this (about
// 75° from the axis): the projections stay wide, so outlines rarely graze. Any value is sound — the
// certificate decides exactly — this only keeps patches from being grown to fail.
constexpr double kGrowCosine = 0.25;
constexpr std::size_t kSmallestPatch = 8;
constexpr std::uint32_t kUnassigned = 0xfffffffeu;

Point2 project(Point3 p, int axis) {
  // Cyclic, so that a face whose normal points along +axis turns counter-clockwise.
  if (axis == 0) return {p.y, p.z};
  if (axis == 1) return {p.z, p.x};
  return {p.x, p.y};
}

// What growing and certifying read of a triangle, gathered in one pass over the faces in order: its
// vertices, the faces across its edges (kNoFace on an open border, kBadFace where the edge does not name
// it: a face folded onto itself) and on which sides of which axes its normal lies within the growth cone.
constexpr FaceIndex kBadFace = -2;
struct Triangle {
  VertexIndex v[3];
  FaceIndex across[3];
  std::uint8_t cones = 0;    // bit 2·axis + (normal along −axis): grows a patch of that axis and side
  std::uint8_t nearest = 0;  // the bit of the axis and side its normal lies nearest: a seed's patch's
  bool usable = false;       // one ring of three vertices, its edges linked
};

Triangle triangle_of(const Solid& solid, FaceIndex f) {
  Triangle t;
  const Face& face = solid.faces[static_cast<std::size_t>(f)];
  if (face.rings.size() != 1) return t;
  const Ring& r = face.rings[0];
  if (r.vertices.size() != 3 || r.edges.size() != 3) return t;
  for (int i = 0; i < 3; ++i) {
    if (r.edges[i] == kNoEdge) return t;
    const SolidEdge& e = solid.edges[r.edges[i]];
    t.v[i] = r.vertices[i];
    t.across[i] = e.left == e.right ? kBadFace : (e.left == f ? e.right : (e.right == f ? e.left : kBadFace));
  }
  const Vector3 n = solid.planes[static_cast<std::size_t>(f)].normal;
  const double along[3] = {n.x, n.y, n.z};
  int axis = 0;
  for (int a = 0; a < 3; ++a) {
    if (along[a] > kGrowCosine) t.cones |= static_cast<std::uint8_t>(1u << (2 * a));
    if (along[a] < -kGrowCosine) t.cones |= static_cast<std::uint8_t>(1u << (2 * a + 1));
    if (std::abs(along[a]) > std::abs(along[axis])) axis = a;
  }
  t.nearest = static_cast<std::uint8_t>(1u << (2 * axis + (along[axis] < 0 ? 1 : 0)));
  t.usable = true;
  return t;
}

// Whether triangle t runs from a to b.
bool runs(const Triangle& t, VertexIndex a, VertexIndex b) {
  return (t.v[0] == a && t.v[1] == b) || (t.v[1] == a && t.v[2] == b) || (t.v[2] == a && t.v[0] == b);
}

// Whether p, collinear with a and b, lies on the closed segment ab (coordinate comparisons: exact).
bool within(Point2 a, Point2 b, Point2 p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

// Whether the closed segments ab and cd share a point, exactly.
bool segments_meet(Point2 a, Point2 b, Point2 c, Point2 d) {
  const int o1 = orient2d(a, b, c), o2 = orient2d(a, b, d), o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && within(a, b, c)) || (o2 == 0 && within(a, b, d)) || (o3 == 0 && within(c, d, a)) ||
         (o4 == 0 && within(c, d, b));
}

// Buffers reused from patch to patch.
struct Scratch {
  struct Border {
    VertexIndex from, to;
  };
  std::vector<Border> border;
  std::vector<std::uint32_t> next, order;
  std::vector<char> walked;
  std::vector<Point2> from, to;
};

// The certificate of embedded_patches.hpp for triangles `faces` along `axis`: tri(f) gives face f's
// Triangle, in_patch(g) whether face g is one of them.
template <typename Tri, typename InPatch>
bool certify(const Solid& solid, std::span<const FaceIndex> faces, int axis, const Tri& tri,
             const InPatch& in_patch, Scratch& s) {
  if (faces.empty()) return false;
  s.border.clear();
  int sign = 0;
  for (const FaceIndex f : faces) {
    const Triangle& t = tri(f);
    if (!t.usable) return false;
    const VertexIndex* v = t.v;
    // (1) One strict orientation, exactly.
    const int turn = orient2d(project(solid.vertices[v[0]], axis), project(solid.vertices[v[1]], axis),
                              project(solid.vertices[v[2]], axis));
    if (turn == 0 || (sign != 0 && turn != sign)) return false;
    sign = turn;
    for (int i = 0; i < 3; ++i) {
      const FaceIndex g = t.across[i];
      if (g == kBadFace) return false;
      const VertexIndex a = v[i], b = v[(i + 1) % 3];
      if (g != kNoFace && in_patch(g)) {
        if (!runs(tri(g), b, a)) return false;  // (2) inconsistent neighbours do not cancel
      } else {
        s.border.push_back({a, b});
      }
    }
  }
  // (3) Loops: each border vertex starts exactly one border edge, and following them comes back round.
  const std::size_t n = s.border.size();
  if (n < 3) return false;
  std::sort(s.border.begin(), s.border.end(),
            [](const Scratch::Border& x, const Scratch::Border& y) { return x.from < y.from; });
  for (std::size_t i = 1; i < n; ++i)
    if (s.border[i].from == s.border[i - 1].from) return false;  // a vertex the border passes twice
  s.next.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const VertexIndex to = s.border[i].to;
    const auto it = std::lower_bound(s.border.begin(), s.border.end(), to,
                                     [](const Scratch::Border& e, VertexIndex v) { return e.from < v; });
    if (it == s.border.end() || it->from != to) return false;
    s.next[i] = static_cast<std::uint32_t>(it - s.border.begin());
  }
  // Their projections are simple: no edge of no length, no edge doubling back over the one before, and
  // (below) no two edges that do not follow each other sharing a point.
  s.from.resize(n);
  s.to.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    s.from[i] = project(solid.vertices[s.border[i].from], axis);
    s.to[i] = project(solid.vertices[s.border[i].to], axis);
    if (s.from[i] == s.to[i]) return false;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 a = s.from[i], b = s.to[i], c = s.to[s.next[i]];
    if (orient2d(a, b, c) != 0) continue;
    // Collinear: it doubles back when c lies on a's side of b, told by comparisons alone.
    const bool back = a.x != b.x ? (b.x > a.x) != (c.x > b.x) : (b.y > a.y) != (c.y > b.y);
    if (back) return false;
  }
  // Disjoint simple loops cover the plane once inside each: the triangles cover a point at most once when
  // exactly one loop turns as they do (the outline) and every other the other way (holes). A loop's turn
  // is that at its lowest point (least x, then y), a corner where it cannot run straight on.
  s.walked.assign(n, 0);
  int outlines = 0;
  for (std::size_t start = 0; start < n; ++start) {
    if (s.walked[start]) continue;
    std::size_t low = start, at = start;
    std::size_t steps = 0;
    do {
      s.walked[at] = 1;
      const Point2 p = s.to[at], q = s.to[low];
      if (p.x < q.x || (p.x == q.x && p.y < q.y)) low = at;
      at = s.next[at];
      if (++steps > n) return false;
    } while (at != start);
    // The turn at to[low], from edge low to the next.
    const int turn = orient2d(s.from[low], s.to[low], s.to[s.next[low]]);
    if (turn == sign) {
      if (++outlines > 1) return false;
    } else if (turn != -sign) {
      return false;
    }
  }
  if (outlines != 1) return false;
  // Pairs whose boxes overlap, swept along x.
  s.order.resize(n);
  for (std::size_t i = 0; i < n; ++i) s.order[i] = static_cast<std::uint32_t>(i);
  auto min_x = [&](std::uint32_t i) { return std::min(s.from[i].x, s.to[i].x); };
  std::sort(s.order.begin(), s.order.end(),
            [&](std::uint32_t x, std::uint32_t y) { return min_x(x) < min_x(y); });
  for (std::size_t p = 0; p < n; ++p) {
    const std::uint32_t i = s.order[p];
    const double reach = std::max(s.from[i].x, s.to[i].x);
    const double ylo = std::min(s.from[i].y, s.to[i].y), yhi = std::max(s.from[i].y, s.to[i].y);
    for (std::size_t q = p + 1; q < n && min_x(s.order[q]) <= reach; ++q) {
      const std::uint32_t j = s.order[q];
      if (std::max(s.from[j].y, s.to[j].y) < ylo || std::min(s.from[j].y, s.to[j].y) > yhi) continue;
      if (s.next[i] == j || s.next[j] == i) continue;  // they meet at their common vertex (checked above)
      if (segments_meet(s.from[i], s.to[i], s.from[j], s.to[j])) return false;
    }
  }
  return true;
}

}  // namespace

bool projects_one_to_one(const Solid& solid, std::span<const FaceIndex> faces, int axis) {
  std::vector<FaceIndex> sorted(faces.begin(), faces.end());
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;
  std::vector<Triangle> triangles(solid.faces.size());
  for (std::size_t f = 0; f < solid.faces.size(); ++f)
    triangles[f] = triangle_of(solid, static_cast<FaceIndex>(f));
  Scratch scratch;
  return certify(
      solid, faces, axis,
      [&](FaceIndex f) -> const Triangle& { return triangles[static_cast<std::size_t>(f)]; },
      [&](FaceIndex g) { return std::binary_search(sorted.begin(), sorted.end(), g); }, scratch);
}

std::vector<std::uint32_t> embedded_patches(const Solid& solid) {
  const std::size_t n = solid.faces.size();
  std::vector<std::uint32_t> patch(n, kUnassigned);
  parallel_chunks((n + kRunFaces - 1) / kRunFaces, threads_for(n, 2 * kRunFaces, 0), [&](std::size_t k) {
    // Faces of this run only are read and written: a neighbour beyond it is outside every patch grown here.
    const std::size_t lo = k * kRunFaces, hi = std::min(n, (k + 1) * kRunFaces);
    auto in_run = [&](FaceIndex g) {
      return g >= 0 && static_cast<std::size_t>(g) >= lo && static_cast<std::size_t>(g) < hi;
    };
    std::vector<Triangle> triangles(hi - lo);
    for (std::size_t f = lo; f < hi; ++f) triangles[f - lo] = triangle_of(solid, static_cast<FaceIndex>(f));
    auto tri = [&](FaceIndex f) -> const Triangle& { return triangles[static_cast<std::size_t>(f) - lo]; };
    Scratch scratch;
    std::vector<FaceIndex> members;
    for (std::size_t seed = lo; seed < hi; ++seed) {
      if (patch[seed] != kUnassigned) continue;
      const Triangle& t = triangles[seed - lo];
      if (!t.usable || (t.cones & t.nearest) == 0) {  // no normal to speak of
        patch[seed] = kNoPatch;
        continue;
      }
      const std::uint8_t cone = t.nearest;  // the patch grows along the axis the seed's normal lies nearest
      const int axis = std::countr_zero(cone) / 2;
      const auto id = static_cast<std::uint32_t>(seed);
      // The largest patch round the seed that is certified: a patch that fails (a fold, an ear seen edge
      // on) is grown again smaller.
      bool sound = false;
      for (std::size_t cap = kPatchFaces; !sound && cap >= kSmallestPatch; cap /= 4) {
        for (const FaceIndex m : members) patch[static_cast<std::size_t>(m)] = kUnassigned;
        members.assign(1, static_cast<FaceIndex>(seed));
        patch[seed] = id;
        for (std::size_t head = 0; head < members.size() && members.size() < cap; ++head) {
          const Triangle& h = tri(members[head]);
          for (int i = 0; i < 3 && members.size() < cap; ++i) {
            const FaceIndex g = h.across[i];
            if (!in_run(g) || patch[static_cast<std::size_t>(g)] != kUnassigned) continue;
            const Triangle& next = tri(g);
            if (!next.usable || (next.cones & cone) == 0) continue;
            patch[static_cast<std::size_t>(g)] = id;
            members.push_back(g);
          }
        }
        sound =
            members.size() > 1 &&
            certify(
                solid, members, axis, tri,
                [&](FaceIndex g) { return in_run(g) && patch[static_cast<std::size_t>(g)] == id; }, scratch);
      }
      if (!sound) {
        for (const FaceIndex m : members) patch[static_cast<std::size_t>(m)] = kUnassigned;
        patch[seed] = kNoPatch;
      }
      members.clear();
    }
  });
  return patch;
}

}  // namespace hlr
