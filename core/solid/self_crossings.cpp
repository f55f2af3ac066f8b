// Where faces of one solid cross: an assembly exported as one mesh, a scan that folds through itself.
// Pairs of faces that may meet come from a uniform grid over the faces' boxes (cells about the size of
// a typical face, so the work follows the number of nearby pairs, not the square of the face count);
// each pair is then rejected cheaply by its planes or solved exactly as two solids' faces are. Faces that
// share an edge meet along it and nowhere else; faces that share one vertex may still pass through each
// other from that vertex on (a fold through a fan, two sheets welded at a point), which for triangles is
// decided by exact orientation predicates (corner_crossing).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/geometry/box3.hpp"
#include "core/geometry/exact_crossing.hpp"
#include "core/geometry/exact_predicates.hpp"
#include "core/parallel.hpp"
#include "core/solid/face_crossing.hpp"
#include "core/solid/solid.hpp"
#include "core/tolerance.hpp"

namespace hlr {
namespace {

// A grid entry (one face in one cell) packed in 64 bits: the cell's 30 bits (x | y << 10 | z << 20) on top,
// then three bits telling on which axes the cell is the first the face's box reaches, then the face's 31.
// Of two faces in a cell, their pair belongs to the cell where both boxes have begun on every axis — the
// cell whose coordinate on each axis is one of the two faces' first — and the flags tell that without
// looking either face up (half the pairs met in a cell belong to another).
constexpr int kCellShift = 34, kFirstShift = 31;
constexpr std::uint64_t kFaceMask = 0x7fffffffu;
std::uint64_t cell_of(std::uint64_t entry) { return entry >> kCellShift; }
FaceIndex face_of(std::uint64_t entry) { return static_cast<FaceIndex>(entry & kFaceMask); }
bool pair_is_met_here(std::uint64_t a, std::uint64_t b) { return (((a | b) >> kFirstShift) & 7) == 7; }

// Sorts entries by their cell, keeping the face order within a cell, which they were made in: two stable
// counting passes of 15 bits — linear, where a comparison sort was the finder's largest cost.
void sort_by_cell(std::vector<std::uint64_t>& entries) {
  std::vector<std::uint64_t> buffer(entries.size());
  std::vector<std::uint32_t> counts(1u << 15);
  for (const int shift : {kCellShift, kCellShift + 15}) {
    std::fill(counts.begin(), counts.end(), 0u);
    for (std::uint64_t e : entries) ++counts[(e >> shift) & 0x7fff];
    std::uint32_t sum = 0;
    for (std::uint32_t& c : counts) sum += std::exchange(c, sum);
    for (std::uint64_t e : entries) buffer[counts[(e >> shift) & 0x7fff]++] = e;
    entries.swap(buffer);
  }
}

// Per face, what the pair tests read, in one cache line: its box and, for a face of one ring of up to four
// vertices (the common case), its vertices, the first repeated to fill four (repeats match nothing new),
// so that telling neighbours apart touches no other memory. A larger face has v[0] = kLarge and v[1] the
// index of its sorted vertices in Finder::big_.
constexpr VertexIndex kLarge = ~VertexIndex{0};
struct alignas(64) FaceInfo {
  Box3 box;
  VertexIndex v[4] = {0, 0, 0, 0};
  bool small() const { return v[0] != kLarge; }
};

class Finder {
 public:
  explicit Finder(const Solid& solid) : solid_(solid) {
    double extent = 0;
    for (Point3 p : solid.vertices) extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    tol_ = Tolerance::for_extent(extent).length;
    info_.resize(solid.faces.size());
    warp_.assign(solid.faces.size(), 0.0);
    for (std::size_t f = 0; f < solid.faces.size(); ++f) {
      const Face& face = solid.faces[f];
      FaceInfo& info = info_[f];
      for (const Ring& ring : face.rings)
        for (VertexIndex v : ring.vertices) {
          info.box.include(solid.vertices[v]);
          warp_[f] = std::max(warp_[f], std::abs(solid.planes[f].signed_distance(solid.vertices[v])));
        }
      const auto& outer = face.rings[0].vertices;
      if (face.rings.size() == 1 && outer.size() <= 4) {
        std::copy(outer.begin(), outer.end(), info.v);
        std::fill(info.v + outer.size(), info.v + 4, outer[0]);
      } else {  // sorted once: a large face meets many neighbours
        big_.emplace_back();
        info.v[0] = kLarge;
        info.v[1] = static_cast<VertexIndex>(big_.size() - 1);
        for (const Ring& ring : face.rings)
          big_.back().insert(big_.back().end(), ring.vertices.begin(), ring.vertices.end());
        std::sort(big_.back().begin(), big_.back().end());
      }
    }
  }

