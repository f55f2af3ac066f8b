// The edge table: every undirected ring edge once with the faces on its two sides, lines on faces, and
// free lines, in first-seen order (for the theses' data this is exactly Desens' LINES numbering).
#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "core/first_touch.hpp"
#include "core/parallel.hpp"
#include "core/solid/builder_detail.hpp"

namespace hlr::solid_detail {

EdgeEntries::EdgeEntries(std::size_t expected_entries, std::size_t vertex_count, std::size_t indexed_entries)
    : expected_(expected_entries),
      slots_(std::bit_ceil(
          std::max<std::size_t>(16, 2 * (indexed_entries ? indexed_entries : expected_entries)))),
      vertex_count_(vertex_count) {
  shift_ = 64 - std::countr_zero(slots_.size());
  set_per_vertex();
}

void EdgeEntries::set_per_vertex() {
  // Slots below 2^32 (entries are numbered in 32 bits), so that lo · per_vertex_ fits in 64 bits.
  per_vertex_ = vertex_count_ == 0 || slots_.size() > (std::size_t{1} << 32)
                    ? 0
                    : (std::uint64_t{slots_.size()} << 32) / vertex_count_;
}

std::size_t EdgeEntries::slot_of(VertexIndex lo, VertexIndex hi, std::size_t& run) const {
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t s = home(lo, hi);; s = (s + 1) & mask, ++run) {
    const Slot& slot = slots_[s];
    if (slot.entry == 0 || (slot.lo == lo && slot.hi == hi)) return s;
  }
}

void EdgeEntries::index_again(std::size_t slot_count) {
  slots_.assign(slot_count, Slot{});
  shift_ = 64 - std::countr_zero(slots_.size());
  if (per_vertex_ != 0) set_per_vertex();
  for (std::uint32_t e = 0; e < size_; ++e) {
    const EdgeEntry& entry = (*this)[e];
    slots_[slot_of(entry.lo, entry.hi)] = {entry.lo, entry.hi, e + 1};
  }
}

std::uint32_t EdgeEntries::get(VertexIndex a, VertexIndex b) {
  const VertexIndex lo = std::min(a, b), hi = std::max(a, b);
  std::size_t run = 0;
  std::size_t s = slot_of(lo, hi, run);
  if (run > kLongRun && per_vertex_ != 0) {  // crowded round a vertex: scatter from now on
    per_vertex_ = 0;
    index_again(slots_.size());
    s = slot_of(lo, hi);
  }
  if (slots_[s].entry != 0) return slots_[s].entry - 1;
  if (size_ >= kNoEdge - 1) throw std::length_error("SolidBuilder: too many edges");
  if (2 * (std::size_t{size_} + 1) > slots_.size()) {
    index_again(2 * slots_.size());
    s = slot_of(lo, hi);
  }
  if ((size_ & kMask) == 0) {
    blocks_.emplace_back();
    blocks_.back().reserve(size_ == 0 ? std::min<std::size_t>(expected_ + 1, kMask + 1) : kMask + 1);
  }
  EdgeEntry e;
  e.lo = lo;
  e.hi = hi;
  blocks_.back().push_back(e);
  slots_[s] = {lo, hi, ++size_};
  return size_ - 1;
}

std::uint32_t EdgeEntries::find(VertexIndex a, VertexIndex b) const {
  const std::uint32_t e = slots_[slot_of(std::min(a, b), std::max(a, b))].entry;
  return e == 0 ? kNoEdge : e - 1;
}

void EdgeEntries::add_use(std::uint32_t e, EdgeUse use) {
  EdgeEntry& entry = (*this)[e];
  if (entry.uses >= 2) {
    entry.uses = 3;
    extra_.push_back({e, use});
    return;
  }
  entry.face[entry.uses] = use.face;
  if (use.forward) entry.forward |= static_cast<std::uint8_t>(1u << entry.uses);
  ++entry.uses;
}

void EdgeEntries::release_index() { slots_ = std::vector<Slot>(); }

