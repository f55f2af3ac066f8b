// From a raw mesh to a validated Solid: exact welding, per-face repairs (repeated vertices, degenerate
// and duplicate faces, non-planar polygons), then SolidBuilder (winding, manifoldness, edge kinds), whose
// diagnostics are mapped back to the file's own face numbers and lines.
#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "core/format_number.hpp"
#include "core/parallel.hpp"
#include "core/release_memory.hpp"
#include "core/solid/solid_builder.hpp"
#include "core/tolerance.hpp"
#include "stdlib/face_cycles.hpp"
#include "stdlib/mesh_detail.hpp"
#include "stdlib/mesh_warnings.hpp"

namespace hlr::stdlib::mesh_detail {

namespace {

// Total work allowed for ear clipping in one import (vertex visits): plenty for real data, a bound for
// adversarial files with huge non-planar polygons.
constexpr std::int64_t kTriangulationBudget = 400'000'000;

// Diagnostic tags carry what they point at: kind in the high bits, index below.
enum class TagKind : std::int64_t { Vertex = 1, Face = 2, Line = 3 };
std::int64_t make_tag(TagKind kind, std::size_t index) {
  return (static_cast<std::int64_t>(kind) << 40) | static_cast<std::int64_t>(index);
}

class Builder {
 public:
  Builder(RawMesh& raw, const MeshImportOptions& options) : raw_(raw), options_(options) {
    for (MeshProblem& p : raw_.warnings) warnings_.add("parse", std::move(p));
  }

  ImportedMesh run() {
    weld();
    const std::size_t n = raw_.face_count();
    // Faces already read: backed by data.
    out_vertices_.reserve(raw_.face_vertices.size());
    out_ends_.reserve(n);
    out_raw_.reserve(n);
    // Most faces need no repair: they are found side by side in parts (their cycle's hash with them), so
    // that what must go in file order — duplicates, repairs and their warnings — is all that is left.
    std::vector<std::uint64_t> hashes(n);  // (released with `plain` before the builder runs)
    std::vector<char> plain(n, 0);
    constexpr std::size_t kPartFaces = 4096;
    parallel_chunks((n + kPartFaces - 1) / kPartFaces, threads_for(n, 2 * kPartFaces, 0), [&](std::size_t k) {
      std::vector<std::uint32_t> ring, scratch, key;
      for (std::size_t f = k * kPartFaces; f < std::min(n, (k + 1) * kPartFaces); ++f) {
        if (const std::span<const std::uint32_t> face = raw_.face(f); face.size() == 3) {
          // A triangle, as below without its vectors: three distinct vertices, some area.
          const std::uint32_t t[3] = {canon_[face[0]], canon_[face[1]], canon_[face[2]]};
          Vector3 normal;
          double size = 0;
          if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] || is_zero_area(t, normal, size)) continue;
          plain[f] = 1;
          hashes[f] = triangle_cycle_hash(t[0], t[1], t[2]);
          continue;
        }
        std::uint32_t repeated_vertex = 0;
        if (clean_ring(f, ring, repeated_vertex) || ring.size() < 3) continue;
        const FaceShape shape = shape_of(ring, scratch);
        if (shape.distinct != ring.size() || shape.zero_area || shape.non_planar) continue;
        plain[f] = 1;
        canonical_cycle(ring, key);
        hashes[f] = cycle_hash(key);
      }
    });
    // A mesh whose every face is kept as it is, none repeating another (a scan, a CAD export), passes its
    // faces on as they are, by parts side by side; any other goes face by face, in file order, for its
    // repairs and their messages.
    const bool as_read = n >= kPartFaces &&
                         std::all_of(plain.begin(), plain.end(), [](char p) { return p != 0; }) &&
                         !any_repeated_cycle(hashes, [&](std::size_t a, std::size_t b) {
                           std::vector<std::uint32_t> ring_a, ring_b, key_a, key_b;
                           std::uint32_t ignored = 0;
                           clean_ring(a, ring_a, ignored), clean_ring(b, ring_b, ignored);
                           canonical_cycle(ring_a, key_a), canonical_cycle(ring_b, key_b);
                           return key_a == key_b;
                         });
    if (as_read) {
      pass_on_as_read();
    } else {
      seen_ = FaceCycleSet(n);
      constexpr std::size_t kAhead = 16;  // faces whose slot is asked for ahead of its lookup
      for (std::size_t f = 0; f < n; ++f) {
        if (f + kAhead < n && plain[f + kAhead]) seen_.prefetch(hashes[f + kAhead]);
        if (!plain[f]) {
          add_face(f);
          continue;
        }
        std::uint32_t ignored = 0;
        clean_ring(f, ring_, ignored);
        if (!is_duplicate(ring_, f, hashes[f])) push_face(ring_, f);
      }
    }
    release(hashes), release(plain), seen_ = FaceCycleSet();
    for (std::size_t l = 0; l < raw_.lines.size(); ++l) add_line(l);
    if (out_ends_.empty() && lines_.empty())
      fail(raw_.files.back(), 0, 0,
           n == 0 ? "the file defines no faces" : "every face of the file is degenerate",
           "a mesh needs at least one face with three distinct, non-collinear vertices");
    return build();
  }

