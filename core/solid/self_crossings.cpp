// Where faces of one solid cross: an assembly exported as one mesh, a scan that folds through itself.
// Pairs of faces that may meet come from a uniform grid over the faces' boxes (cells about the size of
// a typical face, so the work follows the number of nearby pairs, not the square of the face count);
// each pair is then rejected cheaply by its planes or solved exactly as two solids' faces are. Faces that
// share an edge meet along it and nowhere else; faces that share one vertex may still pass through each
// other from that vertex on (a fold through a fan, two sheets welded at a point), which for triangles is
// decided by exact orientation predicates (corner_crossing). Faces of one patch certified to project one to
// one (embedded_patches.hpp) cannot cross, and their pairs are not tested at all: on a smooth scan, nearly
// every pair the grid meets and every fan but those on the patches' borders.
#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/counting_sort.hpp"
#include "core/first_touch.hpp"
#include "core/geometry/box3.hpp"
#include "core/geometry/exact_crossing.hpp"
#include "core/geometry/exact_predicates.hpp"
#include "core/geometry/float_bounds.hpp"
#include "core/parallel.hpp"
#include "core/solid/embedded_patches.hpp"
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

// Per face, what the pair tests read, in 40 bytes: its box grown by the coincidence tolerance and rounded
// outward to floats (never smaller: what it lets through is decided in doubles after), and, for a face of
// one ring of up to four vertices (the common case), its vertices, the first repeated to fill four (repeats
// match nothing new), so that telling neighbours apart touches no other memory. A larger face has
// v[0] = kLarge and v[1] the index of its sorted vertices in Finder::big_.
constexpr VertexIndex kLarge = ~VertexIndex{0};
struct FaceInfo {
  float lo[3], hi[3];
  VertexIndex v[4] = {0, 0, 0, 0};
  bool small() const { return v[0] != kLarge; }
  bool overlaps(const FaceInfo& o) const {
    return lo[0] <= o.hi[0] && o.lo[0] <= hi[0] && lo[1] <= o.hi[1] && o.lo[1] <= hi[1] && lo[2] <= o.hi[2] &&
           o.lo[2] <= hi[2];
  }
};

// A face met in a grid cell: a cell's faces are copied together once, where fetching both FaceInfos of
// every pair met (nearly all of them neighbours, sharing a vertex) waited on memory.
struct CellFace {
  FaceInfo info;
  FaceIndex face;
  std::uint32_t first;  // the entry's flags: on which axes the cell is the face's first
  std::uint32_t patch;  // embedded_patches.hpp: faces of one patch do not cross
};

class Finder {
 public:
  explicit Finder(const Solid& solid, bool use_patches) : solid_(solid) {
    double extent = 0;
    for (Point3 p : solid.vertices) extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    tol_ = Tolerance::for_extent(extent).length;
    const std::size_t n = solid.faces.size();
    constexpr std::size_t kChunk = 8192;
    const unsigned threads = threads_for(n, 2 * kChunk, 0);
    // Faulted in on every core before they are filled (core/first_touch.hpp): a 10⁶-triangle mesh's take
    // 48 MB here and 64 MB more in grid_pairs().
    resize_touched(info_, n, threads);
    resize_touched(warp_, n, threads);
    parallel_chunks((n + kChunk - 1) / kChunk, threads, [&](std::size_t k) {
      for (std::size_t f = k * kChunk; f < std::min(n, (k + 1) * kChunk); ++f) {
        const Face& face = solid.faces[f];
        FaceInfo& info = info_[f];
        Box3 box;
        for (const Ring& ring : face.rings)
          for (VertexIndex v : ring.vertices) {
            box.include(solid.vertices[v]);
            warp_[f] = std::max(warp_[f], std::abs(solid.planes[f].signed_distance(solid.vertices[v])));
          }
        const auto& outer = face.rings[0].vertices;
        if (face.rings.size() == 1 && outer.size() <= 4) {
          std::copy(outer.begin(), outer.end(), info.v);
          std::fill(info.v + outer.size(), info.v + 4, outer[0]);
        } else {
          info.v[0] = kLarge;  // its sorted vertices are listed below
        }
        for (int a = 0; a < 3; ++a) {
          info.lo[a] = float_below(box.lo[a] - tol_);
          info.hi[a] = float_above(box.hi[a] + tol_);
        }
      }
    });
    // Patches certified not to cross themselves spare the search nearly every pair the grid meets on a
    // smooth surface (a scan's faces sit in cells with their neighbours).
    if (use_patches) patch_ = embedded_patches(solid);
    for (std::size_t f = 0; f < n; ++f) {
      if (info_[f].small()) continue;
      // Sorted once: a large face meets many neighbours.
      big_.emplace_back();
      info_[f].v[1] = static_cast<VertexIndex>(big_.size() - 1);
      for (const Ring& ring : solid.faces[f].rings)
        big_.back().insert(big_.back().end(), ring.vertices.begin(), ring.vertices.end());
      std::sort(big_.back().begin(), big_.back().end());
    }
  }