bool EdgeEntries::absorb(const EdgeEntries& later, std::vector<std::uint32_t>& number) {
  if (!extra_.empty() || !later.extra_.empty()) return false;
  // Looked up side by side (the table is only read), then taken in in order.
  const std::size_t m = later.size();
  number.assign(m, kNoEdge);
  parallel_indices(m, 16384, [&](std::size_t j) {
    number[j] = find(later[static_cast<std::uint32_t>(j)].lo, later[static_cast<std::uint32_t>(j)].hi);
  });
  for (std::size_t j = 0; j < m; ++j)
    if (number[j] != kNoEdge && (*this)[number[j]].uses + later[static_cast<std::uint32_t>(j)].uses > 2)
      return false;
  if (size_ + m >= kNoEdge - 1) throw std::length_error("SolidBuilder: too many edges");
  release_index();
  for (std::size_t j = 0; j < m; ++j) {
    const EdgeEntry& entry = later[static_cast<std::uint32_t>(j)];
    if (number[j] != kNoEdge) {
      for (int k = 0; k < entry.uses; ++k) add_use(number[j], entry.use(k));
      continue;
    }
    if ((size_ & kMask) == 0) {
      blocks_.emplace_back();
      blocks_.back().reserve(size_ == 0 ? std::min<std::size_t>(expected_ + 1, kMask + 1) : kMask + 1);
    }
    blocks_.back().push_back(entry);
    number[j] = size_++;
  }
  return true;
}

std::string edge_name(const VertexTable& vertices, VertexIndex a, VertexIndex b) {
  return vertices.id(std::min(a, b)) + "\u2013" + vertices.id(std::max(a, b));
}

void enter_face_edges(EdgeEntries& edges, FaceIndex face, SmallVector<Ring, 1>& rings, const Loops* loops,
                      std::span<const std::pair<VertexIndex, VertexIndex>> lines) {
  // Edges are entered in the order the input traverses them, rings and on-face lines interleaved; when
  // the rings are the input loops as given, one pass does both.
  if (loops)
    for (std::size_t k = 0; k < loops->size(); ++k) {
      const std::span<const VertexIndex> loop = (*loops)[k];
      for (std::size_t i = 0; i < loop.size(); ++i) edges.get(loop[i], loop[i + 1 < loop.size() ? i + 1 : 0]);
    }
  for (Ring& r : rings) {
    const std::size_t n = r.vertices.size();
    r.edges.assign(n, kNoEdge);
    for (std::size_t i = 0; i < n; ++i) {
      const VertexIndex a = r.vertices[i], b = r.vertices[i + 1 < n ? i + 1 : 0];
      const std::uint32_t e = edges.get(a, b);
      edges.add_use(e, {face, a < b});
      r.edges[i] = e;  // an entry number until build_edge_table
    }
  }
  for (const auto& [a, b] : lines) {
    EdgeEntry& e = edges[edges.get(a, b)];
    if (e.marking_face == kNoFace) e.marking_face = face;
  }
}

void prefetch_face_edges(const EdgeEntries& edges, const std::vector<Face>& faces,
                         const std::vector<char>& ready, std::size_t f, std::size_t end) {
  if (f + kPrefetchFaces >= end || !ready[f + kPrefetchFaces]) return;
  const auto& ring = faces[f + kPrefetchFaces].rings[0].vertices;
  for (std::size_t i = 0; i < ring.size() && ring.size() <= kPrefetchFaces; ++i)
    edges.prefetch(ring[i], ring[i + 1 < ring.size() ? i + 1 : 0]);
}

EdgeEntries enter_plain_faces(std::vector<Face>& faces, const std::vector<char>& ready,
                              std::size_t expected_entries, std::size_t vertex_count) {
  const std::size_t n = faces.size(), half = n / 2;
  // Each half's table sized for a little over half the entries, the first one's store for all of them.
  const std::size_t indexed = expected_entries / 2 + expected_entries / 16;
  EdgeEntries edges(expected_entries, vertex_count, indexed);
  EdgeEntries later(indexed, vertex_count);
  auto enter = [&](EdgeEntries& table, std::size_t from, std::size_t to) {
    for (std::size_t f = from; f < to; ++f) {
      prefetch_face_edges(table, faces, ready, f, to);
      if (ready[f]) enter_face_edges(table, static_cast<FaceIndex>(f), faces[f].rings, nullptr, {});
    }
  };
  parallel_chunks(2, 0, [&](std::size_t k) {
    if (k == 0)
      enter(edges, 0, half);
    else
      enter(later, half, n);
  });
  std::vector<std::uint32_t> number;
  if (!edges.absorb(later, number)) {  // a non-manifold edge: face after face, for its uses' order
    edges = EdgeEntries(expected_entries, vertex_count);
    enter(edges, 0, n);
    edges.release_index();
    return edges;
  }
  later = EdgeEntries(0);
  // The second half's rings hold its own table's numbers.
  parallel_indices(n - half, 8192, [&](std::size_t k) {
    if (ready[half + k])
      for (Ring& r : faces[half + k].rings)
        for (std::uint32_t& e : r.edges) e = number[e];
  });
  return edges;
}

