// Hatch lines on the faces of a solid (hatching.hpp): a scan of each face by parallel lines.
#include "core/solid/hatching.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/tolerance.hpp"

namespace hlr {
namespace {

constexpr double kPi = 3.14159265358979323846;

// One set of parallel lines on a face: the points x with dot(across, x) = k · step + offset, k whole, each
// line running along `along`. The offset, half the spacing, keeps lines off the edges of faces whose
// corners sit on whole multiples of it (a box of unit size hatched a quarter apart); the coarser tones'
// steps are multiples of the spacing, so their lines are lines of the finer tones too.
struct LineSet {
  Vector3 along, across;
  double step = 0, offset = 0;
};

// The face's horizontal: z × n, or x when the face faces straight up or down.
Vector3 face_horizontal(Vector3 n) {
  const Vector3 h = cross(Vector3{0, 0, 1}, n);
  const double len = length(h);
  // Level within the tolerance: its horizontal is any direction, take x.
  if (len < Tolerance::kHatchDirection) return Vector3{1, 0, 0};
  return h / len;
}

// Planes: the planes dot(m, x) = k · step + offset cut the face along n × m. Every face uses the same m, so a
// plane meets the two faces of an edge at one point, found from the edge alone: the lines run on unbroken
// across the faces. A face parallel to the planes gets none of them. The crossing set (crossing_step > 0)
// is cut by planes at right angles, normal to m × z (x when m is upright).
int plane_sets(const HatchSpec& spec, Vector3 n, double step, double crossing_step, LineSet out[2]) {
  const Vector3 m = normalize(*spec.planes);
  Vector3 m2 = cross(m, Vector3{0, 0, 1});
  m2 = length(m2) < Tolerance::kHatchDirection ? Vector3{1, 0, 0} : normalize(m2);
  int count = 0;
  const Vector3 normals[2] = {m, m2};
  const double steps[2] = {step, crossing_step};
  for (int s = 0; s < 2; ++s) {
    if (steps[s] <= 0) continue;
    const Vector3 along = cross(n, normals[s]);
    // Parallel to the planes within the tolerance: no line crosses the face (or all of it lies in one).
    if (length(along) < Tolerance::kHatchDirection) continue;
    out[count++] = {normalize(along), normals[s], steps[s], spec.spacing / 2};
  }
  return count;
}

// The sets of lines face `n` gets: none, one, or one and its crossing set.
int line_sets(const HatchSpec& spec, Vector3 n, LineSet out[2]) {
  double step = spec.spacing;
  bool crossing = spec.cross;
  double crossing_step = step;
  if (spec.light) {
    const double lit = std::max(0.0, dot(n, normalize(*spec.light)));
    const double dark = 1 - lit;
    if (dark < 0.25) return 0;
    if (dark < 0.5) {
      step *= 4;
    } else if (dark < 0.75) {
      step *= 2;
    } else if (!crossing) {
      crossing = true;
      crossing_step = 2 * step;  // the darkest tone: a crossing set every second line
    }
    if (spec.cross) crossing_step = step;
  }
  if (spec.planes) return plane_sets(spec, n, step, crossing ? crossing_step : 0, out);
  const Vector3 h = face_horizontal(n), up = cross(n, h);
  const double a = spec.angle_deg * kPi / 180;
  const Vector3 along = h * std::cos(a) + up * std::sin(a);
  out[0] = {along, cross(n, along), step, spec.spacing / 2};
  if (!crossing) return 1;
  out[1] = {out[0].across * -1.0, along, crossing_step, spec.spacing / 2};
  return 2;
}

// The range of k whose lines meet values in [lo, hi].
std::pair<double, double> line_range(double lo, double hi, const LineSet& set) {
  return {std::ceil((lo - set.offset) / set.step), std::floor((hi - set.offset) / set.step)};
}

struct Crossing {
  double along;  // where on the line
  Point3 at;
};

// Whether face f is one the spec hatches (HatchSpec::only_in_plane).
bool hatches_face(const Solid& solid, std::size_t f, const HatchSpec& spec) {
  if (!spec.only_in_plane) return true;
  const Plane& plane = *spec.only_in_plane;
  if (dot(solid.planes[f].normal, plane.normal) < 1 - Tolerance::kHatchDirection) return false;
  for (const VertexIndex v : solid.faces[f].rings[0].vertices)
    if (std::abs(plane.signed_distance(solid.vertices[v])) > spec.in_plane_tolerance) return false;
  return true;
}

}  // namespace

std::size_t hatch_line_bound(const Solid& solid, const HatchSpec& spec) {
  double total = 0;
  for (std::size_t f = 0; f < solid.faces.size(); ++f) {
    if (solid.faces[f].rings.empty() || !hatches_face(solid, f, spec)) continue;
    LineSet sets[2];
    const int n = line_sets(spec, solid.planes[f].normal, sets);
    for (int s = 0; s < n; ++s) {
      double lo = INFINITY, hi = -INFINITY;
      for (const VertexIndex v : solid.faces[f].rings[0].vertices) {
        const double c = dot(sets[s].across, to_vector(solid.vertices[v]));
        lo = std::min(lo, c);
        hi = std::max(hi, c);
      }
      const auto [k0, k1] = line_range(lo, hi, sets[s]);
      total += std::max(0.0, k1 - k0 + 1);
    }
  }
  return total >= 1e18 ? static_cast<std::size_t>(1e18) : static_cast<std::size_t>(total);
}

Solid hatched(const Solid& solid, const HatchSpec& spec) {
  if (!(std::isfinite(spec.spacing) && spec.spacing > 0))
    throw std::invalid_argument("the hatch spacing must be a positive number");
  if (spec.light && !(length(*spec.light) > 0 && std::isfinite(length(*spec.light))))
    throw std::invalid_argument("the light direction must not be the zero vector");
  if (spec.planes && !(length(*spec.planes) > 0 && std::isfinite(length(*spec.planes))))
    throw std::invalid_argument("the planes' normal must not be the zero vector");
  Solid out = solid;
  std::vector<Crossing> crossings;
  for (std::size_t f = 0; f < solid.faces.size(); ++f) {
    const Face& face = solid.faces[f];
    if (face.rings.empty() || !hatches_face(solid, f, spec)) continue;
    const Vector3 n = solid.planes[f].normal;
    if (!(length(n) > 0)) continue;
    LineSet sets[2];
    const int count = line_sets(spec, n, sets);
    for (int s = 0; s < count; ++s) {
      const LineSet& set = sets[s];
      double lo = INFINITY, hi = -INFINITY;
      for (const VertexIndex v : face.rings[0].vertices) {
        const double c = dot(set.across, to_vector(solid.vertices[v]));
        lo = std::min(lo, c);
        hi = std::max(hi, c);
      }
      const auto [k0, k1] = line_range(lo, hi, set);
      for (double k = k0; k <= k1; ++k) {
        const double level = k * set.step + set.offset;
        crossings.clear();
        for (const Ring& ring : face.rings) {
          const std::size_t m = ring.vertices.size();
          for (std::size_t i = 0; i < m; ++i) {
            // From the lower vertex index, so the face across this side finds the very same point.
            VertexIndex a = ring.vertices[i], b = ring.vertices[(i + 1) % m];
            if (a > b) std::swap(a, b);
            const Point3 pa = solid.vertices[a], pb = solid.vertices[b];
            const double ca = dot(set.across, to_vector(pa)), cb = dot(set.across, to_vector(pb));
            // Half-open: a corner on the line counts as above it, so a line through a corner crosses the
            // outline there once or not at all, as the sides round it go on.
            if ((ca < level) == (cb < level)) continue;
            const Point3 at = pa + (pb - pa) * ((level - ca) / (cb - ca));
            crossings.push_back({dot(set.along, to_vector(at)), at});
          }
        }
        std::sort(crossings.begin(), crossings.end(),
                  [](const Crossing& x, const Crossing& y) { return x.along < y.along; });
        // Even-odd, as faces are filled: inside between the first and second crossing, and so on.
        for (std::size_t i = 0; i + 1 < crossings.size(); i += 2) {
          if (!(crossings[i + 1].along > crossings[i].along)) continue;
          const auto v0 = static_cast<VertexIndex>(out.vertices.size());
          out.vertices.push_back(crossings[i].at);
          out.vertices.push_back(crossings[i + 1].at);
          SolidEdge e;
          e.v0 = v0;
          e.v1 = v0 + 1;
          e.left = e.right = static_cast<FaceIndex>(f);
          e.kind = EdgeKind::Hatch;
          out.edges.push_back(e);
        }
      }
    }
  }
  return out;
}

}  // namespace hlr
