// SolidBuilder: collects the input as given, then build() checks it in stages (vertices, faces, edges,
// orientation, edge table), reporting every problem it finds rather than stopping at the first.
#include "core/solid/solid_builder.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <unordered_map>

#include "core/solid/builder_detail.hpp"

namespace hlr {

namespace solid_detail {

std::string format_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::ostringstream out;
  out << value;  // six significant digits, %g style: 0.25, 1e-06
  return out.str();
}

namespace {

// Vertex stage: ids → indices in insertion order; non-finite coordinates, duplicate ids and two ids at
// one position are errors. (`inputs` are SolidBuilder's private VertexInput records.)
VertexTable resolve_vertices(const auto& inputs, Diagnostics& diagnostics) {
  VertexTable table;
  std::vector<std::int64_t> tags;
  for (const auto& in : inputs) {
    if (table.index_of.contains(in.id)) {
      diagnostics.error("duplicate-vertex", "vertex '" + in.id + "' is declared twice; give each vertex its own id",
                        in.tag);
      continue;
    }
    const Point3 p = in.position;
    const bool finite = is_finite(p);
    if (!finite) {
      const double bad = !std::isfinite(p.x) ? p.x : (!std::isfinite(p.y) ? p.y : p.z);
      diagnostics.error("non-finite",
                        "vertex '" + in.id + "' has a non-finite coordinate (" + format_number(bad) + ")", in.tag);
    }
    table.index_of.emplace(in.id, static_cast<VertexIndex>(table.positions.size()));
    table.positions.push_back(p);
    table.ids.push_back(in.id);
    table.usable.push_back(finite);
    tags.push_back(in.tag);
  }

  double extent = 0;
  for (std::size_t i = 0; i < table.positions.size(); ++i)
    if (table.usable[i])
      for (int k = 0; k < 3; ++k) extent = std::max(extent, std::abs(table.positions[i][k]));
  table.tolerance = Tolerance::for_extent(extent);

  // Coincident positions: hash into cubic cells of twice the tolerance. A point then has neighbours
  // within the tolerance only in its own cell and, per axis, the adjacent cell on the side of the
  // nearer cell border: 8 cells to look in. Coordinates are at most 1e9 tolerances from the origin.
  const double tol = table.tolerance.length, cell = 2 * tol;
  const std::size_t n = table.positions.size();
  auto key_of = [](std::int64_t x, std::int64_t y, std::int64_t z) {
    std::uint64_t h = static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= static_cast<std::uint64_t>(z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return h;
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells;
  cells.reserve(n);
  std::vector<std::size_t> twin(n, n);  // earliest vertex at the same position
  for (std::size_t i = 0; i < n; ++i) {
    if (!table.usable[i]) continue;
    const Point3 p = table.positions[i];
    std::int64_t c[3], side[3];
    for (int k = 0; k < 3; ++k) {
      const double f = std::floor(p[k] / cell);
      c[k] = static_cast<std::int64_t>(f);
      side[k] = p[k] / cell - f < 0.5 ? -1 : 1;
    }
    for (int corner = 0; corner < 8; ++corner) {
      const auto it = cells.find(key_of(c[0] + (corner & 1 ? side[0] : 0), c[1] + (corner & 2 ? side[1] : 0),
                                        c[2] + (corner & 4 ? side[2] : 0)));
      if (it == cells.end()) continue;
      for (std::size_t j : it->second)  // hash collisions only add candidates
        if (j < twin[i] && distance(p, table.positions[j]) <= tol) twin[i] = j;
    }
    cells[key_of(c[0], c[1], c[2])].push_back(i);
  }
  for (std::size_t i = 0; i < twin.size(); ++i)
    if (twin[i] < table.positions.size())
      diagnostics.error("duplicate-vertex",
                        "vertex '" + table.ids[i] + "' is at the same position as vertex '" + table.ids[twin[i]] + "'",
                        tags[i]);
  return table;
}

// Options outside their domain (NaN, negative) fall back to the defaults rather than disabling checks.
SolidBuildOptions sanitized(SolidBuildOptions o) {
  if (!(o.crease_angle_deg >= 0)) o.crease_angle_deg = 0;
  if (!(o.planarity_tolerance >= 0)) o.planarity_tolerance = Tolerance::kPlanarity;
  return o;
}

}  // namespace
}  // namespace solid_detail

SolidBuilder::SolidBuilder(SolidBuildOptions options) : options_(options) {}

void SolidBuilder::add_vertex(const std::string& id, Point3 position, std::int64_t tag) {
  vertices_.push_back({id, position, tag});
}

void SolidBuilder::add_face(const std::vector<std::string>& outer, const std::vector<std::vector<std::string>>& holes,
                            std::int64_t tag) {
  FaceInput f{{outer}, false, tag};
  f.rings.insert(f.rings.end(), holes.begin(), holes.end());
  faces_.push_back(std::move(f));
}

void SolidBuilder::add_face_loop(const std::vector<std::string>& loop, std::int64_t tag) {
  faces_.push_back({{loop}, true, tag});
}

void SolidBuilder::add_line(const std::string& a, const std::string& b, std::int64_t tag) {
  lines_.push_back({a, b, tag});
}

SolidBuildResult SolidBuilder::build() const {
  using namespace solid_detail;
  SolidBuildResult result;
  Diagnostics diagnostics(result.diagnostics);
  const SolidBuildOptions options = sanitized(options_);

  const VertexTable vertices = resolve_vertices(vertices_, diagnostics);

  std::vector<PreparedFace> faces;
  faces.reserve(faces_.size());
  for (std::size_t i = 0; i < faces_.size(); ++i)
    faces.push_back(prepare_face(faces_[i].rings, faces_[i].from_loop, static_cast<int>(i + 1), faces_[i].tag,
                                 vertices, options, diagnostics));

  EdgeEntries edges = collect_edges(faces, vertices, diagnostics);
  const bool closed = orient_faces(faces, edges, vertices, options, diagnostics);

  Solid solid;
  solid.vertices = vertices.positions;
  solid.closed = closed;
  solid.crease_angle_deg = options.crease_angle_deg;
  // Faces keep their input positions (invalid ones stay empty; they always come with an error).
  for (PreparedFace& f : faces) {
    solid.faces.push_back(Face{f.rings});
    solid.planes.push_back(f.plane);
  }
  std::vector<LineSpec> lines;
  lines.reserve(lines_.size());
  for (const LineInput& l : lines_) lines.push_back({l.a, l.b, l.tag});
  build_edge_table(solid, edges, faces, lines, vertices, options, diagnostics);
  link_ring_edges(solid);

  if (!diagnostics.has_errors()) result.solid = std::move(solid);
  return result;
}

}  // namespace hlr