  // What one thread finds, with its own buffers.
  struct Part {
    std::vector<std::uint64_t> cell;  // a crowded cell's entries, for the sweep
    FaceCrossingScratch scratch;
    std::vector<CrossingPiece> pieces;
    std::vector<SelfCrossing> found;
  };

  // Examines one pair of faces; appends what crosses.
  void pair(FaceIndex a, FaceIndex b, Part& part) const {
    if (a > b) std::swap(a, b);
    const FaceInfo& ia = info_[a];
    const FaceInfo& ib = info_[b];
    if (!ia.box.overlaps(ib.box, tol_)) return;
    const int shared = shared_vertices(ia, ib);
    if (shared >= 2) return;  // neighbours along an edge (or more): they meet there, not across
    if (shared == 1 && is_triangle(a) && is_triangle(b)) return;  // fan_pairs decides these
    if (shared == 1 && ia.small() && ib.small()) {
      // Faces round one vertex (the quads of a grid, diagonally): most lie beyond each other's planes
      // everywhere but there, and meet at that point only.
      const VertexIndex at = common_vertex(ia, ib);
      if (leaves_plane_from(solid_.planes[a], ib, at) || leaves_plane_from(solid_.planes[b], ia, at)) return;
    }
    // A face its solid's options let off plane (legacy data) is only known to within its warp: crossings
    // that small are noise.
    const double tol = tol_ + warp_[a] + warp_[b];
    if (!face_meets_plane(solid_, b, solid_.planes[a], tol) ||
        !face_meets_plane(solid_, a, solid_.planes[b], tol))
      return;
    part.pieces.clear();
    face_crossings(solid_, a, solid_, b, tol, part.scratch, part.pieces);
    for (const CrossingPiece& p : part.pieces) part.found.push_back({p.p0, p.p1, a, b});
  }

  std::vector<SelfCrossing> all_pairs() const {
    Part part;
    const auto n = static_cast<FaceIndex>(solid_.faces.size());
    for (FaceIndex a = 0; a < n; ++a)
      for (FaceIndex b = a + 1; b < n; ++b) pair(a, b, part);
    return std::move(part.found);
  }

  // Triangles that share one vertex, met vertex by vertex: each vertex's fan is read once, where the grid
  // would fetch the same few triangles again for every pair. Vertices are shared out over the cores.
  std::vector<SelfCrossing> fan_pairs() const {
    const std::size_t nv = solid_.vertices.size(), nf = info_.size();
    std::vector<std::uint32_t> first(nv + 1, 0);
    for (std::size_t f = 0; f < nf; ++f)
      if (is_triangle(static_cast<FaceIndex>(f)))
        for (int k = 0; k < 3; ++k) ++first[info_[f].v[k] + 1];
    for (std::size_t v = 0; v < nv; ++v) first[v + 1] += first[v];
    std::vector<FaceIndex> fan(first[nv]);
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::size_t f = 0; f < nf; ++f)
      if (is_triangle(static_cast<FaceIndex>(f)))
        for (int k = 0; k < 3; ++k) fan[fill[info_[f].v[k]]++] = static_cast<FaceIndex>(f);
    constexpr std::size_t kChunk = 8192;
    std::vector<Part> parts((nv + kChunk - 1) / kChunk);
    parallel_chunks(parts.size(), threads_for(fan.size(), 50000, 0), [&](std::size_t k) {
      Part& part = parts[k];
      std::vector<FanTriangle> round;
      for (std::size_t v = k * kChunk; v < std::min(nv, (k + 1) * kChunk); ++v) {
        if (first[v + 1] - first[v] < 2) continue;
        round.clear();
        for (std::uint32_t i = first[v]; i < first[v + 1]; ++i) {
          const VertexIndex* ring = info_[fan[i]].v;
          const int at = ring[0] == v ? 0 : (ring[1] == v ? 1 : 2);
          const VertexIndex i1 = ring[(at + 1) % 3], i2 = ring[(at + 2) % 3];
          round.push_back({fan[i], i1, i2, solid_.vertices[i1], solid_.vertices[i2], solid_.planes[fan[i]]});
        }
        const Point3 V = solid_.vertices[v];
        for (std::size_t i = 0; i < round.size(); ++i)
          for (std::size_t j = i + 1; j < round.size(); ++j) {
            const FanTriangle &x = round[i], &y = round[j];
            // Triangles sharing a second vertex share an edge: they meet along it, not across.
            if (x.i1 == y.i1 || x.i1 == y.i2 || x.i2 == y.i1 || x.i2 == y.i2) continue;
            corner_crossing(x, y, V, part);
          }
      }
    });
    std::vector<SelfCrossing> found;
    for (Part& part : parts) found.insert(found.end(), part.found.begin(), part.found.end());
    return found;
  }