 private:
  struct BuiltLine {
    std::uint32_t a, b;
    std::size_t raw;
  };

  MeshProblem at(const Source& s, std::string message, std::string hint = {}) const {
    return {raw_.files[static_cast<std::size_t>(s.file)], s.line, s.column, std::move(message),
            std::move(hint)};
  }
  std::string face_name(std::size_t f) const {
    std::string s = std::string(raw_.face_noun) + " " + std::to_string(f + 1);
    if (raw_.face_sources[f].offset >= 0)
      s += " (byte offset " + std::to_string(raw_.face_sources[f].offset) + ")";
    return s;
  }
  std::string vertex_name(std::uint32_t v) const {
    return std::to_string(static_cast<std::int64_t>(v) + raw_.vertex_base);
  }
  [[noreturn]] void fail_at(const Source& s, std::string message, std::string hint = {}) const {
    throw MeshImportError(at(s, std::move(message), std::move(hint)));
  }

  // Exact duplicates become one vertex (-0 and +0 are equal). Reported unless the format has no indices.
  void weld() {
    const std::size_t n = raw_.vertices.size();
    canon_.resize(n);
    positions_.resize(n);
    for (std::size_t i = 0; i < n; ++i) positions_[i] = raw_.vertices[i].position;
    if (raw_.welded_by_format) {  // welded while read: every vertex is its own
      for (std::size_t i = 0; i < n; ++i) canon_[i] = static_cast<std::uint32_t>(i);
      return;
    }
    std::vector<bool> used(n, false);
    for (std::uint32_t v : raw_.face_vertices) used[v] = true;
    for (const RawLine& l : raw_.lines) used[l.a] = used[l.b] = true;
    ExactPointIndex first(n);  // n vertices were read, so this is backed by data
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t j = first.insert(positions_[i], static_cast<std::uint32_t>(i),
                                           [&](std::uint32_t k) { return positions_[k]; });
      canon_[i] = j;
      if (j != i && used[i])
        warnings_.add("merged-vertex",
                      at(raw_.vertices[i].where,
                         "vertex " + vertex_name(static_cast<std::uint32_t>(i)) +
                             " is at the same position as vertex " + vertex_name(j) + "; merged them",
                         "list each vertex once and reuse its index"));
    }
  }

  // Face f's ring through the welding, a vertex repeated in a row (also last = first) dropped; returns
  // whether one was, and which first.
  bool clean_ring(std::size_t f, std::vector<std::uint32_t>& ring, std::uint32_t& repeated_vertex) const {
    ring.clear();
    bool repeated = false;
    for (std::uint32_t raw_v : raw_.face(f)) {
      const std::uint32_t v = canon_[raw_v];
      if (!ring.empty() && ring.back() == v) {
        if (!repeated) repeated_vertex = v;
        repeated = true;
        continue;
      }
      ring.push_back(v);
    }
    while (ring.size() > 1 && ring.back() == ring.front()) {
      if (!repeated) repeated_vertex = ring.back();
      repeated = true;
      ring.pop_back();
    }
    return repeated;
  }

  // Whether a ring of distinct vertices has no area to speak of, with its Newell normal (its length is twice
  // the area) and its box's diagonal. The builder's zero-area floor is kRelative · size²; dropping up to 4×
  // that keeps us clear of it.
  bool is_zero_area(std::span<const std::uint32_t> ring, Vector3& normal, double& size) const {
    const std::vector<Point3>& pos = positions_;
    normal = newell_normal(pos, ring);
    Point3 lo = pos[ring[0]], hi = lo;
    for (std::uint32_t v : ring) {
      lo = {std::min(lo.x, pos[v].x), std::min(lo.y, pos[v].y), std::min(lo.z, pos[v].z)};
      hi = {std::max(hi.x, pos[v].x), std::max(hi.y, pos[v].y), std::max(hi.z, pos[v].z)};
    }
    size = distance(lo, hi);
    return !(length(normal) > 4 * Tolerance::kRelative * std::max(size, Tolerance::kFloor) * size);
  }

  // What the per-face repairs look at: distinct vertices, then (with three or more) area and flatness.
  struct FaceShape {
    std::size_t distinct = 0;
    Vector3 normal{};  // Newell's: its length is twice the area
    bool zero_area = false, non_planar = false;
    double worst = 0;  // the farthest vertex's distance from the plane (non_planar only)
    std::uint32_t worst_vertex = 0;
  };
  FaceShape shape_of(const std::vector<std::uint32_t>& ring, std::vector<std::uint32_t>& scratch) const {
    FaceShape shape;
    // With no vertex repeated in a row, three vertices are distinct; larger rings are counted.
    shape.distinct = ring.size();
    if (ring.size() > 3) {
      scratch.assign(ring.begin(), ring.end());
      std::sort(scratch.begin(), scratch.end());
      shape.distinct =
          static_cast<std::size_t>(std::unique(scratch.begin(), scratch.end()) - scratch.begin());
    }
    if (shape.distinct < 3) return shape;
    const std::vector<Point3>& pos = positions_;
    double size = 0;
    shape.zero_area = is_zero_area(ring, shape.normal, size);
    // Half the builder's planarity tolerance, so no face we pass on can fail its check. A triangle is
    // planar; rings with bridges (a vertex twice) go to the builder as loops.
    if (shape.zero_area || ring.size() <= 3 || shape.distinct != ring.size()) return shape;
    const Vector3 unit = normalize(shape.normal);
    Vector3 sum{};
    for (std::uint32_t v : ring) sum += to_vector(pos[v]);
    const Point3 centroid = to_point(sum / static_cast<double>(ring.size()));
    shape.worst_vertex = ring[0];
    for (std::uint32_t v : ring) {
      const double d = std::abs(dot(pos[v] - centroid, unit));
      if (d > shape.worst) shape.worst = d, shape.worst_vertex = v;
    }
    shape.non_planar = shape.worst > 0.5 * Tolerance::kPlanarity * size;
    return shape;
  }

  void add_face(std::size_t f) {
    const Source& where = raw_.face_sources[f];
    std::vector<std::uint32_t>& ring = ring_;
    std::uint32_t repeated_vertex = 0;
    const bool repeated = clean_ring(f, ring, repeated_vertex);
    const FaceShape shape = shape_of(ring, scratch_);
    if (shape.distinct < 3) {
      warnings_.add("degenerate-face",
                    at(where,
                       face_name(f) + " has only " + std::to_string(shape.distinct) +
                           (shape.distinct == 1 ? " distinct vertex" : " distinct vertices") + "; dropped it",
                       "a face needs at least three distinct vertices"));
      return;
    }
    if (shape.zero_area) {
      warnings_.add("degenerate-face",
                    at(where, face_name(f) + " has zero area (its vertices are collinear); dropped it",
                       "remove the face from the file"));
      return;
    }
    if (repeated)
      warnings_.add("repeated-vertex", at(where,
                                          face_name(f) + " lists vertex " + vertex_name(repeated_vertex) +
                                              " twice in a row; dropped the repeat",
                                          ""));
    canonical_cycle(ring, key_);
    if (is_duplicate(ring, f, cycle_hash(key_))) return;
    if (shape.non_planar) {
      split_non_planar(f, shape.normal, shape.worst, shape.worst_vertex);
      return;
    }
    push_face(ring, f);
  }

  void split_non_planar(std::size_t f, Vector3 normal, double worst, std::uint32_t worst_vertex) {
    const std::vector<Point3>& pos = positions_;
    const Source& where = raw_.face_sources[f];
    std::vector<Triangle> triangles;
    if (!triangulate(pos, ring_, normal, triangles, budget_))
      fail_at(where,
              face_name(f) + " is not planar and has too many vertices (" + std::to_string(ring_.size()) +
                  ") to triangulate",
              "split the polygon into planar faces before importing");
    std::size_t kept = 0;
    for (const Triangle& t : triangles) {
      const double tsize = std::max(
          {distance(pos[t[0]], pos[t[1]]), distance(pos[t[1]], pos[t[2]]), distance(pos[t[2]], pos[t[0]])});
      if (!(length(cross(pos[t[1]] - pos[t[0]], pos[t[2]] - pos[t[0]])) >
            4 * Tolerance::kRelative * tsize * tsize))
        continue;  // a sliver between collinear vertices: no area to draw
      push_face(t, f);
      ++kept;
    }
    warnings_.add("non-planar",
                  at(where,
                     face_name(f) + " is not planar (vertex " + vertex_name(worst_vertex) + " lies " +
                         format_for_message(worst) + " off its plane); split it into " +
                         std::to_string(kept) + " triangles",
                     "the split lines are drawn unless a crease angle hides them; model the polygon as "
                     "planar faces to avoid them"));
  }

  // A face with the same cycle of vertices as an earlier one (either direction) is dropped. `hash` is
  // cycle_hash of the ring's canonical cycle.
  bool is_duplicate(const std::vector<std::uint32_t>& ring, std::size_t f, std::uint64_t hash) {
    // A fingerprint match is checked against the earlier face's own cycle: equal cycles, not equal hashes.
    bool have_key = false;
    const std::size_t earlier = seen_.insert(hash, f, [&](std::size_t e) {
      if (!have_key) canonical_cycle(ring, key_), have_key = true;
      std::uint32_t ignored = 0;
      clean_ring(e, other_, ignored);
      canonical_cycle(other_, other_key_);
      return other_key_ == key_;
    });
    if (earlier == f) return false;
    warnings_.add("duplicate-face",
                  at(raw_.face_sources[f], face_name(f) + " repeats " + face_name(earlier) + "; dropped it",
                     "remove the duplicate from the file"));
    return true;
  }

  // Every face as read (welded), in file order.
  void pass_on_as_read() {
    const std::size_t n = raw_.face_count();
    if (n > options_.max_faces) fail_too_many_faces(options_.max_faces);
    constexpr std::size_t kPart = 65536;
    out_vertices_.resize(raw_.face_vertices.size());
    parallel_chunks((out_vertices_.size() + kPart - 1) / kPart,
                    threads_for(out_vertices_.size(), 2 * kPart, 0), [&](std::size_t k) {
                      const std::size_t end = std::min(out_vertices_.size(), (k + 1) * kPart);
                      for (std::size_t i = k * kPart; i < end; ++i)
                        out_vertices_[i] = canon_[raw_.face_vertices[i]];
                    });
    out_ends_.assign(raw_.face_ends.begin(), raw_.face_ends.end());
    out_raw_.resize(n);
    std::iota(out_raw_.begin(), out_raw_.end(), std::size_t{0});
  }

  [[noreturn]] void fail_too_many_faces(std::size_t f) const {
    fail_at(raw_.face_sources[f],
            "the mesh has more than " + std::to_string(options_.max_faces) +
                " faces after splitting non-planar ones",
            "raise the face limit or simplify the mesh");
  }

  template <typename Ring>
  void push_face(const Ring& ring, std::size_t f) {
    if (out_ends_.size() >= options_.max_faces) fail_too_many_faces(f);
    for (std::uint32_t v : ring) out_vertices_.push_back(v);  // (insert calls memcpy for a dozen bytes)
    out_ends_.push_back(out_vertices_.size());
    out_raw_.push_back(f);
  }

  void add_line(std::size_t l) {
    const RawLine& line = raw_.lines[l];
    const std::uint32_t a = canon_[line.a], b = canon_[line.b];
    if (a == b) {
      warnings_.add("degenerate-line",
                    at(line.where, "line segment from vertex " + vertex_name(a) + " to itself; dropped it"));
      return;
    }
    lines_.push_back({a, b, l});
  }

  // Builder face numbers ("face 3", "faces 3 and 5", "faces (3, 5, 9)") → the file's face numbers.
  std::string rename_faces(const std::string& message) const {
    const std::string noun = raw_.face_noun;
    std::string out;
    std::size_t i = 0;
    auto digit = [&](std::size_t k) { return k < message.size() && message[k] >= '0' && message[k] <= '9'; };
    auto number = [&]() {  // maps the number at i, advancing past it
      std::size_t k = i, n = 0;
      while (digit(k) && k - i < 18) n = n * 10 + static_cast<std::size_t>(message[k++] - '0');
      out += n >= 1 && n <= out_raw_.size() ? std::to_string(out_raw_[n - 1] + 1) : message.substr(i, k - i);
      i = k;
    };
    while (i < message.size()) {
      const bool word_start = i == 0 || !std::isalpha(static_cast<unsigned char>(message[i - 1]));
      if (word_start && message.compare(i, 6, "faces ") == 0 &&
          (digit(i + 6) || message.compare(i + 6, 1, "(") == 0)) {
        out += noun + "s ";
        i += 6;
        if (message[i] == '(') {
          out += '(';
          ++i;
          while (digit(i)) {
            number();
            if (message.compare(i, 2, ", ") == 0) out += ", ", i += 2;
          }
        } else {
          number();
          if (message.compare(i, 5, " and ") == 0 && digit(i + 5)) {
            out += " and ";
            i += 5;
            number();
          }
        }
      } else if (word_start && message.compare(i, 5, "face ") == 0 && digit(i + 5)) {
        out += noun + " ";
        i += 5;
        number();
      } else {
        out += message[i++];
      }
    }
    return out;
  }

  MeshProblem locate(const SolidDiagnostic& d) const {
    const auto kind = static_cast<TagKind>(d.tag >> 40);
    const auto index = static_cast<std::size_t>(d.tag & ((std::int64_t{1} << 40) - 1));
    std::string message = rename_faces(d.message);
    Source where{static_cast<int>(raw_.files.size()) - 1, 0, 0, -1};
    if (d.tag >= 0 && kind == TagKind::Vertex && index < raw_.vertices.size()) {
      where = raw_.vertices[index].where;
    } else if (d.tag >= 0 && kind == TagKind::Face && index < out_raw_.size()) {
      const std::size_t f = out_raw_[index];
      where = raw_.face_sources[f];
      if (where.offset >= 0)
        message += " (" + std::string(raw_.face_noun) + " " + std::to_string(f + 1) +
                   " starts at byte offset " + std::to_string(where.offset) + ")";
    } else if (d.tag >= 0 && kind == TagKind::Line && index < lines_.size()) {
      where = raw_.lines[lines_[index].raw].where;
    }
    return at(where, std::move(message));
  }

  static std::string hint_for(const std::string& code) {
    if (code == "non-manifold-edge")
      return "remove duplicate or extra faces, or split the mesh into separate files";
    if (code == "non-orientable")
      return "a one-sided surface cannot be drawn as a solid; rebuild the faces there";
    if (code == "duplicate-vertex")
      return "two vertices nearly coincide (only exact duplicates are merged on import); merge them in the "
             "file";
    return "repair the mesh in a modelling tool and export it again";
  }

  // Passes the kept vertices (raw indices, file order), the faces and the lines to a SolidBuilder and builds;
  // `spatial`: vertices and faces in spatial order, else in the file's. Fills raw_of (builder vertex → raw
  // vertex). A spatial build's messages are never shown (build() builds again in file order when there are
  // any), so out_raw_ keeps the file's face order. Where not spatial, what only fed the builder is released
  // before it runs, so that its memory is reused rather than fresh.
  SolidBuildResult build_solid(const std::vector<std::uint32_t>& kept, bool spatial,
                               std::vector<std::uint32_t>& raw_of) {
    SolidBuildOptions build_options;
    build_options.crease_angle_deg = options_.crease_angle_deg;
    build_options.fix_winding = true;
    SolidBuilder builder(build_options);
    // A large mesh's lists are filled by parts side by side.
    constexpr std::size_t kPart = 16384;
    const std::size_t nv = kept.size();
    std::vector<Point3> points(nv);
    raw_of = kept;
    if (spatial) {
      parallel_indices(nv, kPart, [&](std::size_t i) { points[i] = raw_.vertices[kept[i]].position; });
      const std::vector<std::uint32_t> order = morton_order(points);
      parallel_indices(nv, kPart, [&](std::size_t i) { raw_of[i] = kept[order[i]]; });
    }
    std::vector<VertexIndex> index_of(raw_.vertices.size(), 0);  // raw vertex → builder vertex
    std::vector<std::int64_t> tags(nv);
    parallel_indices(nv, kPart, [&](std::size_t i) {
      index_of[raw_of[i]] = static_cast<VertexIndex>(i);
      points[i] = raw_.vertices[raw_of[i]].position;
      tags[i] = make_tag(TagKind::Vertex, raw_of[i]);
    });
    builder.reserve(0, out_ends_.size(), out_vertices_.size(), true);
    builder.add_vertices(points, tags);
    release(points), release(tags);
    builder.label_indexed_vertices([&](VertexIndex i) { return vertex_name(raw_of[i]); });
    if (spatial) {
      std::vector<std::uint32_t> vertices(out_vertices_.size());
      parallel_indices(vertices.size(), kPart,
                       [&](std::size_t i) { vertices[i] = index_of[out_vertices_[i]]; });
      std::vector<std::uint32_t> ordered;
      std::vector<std::size_t> ends;
      order_faces_by_least_vertex(vertices, out_ends_, nv, ordered, ends);
      release(vertices);
      builder.add_indexed_polygons(ordered, ends, make_tag(TagKind::Face, 0));
    } else {
      parallel_indices(out_vertices_.size(), kPart,
                       [&](std::size_t i) { out_vertices_[i] = index_of[out_vertices_[i]]; });
      builder.add_indexed_polygons(out_vertices_, out_ends_, make_tag(TagKind::Face, 0));
    }
    for (std::size_t i = 0; i < lines_.size(); ++i)
      builder.add_indexed_line(index_of[lines_[i].a], index_of[lines_[i].b], make_tag(TagKind::Line, i));
    if (!spatial) release(out_vertices_), release(out_ends_);
    release(index_of);
    return builder.build();
  }

  ImportedMesh build() {
    // Only vertices some face or line uses, numbered in messages as in the file.
    const std::size_t n = raw_.vertices.size();
    std::vector<bool> used(n, false);
    for (std::uint32_t v : out_vertices_) used[v] = true;
    for (const BuiltLine& l : lines_) used[l.a] = used[l.b] = true;
    std::size_t unused = 0, first_unused = 0;
    std::vector<std::uint32_t> kept;  // the raw vertices passed on, in file order
    kept.reserve(n);
    for (std::size_t v = 0; v < n; ++v) {
      if (canon_[v] != v) continue;
      if (used[v])
        kept.push_back(static_cast<std::uint32_t>(v));
      else if (unused++ == 0)
        first_unused = v;
    }
    if (unused > 0)
      warnings_.add(
          "unused-vertex",
          at(raw_.vertices[first_unused].where,
             "vertex " + vertex_name(static_cast<std::uint32_t>(first_unused)) +
                 (unused > 1 ? " and " + std::to_string(unused - 1) + " other vertices are" : " is") +
                 " used by no face or line; left out"));
    release(used), release(canon_), release(positions_), release(raw_.face_vertices), release(raw_.face_ends);
    // A large mesh goes to the builder in spatial order (mesh_locality.cpp): the solid keeps that order,
    // and the engine's walks over it then find their vertices and neighbours near each other. The builder
    // reports problems in the order it meets them, so a mesh it finds any in is built again in the file's
    // order, for messages as they always were; a clean mesh is the same solid either way, but for numbering.
    std::vector<std::uint32_t> raw_of;  // builder vertex → raw vertex
    const bool spatial = out_ends_.size() >= kSpatialOrderFaces;
    SolidBuildResult result = build_solid(kept, spatial, raw_of);
    if (spatial && !result.diagnostics.empty()) result = build_solid(kept, false, raw_of);
    std::size_t errors = 0, inside_out = 0;
    const SolidDiagnostic* first_error = nullptr;
    std::optional<MeshProblem> first_inside_out;
    for (const SolidDiagnostic& d : result.diagnostics) {
      if (d.severity == SolidDiagnostic::Severity::Error) {
        if (errors++ == 0) first_error = &d;
        continue;
      }
      // A mesh exported inside out gets one warning, not one per face.
      if (d.code == "reoriented" && d.message.find("inside out") != std::string::npos) {
        if (inside_out++ == 0) first_inside_out = locate(d);
        continue;
      }
      warnings_.add(d.code, locate(d));
    }
    if (inside_out == 1) warnings_.add("reoriented", std::move(*first_inside_out));
    if (inside_out > 1) {
      MeshProblem p = std::move(*first_inside_out);
      p.message = std::to_string(inside_out) + " " + raw_.face_noun +
                  "s were wound clockwise seen from outside, every face of their solid (it was inside out); "
                  "reversed them";
      warnings_.add("reoriented", std::move(p));
    }
    if (first_error || !result.ok()) {
      if (!first_error) fail(raw_.files.back(), 0, 0, "the mesh is not a valid solid");
      MeshProblem p = locate(*first_error);
      if (errors > 1) p.message += " (and " + std::to_string(errors - 1) + " more problems)";
      p.hint = hint_for(first_error->code);
      throw MeshImportError(std::move(p));
    }
    return ImportedMesh{std::move(*result.solid), warnings_.finish()};
  }

  RawMesh& raw_;
  const MeshImportOptions& options_;
  Warnings warnings_;
  std::vector<std::uint32_t> canon_;
  std::vector<Point3> positions_;
  // The faces passed on, back to back (raw vertex indices, canonical), with the file face of each.
  std::vector<std::uint32_t> out_vertices_;
  std::vector<std::size_t> out_ends_;
  std::vector<std::size_t> out_raw_;
  std::vector<BuiltLine> lines_;
  FaceCycleSet seen_;  // cycle of a kept face → its file face
  // One face's ring and buffers, reused.
  std::vector<std::uint32_t> ring_, scratch_, key_, other_, other_key_;
  std::int64_t budget_ = kTriangulationBudget;
};

}  // namespace

ImportedMesh build_mesh(RawMesh raw, const MeshImportOptions& options) { return Builder(raw, options).run(); }

}  // namespace hlr::stdlib::mesh_detail