void report_non_manifold(const EdgeEntries& edges, Tags face_tags, const VertexTable& vertices,
                         Diagnostics& diagnostics) {
  if (edges.extra().empty()) return;
  std::vector<EdgeEntries::Extra> extra = edges.extra();  // grouped by entry, each group in order
  std::stable_sort(extra.begin(), extra.end(),
                   [](const auto& a, const auto& b) { return a.entry < b.entry; });
  std::size_t next = 0;
  for (std::uint32_t i = 0; i < edges.size(); ++i) {
    const EdgeEntry& e = edges[i];
    if (e.uses <= 2) continue;
    std::string names = std::to_string(e.face[0] + 1) + ", " + std::to_string(e.face[1] + 1);
    std::size_t count = 2;
    const FaceIndex third = extra[next].use.face;
    for (; next < extra.size() && extra[next].entry == i; ++next, ++count)
      names += ", " + std::to_string(extra[next].use.face + 1);
    diagnostics.error("non-manifold-edge",
                      "edge " + edge_name(vertices, e.lo, e.hi) + " is used by " + std::to_string(count) +
                          " faces (" + names + "); an edge may border at most two faces",
                      face_tags[static_cast<std::size_t>(third)]);
  }
}

namespace {

// The first face on which both end points lie: within the planarity tolerance of its plane and inside
// or on its polygon. (Only the end points are tested: a line between two points of a non-convex face
// may still leave it.)
FaceIndex face_holding(Point3 a, Point3 b, const Solid& solid, const std::vector<Point3>& pos,
                       const std::vector<bool>& valid, const std::vector<double>& face_sizes,
                       const SolidBuildOptions& options) {
  for (std::size_t fi = 0; fi < solid.faces.size(); ++fi) {
    if (!valid[fi]) continue;
    const auto& rings = solid.faces[fi].rings;
    const double tolerance = options.planarity_tolerance * face_sizes[fi];
    const Plane& plane = solid.planes[fi];
    if (std::abs(plane.signed_distance(a)) > tolerance || std::abs(plane.signed_distance(b)) > tolerance)
      continue;
    const FaceFrame frame = FaceFrame::from_normal(plane.normal, pos[rings[0].vertices[0]]);
    std::vector<Polygon2> flat;
    for (const Ring& r : rings) {
      Polygon2 p;
      for (VertexIndex v : r.vertices) p.push_back(frame.to_2d(pos[v]));
      flat.push_back(std::move(p));
    }
    if (classify_point(frame.to_2d(a), flat, tolerance) != Containment::Outside &&
        classify_point(frame.to_2d(b), flat, tolerance) != Containment::Outside)
      return static_cast<FaceIndex>(fi);
  }
  return kNoFace;
}

}  // namespace