  // The grid: cells of the median face size (at least 1/1000 of the solid's size on each axis, so cell
  // numbers fit 10 bits); a face covering more than kMaxCells cells is met against every face instead.
  // Cells are shared out over the cores; what each finds is joined in cell order.
  std::vector<SelfCrossing> grid_pairs() {
    const std::size_t n = info_.size();
    Box3 all;
    std::vector<double> sizes(n);
    for (std::size_t f = 0; f < n; ++f) {
      all.include(info_[f].box.lo);
      all.include(info_[f].box.hi);
      sizes[f] = info_[f].box.largest_side();
    }
    std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(n / 2), sizes.end());
    const double cell = std::max({sizes[n / 2], all.largest_side() / 1000, tol_, Tolerance::kFloor});
    auto index = [&](double v, double origin) {
      return static_cast<std::uint16_t>(std::clamp(std::floor((v - origin) / cell), 0.0, 1023.0));
    };
    // One entry per (cell, face), packed as above, so a sort groups each cell's faces in face order. Room
    // for eight cells a face (a box at most a cell wide on each axis): only what is written is touched.
    std::vector<std::uint64_t> entries;
    entries.reserve(n * 8);
    std::vector<FaceIndex> big;
    constexpr int kMaxCells = 64;
    for (std::size_t f = 0; f < n; ++f) {
      const Box3& b = info_[f].box;
      std::uint16_t lo[3], hi[3];
      lo[0] = index(b.lo.x - tol_, all.lo.x), hi[0] = index(b.hi.x + tol_, all.lo.x);
      lo[1] = index(b.lo.y - tol_, all.lo.y), hi[1] = index(b.hi.y + tol_, all.lo.y);
      lo[2] = index(b.lo.z - tol_, all.lo.z), hi[2] = index(b.hi.z + tol_, all.lo.z);
      const int cells = (hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
      if (cells > kMaxCells) {
        big.push_back(static_cast<FaceIndex>(f));
        continue;
      }
      for (std::uint64_t x = lo[0]; x <= hi[0]; ++x)
        for (std::uint64_t y = lo[1]; y <= hi[1]; ++y)
          for (std::uint64_t z = lo[2]; z <= hi[2]; ++z) {
            const std::uint64_t first =
                (x == lo[0] ? 1u : 0u) | (y == lo[1] ? 2u : 0u) | (z == lo[2] ? 4u : 0u);
            entries.push_back(((x | (y << 10) | (z << 20)) << kCellShift) | first << kFirstShift | f);
          }
    }
    sort_by_cell(entries);
    // Chunks of whole cells, about kChunk entries each.
    constexpr std::size_t kChunk = 4096;
    std::vector<std::size_t> bounds{0};
    for (std::size_t i = kChunk; i < entries.size(); i += kChunk) {
      while (i < entries.size() && cell_of(entries[i]) == cell_of(entries[i - 1])) ++i;
      if (i < entries.size() && i > bounds.back()) bounds.push_back(i);
    }
    bounds.push_back(entries.size());
    std::vector<Part> parts(bounds.size() - 1);
    parallel_chunks(parts.size(), threads_for(entries.size(), 50000, 0), [&](std::size_t k) {
      Part& part = parts[k];
      for (std::size_t i = bounds[k]; i < bounds[k + 1];) {
        const std::uint64_t cell = cell_of(entries[i]);
        std::size_t end = i + 1;
        while (end < bounds[k + 1] && cell_of(entries[end]) == cell) ++end;
        // A pair sharing several cells is examined in one of them only.
        auto visit = [&](std::uint64_t a, std::uint64_t b) {
          if (pair_is_met_here(a, b)) pair(face_of(a), face_of(b), part);
        };
        if (end - i > kSweepAbove) {
          sweep_cell(entries, i, end, part.cell, visit);
        } else {
          for (std::size_t p = i; p < end; ++p)
            for (std::size_t q = p + 1; q < end; ++q) visit(entries[p], entries[q]);
        }
        i = end;
      }
    });
    std::vector<SelfCrossing> found;
    for (Part& part : parts) found.insert(found.end(), part.found.begin(), part.found.end());
    Part rest;
    std::vector<char> is_big(n, 0);
    for (FaceIndex f : big) is_big[f] = 1;
    for (FaceIndex f : big)
      for (std::size_t g = 0; g < n; ++g)
        if (!is_big[g] || static_cast<FaceIndex>(g) > f) pair(f, static_cast<FaceIndex>(g), rest);
    found.insert(found.end(), rest.found.begin(), rest.found.end());
    return found;
  }