  // What one thread finds, with its own buffers.
  struct Part {
    FaceCrossingScratch scratch;
    std::vector<CrossingPiece> pieces;
    std::vector<SelfCrossing> found;
  };

  // Examines one pair of faces; appends what crosses.
  void pair(FaceIndex a, FaceIndex b, Part& part) const {
    if (a > b) std::swap(a, b);
    if (same_patch(a, b)) return;
    const FaceInfo& ia = info_[a];
    const FaceInfo& ib = info_[b];
    if (!ia.overlaps(ib)) return;
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
  // would fetch the same few triangles again for every pair. The corners are listed by vertex in one pass
  // over the faces, so that a fan's triangles are read from one place (a scan's faces come in no order
  // round its vertices). Vertices are shared out over the cores.
  std::vector<SelfCrossing> fan_pairs() const {
    const std::size_t nv = solid_.vertices.size(), nf = info_.size();
    // Only vertices where triangles of more than one patch (or of none) meet have pairs to test: round
    // any other, every pair lies in one patch.
    constexpr std::uint32_t kUnseen = kNoPatch - 1;
    std::vector<std::uint32_t> meeting(nv, patch_.empty() ? kNoPatch : kUnseen);  // one patch, or kNoPatch
    if (!patch_.empty())
      for (std::size_t f = 0; f < nf; ++f)
        if (is_triangle(static_cast<FaceIndex>(f)))
          for (int k = 0; k < 3; ++k) {
            std::uint32_t& at = meeting[info_[f].v[k]];
            at = at == kUnseen || at == patch_[f] ? patch_[f] : kNoPatch;
          }
    auto tested = [&](VertexIndex v) { return meeting[v] == kNoPatch; };
    std::vector<std::uint32_t> first(nv + 1, 0);
    for (std::size_t f = 0; f < nf; ++f)
      if (is_triangle(static_cast<FaceIndex>(f)))
        for (int k = 0; k < 3; ++k)
          if (tested(info_[f].v[k])) ++first[info_[f].v[k] + 1];
    for (std::size_t v = 0; v < nv; ++v) first[v + 1] += first[v];
    std::vector<Corner> corners(first[nv]);
    {
      std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
      for (std::size_t f = 0; f < nf; ++f) {
        if (!is_triangle(static_cast<FaceIndex>(f))) continue;
        const VertexIndex* ring = info_[f].v;
        for (int k = 0; k < 3; ++k)
          if (tested(ring[k]))
            corners[fill[ring[k]]++] = {static_cast<FaceIndex>(f), ring[(k + 1) % 3], ring[(k + 2) % 3]};
      }
    }
    // Two triangles whose points (other than V) lie farther than this beyond each other's planes, measured
    // with the normal of their own corner, lie beyond the coincidence tolerance of their stored planes too
    // (the two normals differ by rounding, far below it), so corner_crossing would find nothing.
    const double far = 2 * tol_;
    // Parts of about kPartCorners corners, each a run of whole fans: the tested vertices lie scattered
    // over the vertex order, so parts of equal vertex ranges were unequal work.
    constexpr std::size_t kPartCorners = 2048;
    std::vector<std::size_t> part_vertex{0};  // the first vertex of each part, then nv
    for (std::size_t c = kPartCorners; c < corners.size(); c += kPartCorners) {
      const auto v =
          static_cast<std::size_t>(std::lower_bound(first.begin(), first.end() - 1, c) - first.begin());
      if (v > part_vertex.back()) part_vertex.push_back(v);
    }
    if (part_vertex.back() != nv) part_vertex.push_back(nv);
    std::vector<Part> parts(part_vertex.size() - 1);
    parallel_chunks(parts.size(), threads_for(corners.size(), 2 * kPartCorners, 0), [&](std::size_t k) {
      Part& part = parts[k];
      struct Near {  // one triangle of the fan: its corner, the other points relative to V, its normal
        const Corner* corner;
        Vector3 e1, e2, normal;
        double reach;  // far times the normal's length
      };
      std::vector<Near> round;
      for (std::size_t v = part_vertex[k]; v < part_vertex[k + 1]; ++v) {
        if (first[v + 1] - first[v] < 2) continue;
        const Point3 V = solid_.vertices[v];
        round.clear();
        for (std::uint32_t i = first[v]; i < first[v + 1]; ++i) {
          const Corner& c = corners[i];
          const Vector3 e1 = solid_.vertices[c.i1] - V, e2 = solid_.vertices[c.i2] - V;
          const Vector3 normal = cross(e1, e2);
          round.push_back({&c, e1, e2, normal, far * length(normal)});
        }
        auto beyond = [](const Near& plane, const Near& t) {
          const double d1 = dot(plane.normal, t.e1), d2 = dot(plane.normal, t.e2);
          return (d1 > plane.reach && d2 > plane.reach) || (d1 < -plane.reach && d2 < -plane.reach);
        };
        for (std::size_t i = 0; i < round.size(); ++i)
          for (std::size_t j = i + 1; j < round.size(); ++j) {
            const Corner &x = *round[i].corner, &y = *round[j].corner;
            // Triangles sharing a second vertex share an edge: they meet along it, not across.
            if (x.i1 == y.i1 || x.i1 == y.i2 || x.i2 == y.i1 || x.i2 == y.i2 || same_patch(x.face, y.face))
              continue;
            if (beyond(round[j], round[i]) || beyond(round[i], round[j])) continue;
            corner_crossing(fan_triangle(x), fan_triangle(y), V, part);
          }
      }
    });
    std::vector<SelfCrossing> found;
    for (Part& part : parts) found.insert(found.end(), part.found.begin(), part.found.end());
    return found;
  }

  // The grid: cells of the median face size (at least 1/1000 of the solid's size on each axis, so cell
  // numbers fit 10 bits); a face covering more than kMaxCells cells is met against every face instead.
  // The grid is cut into slabs of whole z planes, each listed, sorted and examined on its own, so that
  // the cores share all of it; what each finds is joined in slab order.
  std::vector<SelfCrossing> grid_pairs() {
    const std::size_t n = info_.size();
    // The solid's box, by parts side by side (the 10⁶-triangle torus's loops over the faces here took
    // 40 ms on one core), and the median face size, of a sample of faces spread evenly over the solid's
    // order: the cell size only shares the work out, the pairs found are the same for any.
    constexpr std::size_t kPart = 16384;
    const std::size_t part_count = (n + kPart - 1) / kPart;
    const unsigned threads = threads_for(n, 2 * kPart, 0);  // for the stages by parts below
    std::vector<Box3> part_box(part_count);
    parallel_chunks(part_count, threads, [&](std::size_t k) {
      Box3 box;  // stored once: the parts' boxes share cache lines
      for (std::size_t f = k * kPart; f < std::min(n, (k + 1) * kPart); ++f) {
        const FaceInfo& b = info_[f];  // grown by the tolerance
        box.include({b.lo[0], b.lo[1], b.lo[2]});
        box.include({b.hi[0], b.hi[1], b.hi[2]});
      }
      part_box[k] = box;
    });
    Box3 all;
    for (const Box3& b : part_box) all.include(b.lo), all.include(b.hi);  // no part is empty
    constexpr std::size_t kSizeSample = 16384;
    const std::size_t stride = std::max<std::size_t>(1, n / kSizeSample);
    std::vector<double> sizes;
    sizes.reserve(n / stride + 1);
    for (std::size_t f = 0; f < n; f += stride) {
      const FaceInfo& b = info_[f];
      sizes.push_back(std::max({b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]}));
    }
    const auto middle = static_cast<std::ptrdiff_t>(sizes.size() / 2);
    std::nth_element(sizes.begin(), sizes.begin() + middle, sizes.end());
    const double cell = std::max(
        {sizes[static_cast<std::size_t>(middle)], all.largest_side() / 1000, tol_, Tolerance::kFloor});
    auto index = [&](double v, double origin) {
      return static_cast<std::uint16_t>(std::clamp(std::floor((v - origin) / cell), 0.0, 1023.0));
    };
    auto cell_key = [](std::uint64_t x, std::uint64_t y, std::uint64_t z) {
      return x | (y << 10) | (z << 20);
    };
    // The faces ranked by the cell their box begins in (z first): a slab's faces are then a run of ranks,
    // and a cell's lie near each other in cell_faces, where in a scan's own order they were spread over
    // the whole mesh and every one fetched from memory.
    std::vector<std::uint64_t> ranked;
    resize_touched(ranked, n, threads);
    parallel_indices(n, kPart, [&](std::size_t f) {
      const FaceInfo& c = info_[f];
      ranked[f] = cell_key(index(c.lo[0], all.lo.x), index(c.lo[1], all.lo.y), index(c.lo[2], all.lo.z))
                      << kCellShift |
                  f;
    });
    sort_by_30_bits(ranked, kCellShift);  // by cell, the face order kept within one
    // Per rank: the face's FaceInfo and the cells its grown box covers.
    struct Cells {
      std::uint16_t lo[3], hi[3];
    };
    std::vector<FaceIndex> face_at;
    std::vector<FaceInfo> cell_faces;
    std::vector<Cells> cells;
    resize_touched(face_at, n, threads);
    resize_touched(cell_faces, n, threads);
    resize_touched(cells, n, threads);
    constexpr std::size_t kRanks = 8192;
    parallel_indices(n, kRanks, [&](std::size_t r) {
      face_at[r] = face_of(ranked[r]);
      const FaceInfo& c = cell_faces[r] = info_[face_at[r]];
      for (int a = 0; a < 3; ++a)
        cells[r].lo[a] = index(c.lo[a], all.lo[a]), cells[r].hi[a] = index(c.hi[a], all.lo[a]);
    });
    constexpr int kMaxCells = 64;
    auto is_big = [&](std::size_t r) {
      const Cells& c = cells[r];
      return (c.hi[0] - c.lo[0] + 1) * (c.hi[1] - c.lo[1] + 1) * (c.hi[2] - c.lo[2] + 1) > kMaxCells;
    };
    // The faces met against every face, in rank order, and the most z planes past its first that
    // another face's box spans: by parts side by side, joined in order.
    std::vector<std::vector<FaceIndex>> part_big(part_count);
    std::vector<int> part_reach(part_count, 0);
    parallel_chunks(part_count, threads, [&](std::size_t k) {
      std::vector<FaceIndex> found;  // stored once: the parts' results share cache lines
      int reach = 0;
      for (std::size_t r = k * kPart; r < std::min(n, (k + 1) * kPart); ++r) {
        if (is_big(r))
          found.push_back(face_at[r]);
        else
          reach = std::max(reach, cells[r].hi[2] - cells[r].lo[2]);
      }
      part_big[k] = std::move(found);
      part_reach[k] = reach;
    });
    std::vector<FaceIndex> big;
    for (const std::vector<FaceIndex>& found : part_big) big.insert(big.end(), found.begin(), found.end());
    const int reach = *std::max_element(part_reach.begin(), part_reach.end());
    // Slabs of whole z planes, about kSlabFaces faces beginning in each.
    constexpr std::size_t kSlabFaces = 4096;
    std::vector<std::size_t> slab_ranks{0};  // the first rank beginning in each slab
    for (std::size_t r = kSlabFaces; r < n; r += kSlabFaces) {
      while (r < n && cells[r].lo[2] == cells[r - 1].lo[2]) ++r;
      if (r < n && r > slab_ranks.back()) slab_ranks.push_back(r);
    }
    slab_ranks.push_back(n);
    std::vector<Part> parts(slab_ranks.size() - 1);
    // A slab's lists, per thread: room reused from slab to slab (fresh pages are dear).
    struct SlabRoom {
      std::vector<std::uint64_t> entries, sort_buffer;  // the slab's, and room to sort them
      std::vector<std::uint32_t> sort_counts;
      std::vector<CellFace> local;      // a cell's faces
      std::vector<std::uint64_t> cell;  // a crowded cell's entries, for the sweep
    };
    tbb::enumerable_thread_specific<SlabRoom> rooms;
    parallel_chunks(parts.size(), threads_for(n, 8192, 0), [&](std::size_t k) {
      Part& part = parts[k];
      SlabRoom& room = rooms.local();
      const int z0 = cells[slab_ranks[k]].lo[2];
      const int z1 = slab_ranks[k + 1] < n ? cells[slab_ranks[k + 1]].lo[2] : 1024;  // planes [z0, z1)
      // Faces beginning up to `reach` planes below the slab may reach into it.
      std::size_t from = slab_ranks[k];
      while (from > 0 && cells[from - 1].lo[2] + reach >= z0) --from;
      // One entry per (cell, face rank), packed as above, so a sort groups each cell's faces in rank order.
      std::vector<std::uint64_t>& entries = room.entries;
      entries.clear();
      for (std::size_t r = from; r < slab_ranks[k + 1]; ++r) {
        const Cells& c = cells[r];
        if (c.hi[2] < z0 || is_big(r)) continue;
        const int zlo = std::max<int>(c.lo[2], z0), zhi = std::min<int>(c.hi[2], z1 - 1);
        for (std::uint64_t x = c.lo[0]; x <= c.hi[0]; ++x)
          for (std::uint64_t y = c.lo[1]; y <= c.hi[1]; ++y)
            for (auto z = static_cast<std::uint64_t>(zlo); z <= static_cast<std::uint64_t>(zhi); ++z) {
              const std::uint64_t first =
                  (x == c.lo[0] ? 1u : 0u) | (y == c.lo[1] ? 2u : 0u) | (z == c.lo[2] ? 4u : 0u);
              entries.push_back(cell_key(x, y, z) << kCellShift | first << kFirstShift | r);
            }
      }
      sort_by_30_bits(entries, kCellShift, room.sort_buffer, room.sort_counts);
      std::vector<CellFace>& local = room.local;
      for (std::size_t i = 0; i < entries.size();) {
        const std::uint64_t at = cell_of(entries[i]);
        std::size_t end = i + 1;
        while (end < entries.size() && cell_of(entries[end]) == at) ++end;
        if (end - i > kSweepAbove) {
          // A pair sharing several cells is examined in one of them only.
          room.cell.assign(entries.begin() + static_cast<std::ptrdiff_t>(i),
                           entries.begin() + static_cast<std::ptrdiff_t>(end));
          for (std::uint64_t& e : room.cell)  // ranks to faces
            e = (e & ~kFaceMask) | static_cast<std::uint64_t>(face_at[face_of(e)]);
          sweep_cell(room.cell, [&](std::uint64_t a, std::uint64_t b) {
            if (pair_is_met_here(a, b)) pair(face_of(a), face_of(b), part);
          });
        } else if (!cell_in_one_patch(entries, i, end, face_at)) {
          local.clear();
          for (std::size_t p = i; p < end; ++p) {
            const std::size_t rank = face_of(entries[p]);
            local.push_back({cell_faces[rank], face_at[rank],
                             static_cast<std::uint32_t>(entries[p] >> kFirstShift) & 7,
                             patch_of(face_at[rank])});
          }
          for (std::size_t p = 0; p < local.size(); ++p)
            for (std::size_t q = p + 1; q < local.size(); ++q)
              if (may_cross(local[p], local[q])) pair(local[p].face, local[q].face, part);
        }
        i = end;
      }
    });
    std::vector<SelfCrossing> found;
    for (Part& part : parts) found.insert(found.end(), part.found.begin(), part.found.end());
    Part rest;
    std::vector<char> is_big_face(n, 0);
    for (FaceIndex f : big) is_big_face[f] = 1;
    for (FaceIndex f : big)
      for (std::size_t g = 0; g < n; ++g)
        if (!is_big_face[g] || static_cast<FaceIndex>(g) > f) pair(f, static_cast<FaceIndex>(g), rest);
    found.insert(found.end(), rest.found.begin(), rest.found.end());
    return found;
  }

