// SolidBuilder: collects the input as flat arrays of interned ids or vertex numbers, then build() checks it
// in stages (vertices, faces with their edges, orientation, edge table), reporting every problem it finds
// rather than stopping at the first.
#include "core/solid/solid_builder.hpp"

#include <tbb/task_group.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>

#include "core/first_touch.hpp"
#include "core/geometry/exact_predicates.hpp"
#include "core/parallel.hpp"
#include "core/solid/builder_detail.hpp"

namespace hlr {

namespace solid_detail {

namespace {

// Options outside their domain (NaN, negative) fall back to the defaults rather than disabling checks.
SolidBuildOptions sanitized(SolidBuildOptions o) {
  if (!(o.crease_angle_deg >= 0)) o.crease_angle_deg = 0;
  if (!(o.planarity_tolerance >= 0)) o.planarity_tolerance = Tolerance::kPlanarity;
  return o;
}

}  // namespace
}  // namespace solid_detail

SolidBuilder::SolidBuilder(SolidBuildOptions options) : options_(options) {}

void SolidBuilder::add_tag(std::vector<std::int64_t>& tags, std::size_t position, std::int64_t tag) {
  if (tags.empty()) {
    if (tag == -1) return;
    tags.assign(position, -1);  // the first tag given: the earlier ones were -1
  }
  tags.push_back(tag);
}

SolidBuilder::VertexRef SolidBuilder::id_ref(const std::string& id) {
  const std::uint32_t number = ids_.intern(id);
  if (number >= solid_detail::kIndexRef) throw std::length_error("SolidBuilder: too many vertex ids");
  return number;
}

SolidBuilder::VertexRef SolidBuilder::index_ref(VertexIndex v) {
  // A number too large for the reference's index bits names no indexed vertex: keep it as text.
  return v < solid_detail::kIndexRef ? solid_detail::kIndexRef | v : id_ref(std::to_string(v));
}

void SolidBuilder::end_ring() {
  if (refs_.size() > 0xffffffffu) throw std::length_error("SolidBuilder: too many vertex references");
  ring_ends_.push_back(static_cast<std::uint32_t>(refs_.size()));
}

void SolidBuilder::end_face(std::int64_t tag, bool from_loop) {
  if (ring_ends_.size() > 0xffffffffu) throw std::length_error("SolidBuilder: too many rings");
  face_ends_.push_back(static_cast<std::uint32_t>(ring_ends_.size()));
  add_tag(face_tags_, face_ends_.size() - 1, tag);
  face_is_loop_.push_back(from_loop);
}

void SolidBuilder::add_vertex(const std::string& id, Point3 position, std::int64_t tag) {
  if (positions_.size() >= solid_detail::kIndexRef)
    throw std::length_error("SolidBuilder: too many vertices");
  if (vertex_ids_.empty()) vertex_ids_.assign(positions_.size(), kIndexedId);
  vertex_ids_.push_back(id_ref(id));
  add_tag(vertex_tags_, positions_.size(), tag);
  positions_.push_back(position);
}

VertexIndex SolidBuilder::add_vertex(Point3 position, std::int64_t tag) {
  const std::size_t number = positions_.size();
  if (number >= solid_detail::kIndexRef) throw std::length_error("SolidBuilder: too many vertices");
  if (!vertex_ids_.empty()) vertex_ids_.push_back(kIndexedId);
  add_tag(vertex_tags_, number, tag);
  positions_.push_back(position);
  return static_cast<VertexIndex>(number);
}

VertexIndex SolidBuilder::add_vertices(std::span<const Point3> positions,
                                       std::span<const std::int64_t> tags) {
  const std::size_t first = positions_.size();
  if (!tags.empty() && tags.size() != positions.size())
    throw std::invalid_argument("SolidBuilder::add_vertices: one tag a vertex, or none");
  if (first + positions.size() > solid_detail::kIndexRef)
    throw std::length_error("SolidBuilder: too many vertices");
  if (!vertex_ids_.empty()) vertex_ids_.resize(first + positions.size(), kIndexedId);
  if (!tags.empty() || !vertex_tags_.empty()) {
    vertex_tags_.resize(first, -1);  // the first tag given: the earlier ones were -1
    if (tags.empty())
      vertex_tags_.resize(first + positions.size(), -1);
    else
      vertex_tags_.insert(vertex_tags_.end(), tags.begin(), tags.end());
  }
  positions_.insert(positions_.end(), positions.begin(), positions.end());
  return static_cast<VertexIndex>(first);
}

void SolidBuilder::add_face(const std::vector<std::string>& outer,
                            const std::vector<std::vector<std::string>>& holes, std::int64_t tag) {
  for (const std::string& id : outer) refs_.push_back(id_ref(id));
  end_ring();
  for (const std::vector<std::string>& hole : holes) {
    for (const std::string& id : hole) refs_.push_back(id_ref(id));
    end_ring();
  }
  end_face(tag, false);
}

void SolidBuilder::add_face_loop(const std::vector<std::string>& loop, std::int64_t tag) {
  for (const std::string& id : loop) refs_.push_back(id_ref(id));
  end_ring();
  end_face(tag, true);
}

void SolidBuilder::add_line(const std::string& a, const std::string& b, std::int64_t tag) {
  const VertexRef ra = id_ref(a);
  lines_.push_back({ra, id_ref(b), tag});
}

void SolidBuilder::add_indexed_face(std::span<const std::vector<VertexIndex>> rings, std::int64_t tag) {
  for (const std::vector<VertexIndex>& ring : rings) {
    for (VertexIndex v : ring) refs_.push_back(index_ref(v));
    end_ring();
  }
  end_face(tag, false);
}

void SolidBuilder::add_indexed_polygon(std::span<const VertexIndex> ring, std::int64_t tag) {
  for (VertexIndex v : ring) refs_.push_back(index_ref(v));
  end_ring();
  end_face(tag, false);
}

void SolidBuilder::add_indexed_face_loop(std::span<const VertexIndex> loop, std::int64_t tag) {
  for (VertexIndex v : loop) refs_.push_back(index_ref(v));
  end_ring();
  end_face(tag, true);
}

void SolidBuilder::add_indexed_polygons(std::span<const VertexIndex> vertices,
                                        std::span<const std::size_t> ends, std::int64_t first_tag) {
  for (std::size_t k = 0; k < ends.size(); ++k)
    if (ends[k] < (k == 0 ? 0 : ends[k - 1]) || ends[k] > vertices.size())
      throw std::invalid_argument("SolidBuilder::add_indexed_polygons: face ends out of order");
  const std::size_t ref0 = refs_.size(), ring0 = ring_ends_.size(), face0 = face_ends_.size();
  if (ref0 + vertices.size() > 0xffffffffu)
    throw std::length_error("SolidBuilder: too many vertex references");
  if (ring0 + ends.size() > 0xffffffffu) throw std::length_error("SolidBuilder: too many rings");
  constexpr std::size_t kPart = 16384;  // a mesh's faces go by parts side by side
  refs_.resize(ref0 + vertices.size());
  // A number too large to be an indexed reference is interned as text (index_ref), on this thread, in order.
  std::atomic<bool> too_large = false;
  parallel_indices(vertices.size(), kPart, [&](std::size_t i) {
    if (vertices[i] < solid_detail::kIndexRef)
      refs_[ref0 + i] = solid_detail::kIndexRef | vertices[i];
    else
      too_large.store(true, std::memory_order_relaxed);
  });
  if (too_large)
    for (std::size_t i = 0; i < vertices.size(); ++i)
      if (vertices[i] >= solid_detail::kIndexRef) refs_[ref0 + i] = index_ref(vertices[i]);
  ring_ends_.resize(ring0 + ends.size());
  face_ends_.resize(face0 + ends.size());
  const bool tagged = first_tag != -1 || !face_tags_.empty();
  if (tagged) face_tags_.resize(face0 + ends.size(), -1);  // (the earlier faces' -1 too, if none had one)
  parallel_indices(ends.size(), kPart, [&](std::size_t k) {
    ring_ends_[ring0 + k] = static_cast<std::uint32_t>(ref0 + ends[k]);
    face_ends_[face0 + k] = static_cast<std::uint32_t>(ring0 + k + 1);
    if (tagged) face_tags_[face0 + k] = first_tag == -1 ? -1 : first_tag + static_cast<std::int64_t>(k);
  });
  face_is_loop_.resize(face0 + ends.size(), false);
}

void SolidBuilder::add_indexed_line(VertexIndex a, VertexIndex b, std::int64_t tag) {
  const VertexRef ra = index_ref(a);
  lines_.push_back({ra, index_ref(b), tag});
}

void SolidBuilder::reserve(std::size_t vertices, std::size_t faces, std::size_t references, bool tagged) {
  positions_.reserve(positions_.size() + vertices);
  if (!vertex_ids_.empty()) vertex_ids_.reserve(vertex_ids_.size() + vertices);
  refs_.reserve(refs_.size() + references);
  if (tagged) {  // the tags stay empty while none is given: room only when they will be
    vertex_tags_.reserve(positions_.size() + vertices);
    face_tags_.reserve(face_ends_.size() + faces);
  }
  ring_ends_.reserve(ring_ends_.size() + faces);
  face_ends_.reserve(face_ends_.size() + faces);
  face_is_loop_.reserve(face_is_loop_.size() + faces);
}

namespace {

// Whether the two triangles on edge e lie in one plane exactly (their far corners coplanar with it) and
// on the same side of it: one folded back over the other.
bool folded_flat(const Solid& solid, const SolidEdge& e) {
  // Opposite normals first (the planes are at hand, the rings behind two more pointers): faces folded
  // flat face opposite ways.
  if (dot(solid.planes[static_cast<std::size_t>(e.left)].normal,
          solid.planes[static_cast<std::size_t>(e.right)].normal) >= 0)
    return false;
  const auto& left = solid.faces[static_cast<std::size_t>(e.left)];
  const auto& right = solid.faces[static_cast<std::size_t>(e.right)];
  if (left.rings.size() != 1 || right.rings.size() != 1 || left.rings[0].vertices.size() != 3 ||
      right.rings[0].vertices.size() != 3)
    return false;
  auto far_corner = [&](const Face& f) {
    for (VertexIndex v : f.rings[0].vertices)
      if (v != e.v0 && v != e.v1) return v;
    return f.rings[0].vertices[0];
  };
  const Point3 a = solid.vertices[e.v0], b = solid.vertices[e.v1];
  const Point3 c = solid.vertices[far_corner(left)], d = solid.vertices[far_corner(right)];
  if (orient3d(a, b, c, d) != 0) return false;
  return dot(cross(b - a, c - a), cross(b - a, d - a)) > 0;
}

}  // namespace

SolidBuildResult SolidBuilder::build() const {
  using namespace solid_detail;
  SolidBuildResult result;
  Diagnostics diagnostics(result.diagnostics);
  const SolidBuildOptions options = sanitized(options_);

  VertexTable vertices = resolve_vertices(positions_, Tags{vertex_tags_}, vertex_ids_, ids_,
                                          label_ ? &label_ : nullptr, diagnostics);

  // Faces are prepared in parallel chunks (resolve the references, clean, split, fit the plane; the rings
  // go straight into the solid), each chunk with its own diagnostics, joined in face order; then their
  // edges are entered in face order, which numbers them. Faces keep their input positions (invalid ones
  // stay empty; they always come with an error).
  const std::size_t n = face_ends_.size();
  const Tags face_tags{face_tags_};
  const unsigned threads = threads_for(n, 4096, 0);  // for the stages by parts below
  // The faces' lists are faulted in on every core before they are filled (core/first_touch.hpp): a
  // 10⁶-triangle mesh's take 140 MB.
  Solid solid;
  resize_touched(solid.faces, n, threads);
  resize_touched(solid.planes, n, threads);
  std::vector<char> ready(n, 0);  // valid; chars, so that chunks may write side by side
  std::vector<char> plain(n, 1);  // its rings are its cleaned loops and it has no on-face lines
  std::vector<Vector3> areas;
  resize_touched(areas, n, threads);
  std::vector<double> sizes(lines_.empty() ? 0 : n);  // only add_line needs them
  struct Chunk {
    std::vector<SolidDiagnostic> diagnostics;
    // Faces whose edges are not entered from their rings alone: their cleaned loops and on-face lines.
    std::vector<std::uint32_t> faces;
    std::vector<Loops> loops;
    std::vector<std::vector<std::pair<VertexIndex, VertexIndex>>> lines;
  };
  constexpr std::size_t kChunkFaces = 2048;
  std::vector<Chunk> chunks((n + kChunkFaces - 1) / kChunkFaces);
  parallel_chunks(chunks.size(), threads, [&](std::size_t k) {
    Chunk& chunk = chunks[k];
    Diagnostics found(chunk.diagnostics);
    FaceWork work;
    std::vector<std::string> unknown;
    for (std::size_t f = k * kChunkFaces; f < std::min(n, (k + 1) * kChunkFaces); ++f) {
      // Resolve ids; name each unknown id once.
      work.loops.clear();
      unknown.clear();
      bool resolved = true;
      for (std::size_t r = f == 0 ? 0 : face_ends_[f - 1]; r < face_ends_[f]; ++r) {
        for (std::size_t i = r == 0 ? 0 : ring_ends_[r - 1]; i < ring_ends_[r]; ++i) {
          const VertexIndex v = vertices.resolve(refs_[i]);
          if (v == kNoVertex) {
            resolved = false;
            std::string id = vertices.ref_text(refs_[i]);
            if (std::find(unknown.begin(), unknown.end(), id) == unknown.end()) {
              found.error("unknown-vertex",
                          "face " + std::to_string(f + 1) + " names vertex '" + id +
                              "' which is not declared; declare it with 'vertex " + id +
                              " = (x, y, z)' before the face",
                          face_tags[f]);
              unknown.push_back(std::move(id));
            }
            continue;
          }
          if (!vertices.usable[v]) resolved = false;  // non-finite: reported with the vertex
          work.loops.vertices.push_back(v);
        }
        work.loops.close();
      }
      if (!resolved) continue;
      if (work.loops.size() == 0) work.loops.close();  // no rings at all: one empty ring
      if (!prepare_face(work, face_is_loop_[f], static_cast<int>(f + 1), face_tags[f], vertices, options,
                        found))
        continue;
      ready[f] = 1;
      solid.planes[f] = work.plane;
      areas[f] = work.area;
      if (!sizes.empty()) sizes[f] = work.size;
      solid.faces[f].rings = std::move(work.rings);
      if (!work.rings_are_loops || !work.lines.empty()) {
        plain[f] = 0;
        chunk.faces.push_back(static_cast<std::uint32_t>(f));
        chunk.loops.push_back(work.rings_are_loops ? Loops{} : work.loops);
        chunk.lines.push_back(work.lines);
      }
    }
  });

  // Vertices at one position are looked for beside a stage that takes one thread (they only read the
  // vertex table): the edges' entry face after face, or else the orientation. Their errors go in their
  // place: after the vertex stage's, before the faces'.
  std::vector<SolidDiagnostic> twin_diagnostics;
  auto find_twins = [&] {
    Diagnostics found(twin_diagnostics);
    report_vertex_twins(vertices, Tags{vertex_tags_}, found);
  };
  tbb::task_group twins;
  auto start_twins = [&] {
    if (threads == 1)
      find_twins();
    else
      twins.run(find_twins);
  };
  const std::size_t twins_at = diagnostics.size();

  std::vector<bool> valid(ready.begin(), ready.end());
  // A closed surface names each edge twice; the vertex count lays the lookup table out in vertex order.
  const std::size_t expected_entries = refs_.size() / 2 + lines_.size(),
                    vertex_count = vertices.positions().size();
  std::vector<std::vector<SolidDiagnostic>> face_diagnostics(chunks.size());
  // Where every face's rings are its loops and no line is to be added (a mesh file, a generator), the
  // edges of 8 192 faces or more are entered by halves side by side; else face after face.
  const bool by_halves =
      lines_.empty() && threads_for(n, 4 * kChunkFaces, 0) != 1 &&
      std::all_of(chunks.begin(), chunks.end(), [](const Chunk& chunk) { return chunk.faces.empty(); });
  EdgeEntries edges = by_halves ? enter_plain_faces(solid.faces, ready, expected_entries, vertex_count)
                                : EdgeEntries(expected_entries, vertex_count);
  if (by_halves) {
    for (std::size_t k = 0; k < chunks.size(); ++k) face_diagnostics[k] = std::move(chunks[k].diagnostics);
    chunks.clear();
    start_twins();
  } else {
    start_twins();
    for (std::size_t k = 0; k < chunks.size(); ++k) {
      Chunk& chunk = chunks[k];
      face_diagnostics[k] = std::move(chunk.diagnostics);
      std::size_t special = 0;
      for (std::size_t f = k * kChunkFaces; f < std::min(n, (k + 1) * kChunkFaces); ++f) {
        prefetch_face_edges(edges, solid.faces, ready, f, n);
        if (!ready[f]) continue;
        if (plain[f]) {
          enter_face_edges(edges, static_cast<FaceIndex>(f), solid.faces[f].rings, nullptr, {});
          continue;
        }
        const Loops& loops = chunk.loops[special];
        enter_face_edges(edges, static_cast<FaceIndex>(f), solid.faces[f].rings,
                         loops.size() ? &loops : nullptr, chunk.lines[special]);
        ++special;
      }
      chunk = Chunk{};
    }
  }
  for (std::vector<SolidDiagnostic>& found : face_diagnostics) diagnostics.append(found);

  report_non_manifold(edges, face_tags, vertices, diagnostics);
  if (lines_.empty()) edges.release_index();  // only add_line looks edges up again

  solid.closed =
      orient_faces(solid.faces, solid.planes, valid, areas, face_tags, edges, vertices, options, diagnostics);
  solid.crease_angle_deg = options.crease_angle_deg;
  build_edge_table(solid, edges, valid, sizes, lines_, vertices, options, diagnostics);
  twins.wait();  // before the vertex table gives up its positions
  diagnostics.insert(twins_at, twin_diagnostics);
  solid.vertices = vertices.input_of.empty() ? positions_ : std::move(vertices.kept);
  // Triangles folded flat onto each other: in one plane exactly, on the same side of their edge.
  constexpr std::size_t kChunkEdges = 16384;
  const std::size_t edge_count = solid.edges.size();
  std::vector<char> folded((edge_count + kChunkEdges - 1) / kChunkEdges, 0);
  parallel_chunks(folded.size(), threads_for(edge_count, 2 * kChunkEdges, 0), [&](std::size_t k) {
    const auto from = solid.edges.begin() + static_cast<std::ptrdiff_t>(k * kChunkEdges);
    const auto to =
        solid.edges.begin() + static_cast<std::ptrdiff_t>(std::min(edge_count, (k + 1) * kChunkEdges));
    folded[k] = std::any_of(from, to, [&](const SolidEdge& e) {
      return e.left != kNoFace && e.right != kNoFace && e.left != e.right && folded_flat(solid, e);
    });
  });
  solid.folded = std::any_of(folded.begin(), folded.end(), [](char f) { return f != 0; });

  if (!diagnostics.has_errors()) result.solid = std::move(solid);
  return result;
}

}  // namespace hlr