 private:
  // A cell holding more faces than this is swept, not paired all with all: faces much longer than the
  // median (the sides of a many-sided prism, as tall as the cells are wide) crowd into a few cells.
  static constexpr std::size_t kSweepAbove = 32;

  // Calls visit(a, b) (two of the cell's entries) for the pairs of the cell's faces whose boxes overlap
  // along the axis where they overlap least: sorted by the box's low end on it, each face meets the
  // faces starting before its box ends.
  template <typename Visit>
  void sweep_cell(const std::vector<std::uint64_t>& entries, std::size_t begin, std::size_t end,
                  std::vector<std::uint64_t>& cell, Visit&& visit) const {
    cell.assign(entries.begin() + static_cast<std::ptrdiff_t>(begin),
                entries.begin() + static_cast<std::ptrdiff_t>(end));
    int axis = 0;
    double best = -1;
    for (int k = 0; k < 3; ++k) {  // overlaps expected ∝ total box length / the range they spread over
      const Box3& first = info_[face_of(cell[0])].box;
      double length = 0, lo = first.lo[k], hi = first.hi[k];
      for (std::uint64_t e : cell) {
        const Box3& b = info_[face_of(e)].box;
        length += b.hi[k] - b.lo[k];
        lo = std::min(lo, b.lo[k]);
        hi = std::max(hi, b.hi[k]);
      }
      const double score = (hi - lo) / std::max(length, Tolerance::kFloor);
      if (score > best) best = score, axis = k;
    }
    std::sort(cell.begin(), cell.end(), [&](std::uint64_t a, std::uint64_t b) {
      const double la = info_[face_of(a)].box.lo[axis], lb = info_[face_of(b)].box.lo[axis];
      return la < lb || (la == lb && face_of(a) < face_of(b));
    });
    for (std::size_t p = 0; p < cell.size(); ++p) {
      const double reach = info_[face_of(cell[p])].box.hi[axis] + 2 * tol_;
      for (std::size_t q = p + 1; q < cell.size() && info_[face_of(cell[q])].box.lo[axis] <= reach; ++q)
        visit(cell[p], cell[q]);
    }
  }

  // A triangle's fourth slot repeats its first vertex (a quad's holds its own fourth).
  bool is_triangle(FaceIndex f) const { return info_[f].small() && info_[f].v[3] == info_[f].v[0]; }