 private:
  // A cell holding more faces than this is swept, not paired all with all: faces much longer than the
  // median (the sides of a many-sided prism, as tall as the cells are wide) crowd into a few cells.
  static constexpr std::size_t kSweepAbove = 32;

  // Calls visit(a, b) (two of the cell's entries, faces for ranks) for the pairs of the cell's faces whose
  // boxes overlap along the axis where they overlap least: sorted by the box's low end on it, each face meets
  // the faces starting before its box ends.
  template <typename Visit>
  void sweep_cell(std::vector<std::uint64_t>& cell, Visit&& visit) const {
    int axis = 0;
    double best = -1;
    for (int k = 0; k < 3; ++k) {  // overlaps expected ∝ total box length / the range they spread over
      const FaceInfo& first = info_[face_of(cell[0])];
      double length = 0, lo = first.lo[k], hi = first.hi[k];
      for (std::uint64_t e : cell) {
        const FaceInfo& b = info_[face_of(e)];
        length += b.hi[k] - b.lo[k];
        lo = std::min<double>(lo, b.lo[k]);
        hi = std::max<double>(hi, b.hi[k]);
      }
      const double score = (hi - lo) / std::max(length, Tolerance::kFloor);
      if (score > best) best = score, axis = k;
    }
    std::sort(cell.begin(), cell.end(), [&](std::uint64_t a, std::uint64_t b) {
      const float la = info_[face_of(a)].lo[axis], lb = info_[face_of(b)].lo[axis];
      return la < lb || (la == lb && face_of(a) < face_of(b));
    });
    for (std::size_t p = 0; p < cell.size(); ++p) {
      const float reach = info_[face_of(cell[p])].hi[axis];  // the boxes are grown by the tolerance
      for (std::size_t q = p + 1; q < cell.size() && info_[face_of(cell[q])].lo[axis] <= reach; ++q)
        visit(cell[p], cell[q]);
    }
  }

