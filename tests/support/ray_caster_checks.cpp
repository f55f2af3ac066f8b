// The three property checks of ray_caster_checks.hpp. Failure messages carry everything needed to
// reproduce a case by hand: object name, edge index and kind, the sample point, its picture position and
// the oracle's reason.
#include "tests/support/ray_caster_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <sstream>
#include <utility>

namespace hlr::test {

namespace {

const char* kind_name(EdgeKind k) {
  switch (k) {
    case EdgeKind::Feature:
      return "Feature";
    case EdgeKind::Smooth:
      return "Smooth";
    case EdgeKind::Flat:
      return "Flat";
    case EdgeKind::Boundary:
      return "Boundary";
    case EdgeKind::Marking:
      return "Marking";
    case EdgeKind::Free:
      return "Free";
    case EdgeKind::Hatch:
      return "Hatch";
  }
  return "?";
}

void fail(CheckReport& r, const CheckOptions& o, const std::string& message) {
  if (r.failures.size() < o.max_failures)
    r.failures.push_back(message);
  else if (r.failures.size() == o.max_failures)
    r.failures.push_back("... further failures omitted");
}

std::uint64_t key(std::uint32_t object, std::uint32_t edge) { return (std::uint64_t{object} << 32) | edge; }

// Edge pieces (not hidden) grouped by (object, edge).
std::map<std::uint64_t, std::vector<std::size_t>> pieces_by_edge(const FrameResult& result) {
  std::map<std::uint64_t, std::vector<std::size_t>> m;
  for (std::size_t i = 0; i < result.segments.size(); ++i) {
    const VisibleSegment& s = result.segments[i];
    if (s.source == SegmentSource::Edge && !s.hidden) m[key(s.object, s.edge)].push_back(i);
  }
  return m;
}

std::string segment_text(const Scene& scene, const VisibleSegment& s) {
  std::ostringstream m;
  const std::string name = s.object < scene.objects.size() ? scene.objects[s.object].name : "?";
  if (s.source == SegmentSource::Edge) {
    m << "edge piece of object " << s.object << " '" << name << "' edge " << s.edge;
    if (s.object < scene.objects.size() && s.edge < scene.objects[s.object].solid->edges.size())
      m << " (" << kind_name(scene.objects[s.object].solid->edges[s.edge].kind) << ")";
  } else {
    m << "intersection piece of objects " << s.object << " and " << s.other;
  }
  m << " " << str(s.p0) << " -> " << str(s.p1);
  return m.str();
}

// Is p on some face of `object` (within tol of its plane and inside or within tol of its polygon)?
bool on_surface(const Scene& scene, const RayCaster& oracle, std::uint32_t object, Point3 p) {
  const double tol = oracle.tolerance();
  for (std::uint32_t f = 0; f < scene.objects[object].solid->faces.size(); ++f) {
    if (std::abs(oracle.signed_distance(object, f, p)) > tol) continue;
    const auto prox = oracle.proximity(object, f, p);
    if (prox.inside || prox.boundary_distance <= tol) return true;
  }
  return false;
}

// Parameters t where the line p0 + t·u (u unit) crosses the edges of a face lying in a plane with it.
void ring_crossings(const Solid& s, const Face& face, Point3 p0, Vector3 u, double tol,
                    std::vector<double>& out) {
  for (const Ring& ring : face.rings)
    for (std::size_t i = 0; i < ring.vertices.size(); ++i) {
      const Point3 c = s.vertices[ring.vertices[i]],
                   d = s.vertices[ring.vertices[(i + 1) % ring.vertices.size()]];
      const Vector3 e = d - c, w0 = p0 - c;
      const double b = dot(u, e), cc = dot(e, e), dd = dot(u, w0), ee = dot(e, w0);
      const double denom = cc - b * b;
      if (denom <= 1e-12 * cc) continue;  // edge parallel to the line: its ends are crossings of neighbours
      const double t = (b * ee - cc * dd) / denom, sp = (ee - b * dd) / denom;
      if (sp < -1e-9 || sp > 1 + 1e-9) continue;
      if (distance(p0 + t * u, c + sp * e) > 10 * tol) continue;
      out.push_back(t);
    }
}

}  // namespace

std::string str(Point2 p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x << ", " << p.y << ")";
  return s.str();
}

std::string str(Point3 p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

bool in_frame(const Camera& c, Point2 s, double margin) {
  if (!c.frame) return true;
  const Rect2& f = *c.frame;
  return s.x >= f.xmin - margin && s.x <= f.xmax + margin && s.y >= f.ymin - margin && s.y <= f.ymax + margin;
}

bool in_front(const Camera& c, Point3 p) {
  return c.projection == Projection::Orthographic || c.view(p).z > c.near_depth;
}

std::string CheckReport::summary() const {
  std::ostringstream m;
  m << "drawn samples " << drawn_samples << " (ambiguous " << drawn_ambiguous << "), edge samples "
    << edge_samples << " (visible " << edge_visible << ", ambiguous " << edge_ambiguous
    << "), intersection samples " << intersection_samples << ", expected intersection samples "
    << intersection_expected << ", failures " << failures.size();
  for (const auto& f : failures) m << "\n  " << f;
  for (const auto& a : ambiguous_examples) m << "\n  ambiguous: " << a;
  return m.str();
}

std::vector<Point3> segment_samples(const VisibleSegment& s) {
  std::vector<Point3> out;
  for (double t : kSegmentSampleFractions) out.push_back(lerp(s.p0, s.p1, t));
  return out;
}

Candidate drawn_candidate(const RayCaster& oracle, std::uint32_t object, const Solid& solid,
                          const SolidEdge& e) {
  (void)solid;
  switch (e.kind) {
    case EdgeKind::Flat:
      return Candidate::No;
    case EdgeKind::Smooth:
      break;
    default:
      return Candidate::Yes;
  }
  if (e.left == kNoFace || e.right == kNoFace) return Candidate::Yes;
  const Camera& cam = oracle.camera();
  // +1 front-facing, −1 back-facing, 0 too close to edge-on to say.
  auto facing = [&](FaceIndex f) {
    const auto fi = static_cast<std::uint32_t>(f);
    double s;
    double band;
    if (cam.projection == Projection::Perspective) {
      s = oracle.signed_distance(object, fi, cam.eye_world());
      band = oracle.tolerance();
    } else {
      s = -dot(oracle.normal(object, fi), cam.direction_world());
      band = 1e-6;  // radians from edge-on
    }
    return s > band ? 1 : (s < -band ? -1 : 0);
  };
  const int a = facing(e.left), b = facing(e.right);
  if (a == 0 || b == 0) return Candidate::Ambiguous;
  return a != b ? Candidate::Yes : Candidate::No;
}

double picture_extent(const Scene& scene, const Camera& camera, const FrameResult& result) {
  if (camera.frame) {
    const Rect2& f = *camera.frame;
    return std::hypot(f.xmax - f.xmin, f.ymax - f.ymin);
  }
  // Perspective without a frame: only what lies within 45° of the view axis counts, since points near the
  // near plane far off-axis project arbitrarily far out and would make any relative tolerance useless.
  auto counts = [&](Point3 world) {
    if (camera.projection == Projection::Orthographic) return true;
    const Point3 v = camera.view(world);
    return v.z > camera.near_depth && std::abs(v.x) <= v.z && std::abs(v.y) <= v.z;
  };
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double x0 = kInf, y0 = kInf, x1 = -kInf, y1 = -kInf;
  auto grow = [&](Point3 world) {
    if (!counts(world)) return;
    const Point2 p = camera.project(world);
    x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  };
  for (const auto& s : result.segments) grow(s.p0), grow(s.p1);
  for (const auto& o : scene.objects)
    for (const Point3& p : o.solid->vertices) grow(p);
  const double extent = x0 <= x1 ? std::hypot(x1 - x0, y1 - y0) : 0.0;
  // At least the 90° field itself (focal·[−1, 1]² for perspective).
  return std::max(extent, camera.projection == Projection::Perspective ? 2 * std::abs(camera.focal) : 1e-12);
}

CheckReport check_drawn_not_hidden(const Scene& scene, const RayCaster& oracle, const FrameResult& result,
                                   const CheckOptions& options) {
  CheckReport r;
  const Camera& cam = oracle.camera();
  const double tol = oracle.tolerance();
  const double eps = options.picture_relative * picture_extent(scene, cam, result);
  for (std::size_t i = 0; i < result.segments.size(); ++i) {
    const VisibleSegment& s = result.segments[i];
    if (s.hidden) continue;
    std::ostringstream where;
    where << "segment " << i << ": " << segment_text(scene, s);
    const std::uint32_t n_objects = static_cast<std::uint32_t>(scene.objects.size());
    if (s.object >= n_objects || (s.source == SegmentSource::Intersection && s.other >= n_objects)) {
      fail(r, options, where.str() + ": object index out of range");
      continue;
    }
    if (s.source == SegmentSource::Edge) {
      const Solid& solid = *scene.objects[s.object].solid;
      if (s.edge >= solid.edges.size()) {
        fail(r, options, where.str() + ": edge index out of range");
        continue;
      }
      const SolidEdge& e = solid.edges[s.edge];
      if (drawn_candidate(oracle, s.object, solid, e) == Candidate::No)
        fail(r, options,
             where.str() + ": this edge is not drawn from here (Flat, or Smooth off the contour)");
      // The piece must lie on its edge.
      const Point3 v0 = solid.vertices[e.v0], v1 = solid.vertices[e.v1];
      const Vector3 ev = v1 - v0;
      for (Point3 p : {s.p0, s.p1}) {
        const double t = std::clamp(dot(p - v0, ev) / dot(ev, ev), 0.0, 1.0);
        if (distance(p, v0 + t * ev) > tol)
          fail(r, options, where.str() + ": end point " + str(p) + " is off its edge");
      }
    }
    // Picture coordinates must be the camera's projection of the world end points.
    const std::pair<Point3, Point2> ends[2] = {{s.p0, s.s0}, {s.p1, s.s1}};
    for (const auto& [p, pic] : ends)
      if (in_front(cam, p) && distance(cam.project(p), pic) > eps + 1e-9 * length(pic - Point2{}))
        fail(r, options,
             where.str() + ": picture point " + str(pic) + " is not the projection " + str(cam.project(p)));
    for (Point3 p : segment_samples(s)) {
      ++r.drawn_samples;
      const Verdict v = oracle.classify(p);
      if (v.visibility == Visibility::Ambiguous) {
        ++r.drawn_ambiguous;
        if (r.ambiguous_examples.size() < 3) r.ambiguous_examples.push_back(str(p) + ": " + v.reason);
      }
      if (v.visibility == Visibility::Hidden) {
        fail(r, options,
             where.str() + ": drawn sample " + str(p) + " at picture " + str(cam.project(p)) +
                 " is hidden: " + v.reason);
        break;  // one message per piece is enough
      }
      if (in_front(cam, p) && !in_frame(cam, cam.project(p), eps)) {
        fail(r, options, where.str() + ": drawn sample " + str(p) + " lies outside the picture frame");
        break;
      }
    }
  }
  // Pieces of one edge must not overlap (each shared edge is emitted once).
  for (const auto& [k, idx] : pieces_by_edge(result)) {
    const auto o = static_cast<std::uint32_t>(k >> 32), e = static_cast<std::uint32_t>(k & 0xffffffffu);
    if (o >= scene.objects.size() || e >= scene.objects[o].solid->edges.size() || idx.size() < 2) continue;
    const Solid& solid = *scene.objects[o].solid;
    const Point3 v0 = solid.vertices[solid.edges[e].v0], v1 = solid.vertices[solid.edges[e].v1];
    const Vector3 ev = v1 - v0;
    const double len2 = dot(ev, ev);
    std::vector<std::pair<double, double>> spans;
    for (std::size_t i : idx) {
      const double a = dot(result.segments[i].p0 - v0, ev) / len2,
                   b = dot(result.segments[i].p1 - v0, ev) / len2;
      spans.push_back({std::min(a, b), std::max(a, b)});
    }
    std::sort(spans.begin(), spans.end());
    const double slack = tol / std::sqrt(len2);
    for (std::size_t i = 1; i < spans.size(); ++i)
      if (spans[i].first < spans[i - 1].second - slack) {
        std::ostringstream m;
        m << "object " << o << " edge " << e << ": pieces overlap on [" << spans[i].first << ", "
          << std::min(spans[i].second, spans[i - 1].second) << "] of the edge";
        fail(r, options, m.str());
      }
  }
  return r;
}

namespace {
double world_segment_distance(Point3 p, Point3 a, Point3 b) {
  const Vector3 d = b - a;
  const double len2 = dot(d, d);
  const double t = len2 > 0 ? std::clamp(dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
  return distance(p, a + t * d);
}
}  // namespace

CheckReport check_visible_not_missing(const Scene& scene, const RayCaster& oracle, const FrameResult& result,
                                      const CheckOptions& options) {
  CheckReport r;
  const Camera& cam = oracle.camera();
  const double tol = oracle.tolerance();
  const double eps = options.picture_relative * picture_extent(scene, cam, result);
  const auto pieces = pieces_by_edge(result);
  for (std::uint32_t o = 0; o < scene.objects.size(); ++o) {
    const Solid& solid = *scene.objects[o].solid;
    for (std::uint32_t e = 0; e < solid.edges.size(); ++e) {
      const SolidEdge& edge = solid.edges[e];
      if (drawn_candidate(oracle, o, solid, edge) != Candidate::Yes) continue;
      const Point3 v0 = solid.vertices[edge.v0], v1 = solid.vertices[edge.v1];
      // An edge seen (nearly) end-on is a point on the picture: nothing need be drawn.
      if (in_front(cam, v0) && in_front(cam, v1) && distance(cam.project(v0), cam.project(v1)) < 10 * eps)
        continue;
      const auto it = pieces.find(key(o, e));
      for (int i = 0; i < options.edge_samples; ++i) {
        const double t = (i + 0.5) / options.edge_samples;
        const Point3 p = lerp(v0, v1, t);
        ++r.edge_samples;
        const Verdict v = oracle.classify(p);
        if (v.visibility == Visibility::Ambiguous) {
          ++r.edge_ambiguous;
          if (r.ambiguous_examples.size() < 3) r.ambiguous_examples.push_back(str(p) + ": " + v.reason);
        }
        if (v.visibility != Visibility::Visible) continue;
        const Point2 pic = cam.project(p);
        if (cam.frame && !in_frame(cam, pic, -eps)) continue;  // outside the frame (or on its border)
        ++r.edge_visible;
        bool covered = false;
        if (it != pieces.end())
          for (std::size_t si : it->second)
            covered =
                covered || point_segment_distance(pic, result.segments[si].s0, result.segments[si].s1) < eps;
        // Where another solid's edge lies on this one, the line is drawn once (by either): a visible
        // piece of any object through the same world point, on the same picture point, draws it.
        for (std::size_t si = 0; !covered && si < result.segments.size(); ++si) {
          const VisibleSegment& s = result.segments[si];
          covered = !s.hidden && world_segment_distance(p, s.p0, s.p1) <= tol &&
                    point_segment_distance(pic, s.s0, s.s1) < eps;
        }
        if (!covered) {
          std::ostringstream m;
          m << "missing: object " << o << " '" << scene.objects[o].name << "' edge " << e << " ("
            << kind_name(edge.kind) << ") " << str(v0) << " -> " << str(v1) << " at t = " << t << ": point "
            << str(p) << " picture " << str(pic) << " is visible but not drawn; pieces of this edge:";
          if (it == pieces.end())
            m << " none";
          else
            for (std::size_t si : it->second)
              m << " [" << str(result.segments[si].p0) << " -> " << str(result.segments[si].p1) << "]";
          fail(r, options, m.str());
          break;  // one message per edge
        }
      }
    }
  }
  return r;
}

namespace {
// How many vertices two faces of one solid have in common. Two or more: they meet along an edge and do
// not cross. One: they may still pass through each other from that vertex on.
int shared_vertices(const Face& x, const Face& y) {
  int count = 0;
  for (const Ring& rx : x.rings)
    for (VertexIndex u : rx.vertices)
      for (const Ring& ry : y.rings)
        if (std::find(ry.vertices.begin(), ry.vertices.end(), u) != ry.vertices.end()) ++count;
  return count;
}
}  // namespace

CheckReport check_intersections(const Scene& scene, const RayCaster& oracle, const FrameResult& result,
                                const CheckOptions& options) {
  CheckReport r;
  const Camera& cam = oracle.camera();
  const double tol = oracle.tolerance();
  const double eps = options.picture_relative * picture_extent(scene, cam, result);
  const auto n_objects = static_cast<std::uint32_t>(scene.objects.size());
  // (c1) returned intersection pieces lie on both surfaces and are not hidden.
  for (std::size_t i = 0; i < result.segments.size(); ++i) {
    const VisibleSegment& s = result.segments[i];
    if (s.source != SegmentSource::Intersection || s.hidden || s.object >= n_objects || s.other >= n_objects)
      continue;
    for (Point3 p : segment_samples(s)) {
      ++r.intersection_samples;
      if (!on_surface(scene, oracle, s.object, p) || !on_surface(scene, oracle, s.other, p)) {
        fail(r, options,
             "segment " + std::to_string(i) + ": " + segment_text(scene, s) + ": sample " + str(p) +
                 " is not on both solids' surfaces");
        break;
      }
      const Verdict v = oracle.classify(p);
      if (v.visibility == Visibility::Hidden) {
        fail(r, options,
             "segment " + std::to_string(i) + ": " + segment_text(scene, s) + ": sample " + str(p) +
                 " is hidden: " + v.reason);
        break;
      }
    }
  }
  // (c2) visible crossings of faces of two solids, or of two faces of one solid that share at most one
  // vertex (parts of one mesh passing through each other, a fold through a fan), open or closed, are drawn.
  for (std::uint32_t a = 0; a < n_objects; ++a)
    for (std::uint32_t b = a; b < n_objects; ++b) {
      const Solid& sa = *scene.objects[a].solid;
      const Solid& sb = *scene.objects[b].solid;
      std::vector<std::size_t> pair_pieces;
      for (std::size_t i = 0; i < result.segments.size(); ++i) {
        const VisibleSegment& s = result.segments[i];
        if (s.source == SegmentSource::Intersection && !s.hidden &&
            ((s.object == a && s.other == b) || (s.object == b && s.other == a)))
          pair_pieces.push_back(i);
      }
      for (std::uint32_t fa = 0; fa < sa.faces.size(); ++fa)
        for (std::uint32_t fb = a == b ? fa + 1 : 0; fb < sb.faces.size(); ++fb) {
          if (a == b && shared_vertices(sa.faces[fa], sb.faces[fb]) >= 2) continue;
          const Vector3 na = oracle.normal(a, fa), nb = oracle.normal(b, fb);
          const Vector3 dir = cross(na, nb);
          if (length(dir) < 1e-6) continue;  // (nearly) parallel planes: no transversal crossing
          // The line where the planes meet: p0 solves na·p = ha, nb·p = hb, with p0 ⟂ dir.
          const double ha = -oracle.signed_distance(a, fa, Point3{}),
                       hb = -oracle.signed_distance(b, fb, Point3{});
          const double c = dot(na, nb), det = 1 - c * c;
          const Point3 p0 = to_point(((ha - hb * c) / det) * na + ((hb - ha * c) / det) * nb);
          const Vector3 u = normalize(dir);
          std::vector<double> ts;
          ring_crossings(sa, sa.faces[fa], p0, u, tol, ts);
          ring_crossings(sb, sb.faces[fb], p0, u, tol, ts);
          if (ts.size() < 2) continue;
          std::sort(ts.begin(), ts.end());
          for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
            if (ts[k + 1] - ts[k] < 10 * tol) continue;
            for (int j = 0; j < 5; ++j) {
              const Point3 p = p0 + (ts[k] + (j + 0.5) / 5 * (ts[k + 1] - ts[k])) * u;
              const auto pa = oracle.proximity(a, fa, p), pb = oracle.proximity(b, fb, p);
              // Only points strictly inside both faces: there the surfaces cross transversally.
              if (!pa.inside || !pb.inside || pa.boundary_distance <= tol || pb.boundary_distance <= tol)
                continue;
              if (oracle.classify(p).visibility != Visibility::Visible) continue;
              const Point2 pic = cam.project(p);
              if (cam.frame && !in_frame(cam, pic, -eps)) continue;
              ++r.intersection_expected;
              bool covered = false;
              for (std::size_t si : pair_pieces)
                covered = covered ||
                          point_segment_distance(pic, result.segments[si].s0, result.segments[si].s1) < eps;
              if (!covered) {
                std::ostringstream m;
                m << "missing intersection: objects " << a << " '" << scene.objects[a].name << "' face " << fa
                  << " and " << b << " '" << scene.objects[b].name << "' face " << fb << " cross at "
                  << str(p) << " picture " << str(pic) << ", visible but not drawn (" << pair_pieces.size()
                  << " intersection pieces for this pair)";
                fail(r, options, m.str());
                break;
              }
            }
          }
        }
    }
  return r;
}

CheckReport check_frame(const Scene& scene, const Camera& camera, const FrameResult& result,
                        const CheckOptions& options) {
  const RayCaster oracle(scene, camera);
  CheckReport r = check_drawn_not_hidden(scene, oracle, result, options);
  CheckReport b = check_visible_not_missing(scene, oracle, result, options);
  r.edge_samples = b.edge_samples, r.edge_visible = b.edge_visible, r.edge_ambiguous = b.edge_ambiguous;
  for (auto& f : b.failures) r.failures.push_back(std::move(f));
  if (r.ambiguous_examples.empty()) r.ambiguous_examples = std::move(b.ambiguous_examples);
  if (options.intersections) {
    CheckReport c = check_intersections(scene, oracle, result, options);
    r.intersection_samples = c.intersection_samples, r.intersection_expected = c.intersection_expected;
    for (auto& f : c.failures) r.failures.push_back(std::move(f));
  }
  return r;
}

}  // namespace hlr::test