  // How many vertices faces a and b share, counting to two (an edge).
  int shared_vertices(const FaceInfo& ia, const FaceInfo& ib) const {
    // Most pairs met are neighbours: the padded four against four, without branches.
    if (ia.small() && ib.small()) {
      int count = 0;
      for (int i = 0; i < 4; ++i) {
        const VertexIndex v = ia.v[i];
        const bool own = i == 0 || v != ia.v[0];  // padding repeats the first vertex
        count += own && (v == ib.v[0] || v == ib.v[1] || v == ib.v[2] || v == ib.v[3]);
      }
      return std::min(count, 2);
    }
    int count = 0;
    if (ia.small() || ib.small()) {  // a small face against a large one: look its few vertices up
      const FaceInfo& small = ia.small() ? ia : ib;
      const std::vector<VertexIndex>& sorted = big_[static_cast<std::size_t>((ia.small() ? ib : ia).v[1])];
      for (int i = 0; i < 4 && count < 2; ++i)
        count += (i == 0 || small.v[i] != small.v[0]) &&
                 std::binary_search(sorted.begin(), sorted.end(), small.v[i]);
      return count;
    }
    const std::vector<VertexIndex>&sa = big_[static_cast<std::size_t>(ia.v[1])],
          &sb = big_[static_cast<std::size_t>(ib.v[1])];
    for (std::size_t i = 0, j = 0; i < sa.size() && j < sb.size() && count < 2;) {  // merge the sorted lists
      if (sa[i] == sb[j]) {
        ++count, ++i, ++j;
      } else {
        sa[i] < sb[j] ? ++i : ++j;
      }
    }
    return count;
  }

  // The vertex two small faces share (they share one).
  static VertexIndex common_vertex(const FaceInfo& x, const FaceInfo& y) {
    for (VertexIndex v : x.v)
      if (v == y.v[0] || v == y.v[1] || v == y.v[2] || v == y.v[3]) return v;
    return x.v[0];
  }

  // Whether small face f, apart from its vertex `at`, lies beyond the coincidence tolerance on one side of
  // the plane: it then meets the plane at `at` alone (as one_side rules for a fan's triangles).
  bool leaves_plane_from(const Plane& plane, const FaceInfo& f, VertexIndex at) const {
    bool above = false, below = false;
    for (VertexIndex v : f.v) {
      if (v == at) continue;
      const double d = plane.signed_distance(solid_.vertices[v]);
      below = below || d <= tol_;
      above = above || d >= -tol_;
    }
    return above != below;
  }

  // One triangle of a vertex's fan, read once for all its pairs: its plane and its other two vertices
  // (ring order after the fan's vertex).
  struct FanTriangle {
    FaceIndex face;
    VertexIndex i1, i2;
    Point3 p1, p2;
    Plane plane;
  };