  // Whether pair() may find a crossing of two faces met in a cell, from what the cell holds: the pair is
  // met in this cell (of those the two share), their boxes overlap, and, between faces of up to four
  // vertices, they share no edge and are not two triangles at one vertex (fan_pairs takes those).
  static bool may_cross(const CellFace& cell_a, const CellFace& cell_b) {
    if ((cell_a.first | cell_b.first) != 7 || (cell_a.patch == cell_b.patch && cell_a.patch != kNoPatch))
      return false;
    const FaceInfo &a = cell_a.info, &b = cell_b.info;
    if (!a.overlaps(b)) return false;
    if (!a.small() || !b.small()) return true;
    const int shared = shared_among_four(a, b);
    if (shared >= 2) return false;
    const bool triangles = a.v[3] == a.v[0] && b.v[3] == b.v[0];
    return !(shared == 1 && triangles);
  }

  std::uint32_t patch_of(FaceIndex f) const {
    return patch_.empty() ? kNoPatch : patch_[static_cast<std::size_t>(f)];
  }
  bool same_patch(FaceIndex a, FaceIndex b) const {
    const std::uint32_t p = patch_of(a);
    return p != kNoPatch && p == patch_of(b);
  }
  // Whether the faces of entries [begin, end) (ranks, face_at naming their faces) all lie in one patch.
  bool cell_in_one_patch(const std::vector<std::uint64_t>& entries, std::size_t begin, std::size_t end,
                         const std::vector<FaceIndex>& face_at) const {
    const std::uint32_t p = patch_of(face_at[face_of(entries[begin])]);
    if (p == kNoPatch) return false;
    for (std::size_t i = begin + 1; i < end; ++i)
      if (patch_of(face_at[face_of(entries[i])]) != p) return false;
    return true;
  }