void build_edge_table(Solid& solid, EdgeEntries& edges, const std::vector<bool>& valid,
                      const std::vector<double>& face_sizes, const std::vector<LineSpec>& lines,
                      const VertexTable& vertices, const SolidBuildOptions& options,
                      Diagnostics& diagnostics) {
  const std::vector<Point3>& pos = vertices.positions();
  for (std::size_t li = 0; li < lines.size(); ++li) {
    const LineSpec& line = lines[li];
    const std::string name = "line " + std::to_string(li + 1);
    VertexIndex ends[2] = {0, 0};
    bool resolved = true;
    const VertexRef refs[2] = {line.a, line.b};
    for (int k = 0; k < 2; ++k) {
      const VertexIndex v = vertices.resolve(refs[k]);
      if (v == kNoVertex) {
        const std::string id = vertices.ref_text(refs[k]);
        if (k == 0 || id != vertices.ref_text(line.a))
          diagnostics.error("unknown-vertex",
                            name + " names vertex '" + id +
                                "' which is not declared; declare it with 'vertex " + id +
                                " = (x, y, z)' before the line",
                            line.tag);
        resolved = false;
        continue;
      }
      if (!vertices.usable[v]) resolved = false;  // non-finite: reported with the vertex
      ends[k] = v;
    }
    if (!resolved) continue;
    if (ends[0] == ends[1]) {
      diagnostics.warning("degenerate-line",
                          name + " joins vertex '" + vertices.ref_text(line.a) + "' to itself; dropped it",
                          line.tag);
      continue;
    }
    if (edges.find(ends[0], ends[1]) != kNoEdge) continue;  // already an edge or a line: keep one
    const FaceIndex on = face_holding(pos[ends[0]], pos[ends[1]], solid, pos, valid, face_sizes, options);
    EdgeEntry& e = edges[edges.get(ends[0], ends[1])];
    if (on != kNoFace)
      e.marking_face = on;
    else
      e.free_line = true;
  }
  edges.release_index();

  // Entries that become no edge: more than two faces (reported; no solid) or a path dropped by the loop
  // split. Counted first so the table is allocated once, at its size.
  auto kept = [](const EdgeEntry& e) {
    return e.uses == 1 || e.uses == 2 || (e.uses == 0 && (e.marking_face != kNoFace || e.free_line));
  };
  // Each kept entry's edge number (a prefix count), then the edges made side by side: each reads its two
  // faces' planes, which in a mesh whose faces come in no order are far apart in memory.
  const std::uint32_t n = edges.size();
  std::vector<std::uint32_t> index_of;  // entry → solid edge, when some entries are dropped
  std::size_t count = 0;
  for (std::uint32_t i = 0; i < n; ++i) count += kept(edges[i]);
  if (count != n) {
    index_of.assign(n, kNoEdge);
    for (std::uint32_t i = 0, next = 0; i < n; ++i)
      if (kept(edges[i])) index_of[i] = next++;
  }
  constexpr std::size_t kPart = 8192;
  const unsigned threads = threads_for(n, 4 * kPart, 0);
  resize_touched(solid.edges, count, threads);  // faulted in on every core first
  parallel_chunks((n + kPart - 1) / kPart, threads, [&](std::size_t k) {
    for (std::uint32_t i = static_cast<std::uint32_t>(k * kPart);
         i < std::min<std::size_t>(n, (k + 1) * kPart); ++i) {
      const EdgeEntry& entry = edges[i];
      if (!kept(entry)) continue;
      SolidEdge& e = solid.edges[index_of.empty() ? i : index_of[i]];
      e.v0 = entry.lo;
      e.v1 = entry.hi;
      if (entry.uses == 2) {
        // left runs v0→v1; after orientation the other use runs v1→v0.
        const int l = entry.use(0).forward ? 0 : 1;
        e.left = entry.face[l];
        e.right = entry.face[1 - l];
        const DihedralClass c = classify_dihedral(
            pos[e.v1] - pos[e.v0], solid.planes[static_cast<std::size_t>(e.left)].normal,
            solid.planes[static_cast<std::size_t>(e.right)].normal, options.crease_angle_deg);
        e.kind = c.kind;
        e.concave = c.concave;
      } else if (entry.uses == 1) {
        if (!entry.use(0).forward) std::swap(e.v0, e.v1);  // keep the face on the left
        e.left = entry.face[0];
        e.kind = EdgeKind::Boundary;
      } else if (entry.marking_face != kNoFace) {
        e.left = e.right = entry.marking_face;
        e.kind = EdgeKind::Marking;
      } else {
        e.kind = EdgeKind::Free;
      }
    }
  });
  edges = EdgeEntries(0);  // free the entries before the last pass

  // Rings hold entry numbers; entries that were kept keep their order, so only dropped ones shift them.
  if (!index_of.empty())
    for (Face& f : solid.faces)
      for (Ring& r : f.rings)
        for (std::uint32_t& e : r.edges) e = index_of[e];
}

}  // namespace hlr::solid_detail