  void corner_crossing(const FanTriangle& a, const FanTriangle& b, Point3 V, Part& part) const {
    // Most neighbours round a vertex lie wholly to one side of each other's planes, farther than the
    // coincidence tolerance — far beyond the rounding of a triangle's plane, so the exact signs agree.
    auto one_side = [&](const Plane& plane, Point3 p, Point3 q) {
      const double dp = plane.signed_distance(p), dq = plane.signed_distance(q);
      return (dp > tol_ && dq > tol_) || (dp < -tol_ && dq < -tol_);
    };
    if (one_side(b.plane, a.p1, a.p2) || one_side(a.plane, b.p1, b.p2)) return;
    const Point3 a1 = a.p1, a2 = a.p2, b1 = b.p1, b2 = b.p2;
    // Nearly coplanar neighbours within the tolerance of each other's planes (a flat region's fan: most
    // pairs of a CAD mesh) have no line to cross along, as face_crossings rules for every pair — and this
    // spares the predicates below their exact path, which exactly coplanar points always take.
    const Vector3 line = cross(a.plane.normal, b.plane.normal);
    const bool grazing = dot(line, line) < Tolerance::kExactCrossingAngle * Tolerance::kExactCrossingAngle;
    auto near = [&](const Plane& plane, Point3 p) { return std::abs(plane.signed_distance(p)) <= tol_; };
    if (grazing && near(b.plane, a1) && near(b.plane, a2) && near(a.plane, b1) && near(a.plane, b2)) return;
    const int g1 = orient3d(V, b1, b2, a1), g2 = orient3d(V, b1, b2, a2);
    if (g1 * g2 >= 0) return;
    const int h1 = orient3d(V, a1, a2, b1), h2 = orient3d(V, a1, a2, b2);
    if (h1 * h2 >= 0 || g1 != -h1) return;
    if (grazing) {  // where the planes' line runs is too ill-conditioned for doubles: exactly
      const auto x = exact_triangle_crossing({V, a1, a2}, {V, b1, b2});
      if (x && distance((*x)[0], (*x)[1]) > tol_)
        part.found.push_back({(*x)[0], (*x)[1], std::min(a.face, b.face), std::max(a.face, b.face)});
      return;
    }
    // Where L leaves each triangle, from the same determinants' values (their signs are known).
    const double vg1 = orient3d_value(V, b1, b2, a1), vg2 = orient3d_value(V, b1, b2, a2);
    const double vh1 = orient3d_value(V, a1, a2, b1), vh2 = orient3d_value(V, a1, a2, b2);
    const Point3 xa = lerp(a1, a2, std::clamp(vg1 / (vg1 - vg2), 0.0, 1.0));
    const Point3 xb = lerp(b1, b2, std::clamp(vh1 / (vh1 - vh2), 0.0, 1.0));
    const Point3 end = distance(V, xa) <= distance(V, xb) ? xa : xb;
    if (distance(V, end) <= tol_) return;
    part.found.push_back({V, end, std::min(a.face, b.face), std::max(a.face, b.face)});
  }

  const Solid& solid_;
  double tol_ = 0;
  std::vector<FaceInfo> info_;
  std::vector<double> warp_;                   // per face: the farthest of its vertices from its plane
  std::vector<std::vector<VertexIndex>> big_;  // the vertices of each face of more than four, sorted
};

std::vector<SelfCrossing> find_self_crossings(const Solid& solid) {
  // Two faces at least (two triangles may cross through their one shared vertex).
  if (solid.faces.size() < 2 || solid.planes.size() != solid.faces.size()) return {};
  Finder finder(solid);
  // Below a few dozen faces every pair is cheaper than building the grid.
  std::vector<SelfCrossing> found = solid.faces.size() <= 48 ? finder.all_pairs() : finder.grid_pairs();
  const std::vector<SelfCrossing> at_vertices = finder.fan_pairs();
  found.insert(found.end(), at_vertices.begin(), at_vertices.end());
  // Sorted by faces, whatever order the pairs were met in; a pair's pieces keep their order.
  std::stable_sort(found.begin(), found.end(), [](const SelfCrossing& x, const SelfCrossing& y) {
    return x.face0 != y.face0 ? x.face0 < y.face0 : x.face1 < y.face1;
  });
  return found;
}

const std::vector<SelfCrossing> kNone;

}  // namespace

SelfCrossingCache& SelfCrossingCache::operator=(const SelfCrossingCache&) {
  const auto* old = found_.exchange(nullptr);
  if (old != &kNone) delete old;
  return *this;
}

SelfCrossingCache& SelfCrossingCache::operator=(SelfCrossingCache&& other) noexcept {
  const auto* old = found_.exchange(other.found_.exchange(nullptr));
  if (old != &kNone) delete old;
  return *this;
}

SelfCrossingCache::~SelfCrossingCache() {
  const auto* old = found_.load();
  if (old != &kNone) delete old;
}

const std::vector<SelfCrossing>& SelfCrossingCache::get(const Solid& solid) const {
  if (const auto* found = found_.load(std::memory_order_acquire)) return *found;
  // Two threads may both compute; the result does not depend on which one's copy is kept.
  std::vector<SelfCrossing> crossings = find_self_crossings(solid);
  const std::vector<SelfCrossing>* mine =
      crossings.empty() ? &kNone : new std::vector<SelfCrossing>(std::move(crossings));
  const std::vector<SelfCrossing>* expected = nullptr;
  if (found_.compare_exchange_strong(expected, mine, std::memory_order_acq_rel)) return *mine;
  if (mine != &kNone) delete mine;
  return *expected;
}

}  // namespace hlr