  // A triangle's fourth slot repeats its first vertex (a quad's holds its own fourth).
  bool is_triangle(FaceIndex f) const { return info_[f].small() && info_[f].v[3] == info_[f].v[0]; }

  // How many vertices two faces of up to four share, counting to two. Most pairs met are neighbours: the
  // padded four against four, without branches.
  static int shared_among_four(const FaceInfo& a, const FaceInfo& b) {
    int count = 0;
    for (int i = 0; i < 4; ++i) {
      const VertexIndex v = a.v[i];
      const bool own = i == 0 || v != a.v[0];  // padding repeats the first vertex
      count += own && (v == b.v[0] || v == b.v[1] || v == b.v[2] || v == b.v[3]);
    }
    return std::min(count, 2);
  }

  // How many vertices faces a and b share, counting to two (an edge).
  int shared_vertices(const FaceInfo& ia, const FaceInfo& ib) const {
    if (ia.small() && ib.small()) return shared_among_four(ia, ib);
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

  // A triangle at one of its corners: the other two vertices, in ring order after the corner's.
  struct Corner {
    FaceIndex face;
    VertexIndex i1, i2;
  };

  // One triangle of a vertex's fan, read once for all its pairs: its plane and its other two vertices
  // (ring order after the fan's vertex).
  struct FanTriangle {
    FaceIndex face;
    VertexIndex i1, i2;
    Point3 p1, p2;
    Plane plane;
  };

  FanTriangle fan_triangle(const Corner& c) const {
    return {c.face, c.i1, c.i2, solid_.vertices[c.i1], solid_.vertices[c.i2], solid_.planes[c.face]};
  }

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
  std::vector<std::uint32_t> patch_;           // per face (embedded_patches.hpp); empty: none used
};

std::vector<SelfCrossing> find_self_crossings(const Solid& solid) {
  // Two faces at least (two triangles may cross through their one shared vertex).
  if (solid.faces.size() < 2 || solid.planes.size() != solid.faces.size()) return {};
  // Below a few dozen faces every pair is cheaper than certifying patches too.
  Finder finder(solid, solid.faces.size() > 48);
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

}  // namespace

const std::vector<SelfCrossing>& Solid::self_crossings() const {
  return self_crossing_cache.get([this] { return find_self_crossings(*this); });
}

}  // namespace hlr
