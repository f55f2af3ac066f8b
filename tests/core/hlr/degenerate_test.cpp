// Degenerate configurations: the eye in a face's plane, edge-on faces, coincident faces, the camera inside
// a solid, everything behind the eye, open and empty scenes, free lines alone, a face seen edge-on
// through its own edge, the eye a micrometre from a face, and huge and tiny coordinates. Each case states
// the exact expected output (which edges, which pieces), never just "did not crash".
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/camera/lookat_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "core/hlr/render_frame.hpp"
#include "core/solid/solid_builder.hpp"
#include "stdlib/generators.hpp"

namespace hlr {
namespace {

std::string str(Point3 p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

std::string str(const VisibleSegment& s) {
  std::ostringstream o;
  o << (s.source == SegmentSource::Edge ? "edge " : "intersection ") << s.object << ":" << s.edge
    << (s.hidden ? " hidden " : " ") << str(s.p0) << "–" << str(s.p1);
  return o.str();
}

std::string dump(const FrameResult& r) {
  std::string out;
  for (const VisibleSegment& s : r.segments) out += "\n  " + str(s);
  return out;
}

Camera lookat(Point3 eye, Point3 target, Vector3 up = {0, 0, 1}, double near = 0) {
  LookatParameters p;
  p.eye = eye;
  p.target = target;
  p.up = up;
  p.near = near;
  return lookat_camera(p);
}

Camera ortho(Point3 eye, Point3 target, Vector3 up = {0, 0, 1}, double height = 3) {
  OrthoParameters p;
  p.eye = eye;
  p.target = target;
  p.up = up;
  p.height = height;
  return ortho_camera(p);
}

Scene scene_of(const std::vector<Solid>& solids) {
  Scene scene;
  for (std::size_t i = 0; i < solids.size(); ++i)
    scene.objects.push_back({"object" + std::to_string(i), solids[i]});
  return scene;
}

// Every world and picture coordinate finite, picture points the camera's projection of the world points,
// the statistics consistent.
void expect_sane(const FrameResult& r, const Camera& camera, const std::string& label) {
  std::size_t visible = 0;
  for (const VisibleSegment& s : r.segments) {
    EXPECT_TRUE(is_finite(s.p0) && is_finite(s.p1)) << label << ": non-finite world point " << str(s);
    EXPECT_TRUE(std::isfinite(s.s0.x) && std::isfinite(s.s0.y) && std::isfinite(s.s1.x) &&
                std::isfinite(s.s1.y))
        << label << ": non-finite picture point " << str(s);
    for (const auto& [p, q] : {std::pair{s.p0, s.s0}, std::pair{s.p1, s.s1}}) {
      const Point2 want = camera.project(p);
      EXPECT_LE(distance(want, q), 1e-7 * std::max({1.0, std::abs(want.x), std::abs(want.y)}))
          << label << ": picture point off the projection of " << str(p);
    }
    if (!s.hidden) ++visible;
  }
  EXPECT_EQ(r.stats.visible_segments, visible) << label;
}

struct Expected {
  std::uint32_t object;
  Point3 a, b;
  SegmentSource source = SegmentSource::Edge;
  bool hidden = false;
};

bool same_ends(const VisibleSegment& s, Point3 a, Point3 b, double tol) {
  return (distance(s.p0, a) <= tol && distance(s.p1, b) <= tol) ||
         (distance(s.p0, b) <= tol && distance(s.p1, a) <= tol);
}

// The result must consist of exactly the expected segments (any order, either direction).
void expect_segments(const FrameResult& r, const std::vector<Expected>& expected, double tol,
                     const std::string& label) {
  std::vector<bool> used(r.segments.size(), false);
  bool ok = true;
  for (const Expected& e : expected) {
    bool found = false;
    for (std::size_t i = 0; i < r.segments.size() && !found; ++i) {
      const VisibleSegment& s = r.segments[i];
      if (used[i] || s.object != e.object || s.source != e.source || s.hidden != e.hidden) continue;
      if (same_ends(s, e.a, e.b, tol)) found = used[i] = true;
    }
    if (!found) {
      ADD_FAILURE() << label << ": missing segment of object " << e.object << " " << str(e.a) << "–"
                    << str(e.b);
      ok = false;
    }
  }
  for (std::size_t i = 0; i < r.segments.size(); ++i)
    if (!used[i]) {
      ADD_FAILURE() << label << ": unexpected " << str(r.segments[i]);
      ok = false;
    }
  if (!ok) ADD_FAILURE() << label << ": got" << dump(r);
}

// The four edges of the axis-aligned rectangle with corners c[0..3] (in order).
std::vector<Expected> loop(std::uint32_t object, const std::vector<Point3>& c) {
  std::vector<Expected> out;
  for (std::size_t i = 0; i < c.size(); ++i) out.push_back({object, c[i], c[(i + 1) % c.size()]});
  return out;
}

std::vector<Expected> join(std::vector<Expected> a, const std::vector<Expected>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The nine edges of the unit-ish box [lo, hi] on its x = hi.x, y = lo.y and z = hi.z faces (the faces on
// view from an eye with x > hi.x, y < lo.y, z > hi.z).
std::vector<Expected> nine_edges(std::uint32_t o, Point3 lo, Point3 hi) {
  const double x0 = lo.x, y0 = lo.y, z0 = lo.z, x1 = hi.x, y1 = hi.y, z1 = hi.z;
  return {
      {o, {x0, y0, z1}, {x1, y0, z1}}, {o, {x1, y0, z1}, {x1, y1, z1}},
      {o, {x1, y1, z1}, {x0, y1, z1}}, {o, {x0, y1, z1}, {x0, y0, z1}},  // top
      {o, {x0, y0, z0}, {x1, y0, z0}}, {o, {x1, y0, z0}, {x1, y1, z0}},  // bottom of y0 and x1
      {o, {x0, y0, z0}, {x0, y0, z1}}, {o, {x1, y0, z0}, {x1, y0, z1}},
      {o, {x1, y1, z0}, {x1, y1, z1}},  // verticals
  };
}

Solid single_quad(Point3 a, Point3 b, Point3 c, Point3 d) {
  SolidBuilder builder;
  builder.add_vertex("a", a);
  builder.add_vertex("b", b);
  builder.add_vertex("c", c);
  builder.add_vertex("d", d);
  builder.add_face({"a", "b", "c", "d"});
  SolidBuildResult r = builder.build();
  for (const SolidDiagnostic& diag : r.diagnostics) ADD_FAILURE() << "[" << diag.code << "] " << diag.message;
  EXPECT_TRUE(r.ok());
  return r.ok() ? *r.solid : Solid{};
}

// A solid of free lines only, built by hand (the Solid contract: edges of kind Free on no face).
Solid free_lines(const std::vector<std::pair<Point3, Point3>>& lines) {
  Solid s;
  for (const auto& [a, b] : lines) {
    SolidEdge e;
    e.v0 = static_cast<VertexIndex>(s.vertices.size());
    s.vertices.push_back(a);
    e.v1 = static_cast<VertexIndex>(s.vertices.size());
    s.vertices.push_back(b);
    e.kind = EdgeKind::Free;
    s.edges.push_back(e);
  }
  return s;
}

// ---- the eye in a face's plane ------------------------------------------------------------------------

// The eye lies in the plane of the top face: the top is edge-on, the bottom and the y faces are seen from
// behind, only x = 1 is on view. Exactly its 4 edges, whole; the top face collapses to one picture line.
TEST(DegenerateEye, InThePlaneOfATopFace) {
  const Scene scene = scene_of({stdlib::box({0, 0, 0}, {1, 1, 1})});
  const Camera cam = lookat({3, 0.5, 1}, {0.5, 0.5, 0.5});
  const FrameResult r = render_frame(scene, cam);
  expect_sane(r, cam, "eye in top plane");
  expect_segments(r, loop(0, {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}), 1e-12, "eye in top plane");
  // All of the top face (corners and the drawn top edge) projects onto one picture line.
  const Point2 a = cam.project({0, 0, 1}), b = cam.project({1, 1, 1});
  for (Point3 p : {Point3{0, 1, 1}, Point3{1, 0, 1}, Point3{0.5, 0.5, 1}}) {
    const Point2 q = cam.project(p);
    EXPECT_NEAR(cross(b - a, q - a), 0, 1e-12);
  }
  for (const VisibleSegment& s : r.segments)
    if (s.p0.z == 1 && s.p1.z == 1) {
      EXPECT_NEAR(cross(b - a, s.s0 - a), 0, 1e-12);
      EXPECT_NEAR(cross(b - a, s.s1 - a), 0, 1e-12);
    }
}

// The same eye with a tall box B = [−3, −2] × [0.25, 0.75] × [0, 2] behind the cube. The ray from the eye
// (3, 0.5, 1) to a point (−2, y, z) crosses the plane x = 1 at height 1 + 0.4·(z − 1), inside the cube's
// x = 1 face exactly for z < 1: B's front verticals are cut exactly at the height of the eye's plane (the
// edge-on top face hides nothing), its bottom front edge is hidden, its top front edge is whole.
TEST(DegenerateEye, InThePlaneOfATopFaceOccluderCutsAtTheHorizon) {
  const Scene scene =
      scene_of({stdlib::box({0, 0, 0}, {1, 1, 1}), stdlib::box({-3, 0.25, 0}, {-2, 0.75, 2})});
  const Camera cam = lookat({3, 0.5, 1}, {0.5, 0.5, 0.5});
  const FrameResult r = render_frame(scene, cam);
  expect_sane(r, cam, "horizon cut");
  expect_segments(
      r,
      join(loop(0, {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}), {{1, {-2, 0.25, 2}, {-2, 0.75, 2}},
                                                                   {1, {-2, 0.25, 1}, {-2, 0.25, 2}},
                                                                   {1, {-2, 0.75, 1}, {-2, 0.75, 2}}}),
      1e-12, "horizon cut");
}

// ---- edge-on faces --------------------------------------------------------------------------------------

// Orthographic along (−1, 1, 0): the top and bottom are edge-on; x = 1 and y = 0 are on view: 7 edges.
TEST(DegenerateEdgeOn, OrthoAlongTheTopFacesPlane) {
  const Scene scene = scene_of({stdlib::box({0, 0, 0}, {1, 1, 1})});
  const Camera cam = ortho({5.5, -4.5, 0.5}, {0.5, 0.5, 0.5}, {0, 0, 1}, 2);
  const FrameResult r = render_frame(scene, cam);
  expect_sane(r, cam, "ortho in top plane");
  expect_segments(r,
                  join(loop(0, {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}),
                       {{0, {0, 0, 0}, {1, 0, 0}}, {0, {0, 0, 0}, {0, 0, 1}}, {0, {0, 0, 1}, {1, 0, 1}}}),
                  1e-12, "ortho in top plane");
  // Both top edges lie on the picture line y = focal·(z − 0.5) = 0.5.
  for (const VisibleSegment& s : r.segments)
    if (s.p0.z == 1 && s.p1.z == 1) {
      EXPECT_NEAR(s.s0.y, 0.5, 1e-12);
      EXPECT_NEAR(s.s1.y, 0.5, 1e-12);
    }
}

// Front view (ortho along +y): every side face is edge-on. A far box whose left edge projects exactly onto
// the near box's right silhouette edge is not hidden there (boundary points are not hidden).
TEST(DegenerateEdgeOn, FrontViewWithCoincidentSilhouettes) {
  const Scene scene = scene_of({stdlib::box({0, 0, 0}, {1, 1, 1}), stdlib::box({1, 3, 0}, {2, 4, 1})});
  const Camera cam = ortho({1, -10, 0.5}, {1, 0, 0.5}, {0, 0, 1}, 2);
  const FrameResult r = render_frame(scene, cam);
  expect_sane(r, cam, "front view");
  expect_segments(r,
                  join(loop(0, {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}),
                       loop(1, {{1, 3, 0}, {2, 3, 0}, {2, 3, 1}, {1, 3, 1}})),
                  1e-12, "front view");
}

// ---- coincident faces -----------------------------------------------------------------------------------

// Two identical boxes in the same place: neither hides the other's nine on-view edges (a face never hides
// an edge lying in its plane), and each line comes out once, as the first box's; coplanar faces produce
// no intersection lines.
TEST(DegenerateCoincident, TwoIdenticalBoxes) {
  const Solid b = stdlib::box({0, 0, 0}, {1, 1, 1});
  const Scene scene = scene_of({b, b});
  for (const Camera& cam : {lookat({3, -2, 2.5}, {0.5, 0.5, 0.5}), ortho({3, -2, 2.5}, {0.5, 0.5, 0.5})}) {
    const FrameResult r = render_frame(scene, cam);
    expect_sane(r, cam, "identical boxes " + cam.kind);
    // Each line once: the second box's nine pieces lie on the first's and are left out.
    expect_segments(r, nine_edges(0, {0, 0, 0}, {1, 1, 1}), 1e-12, "identical boxes " + cam.kind);
    EXPECT_EQ(r.stats.intersection_lines, 0u);
  }
}

// Two boxes sharing a face (stacked): the lower draws its nine edges minus the two far top edges, which
// lie behind the upper box (x = 0, z = 1 and y = 1, z = 1); the upper its nine minus the two it shares
// with the lower's front top edges. The shared face makes no
// intersection lines.
TEST(DegenerateCoincident, StackedBoxesSharingAFace) {
  const Scene scene = scene_of({stdlib::box({0, 0, 0}, {1, 1, 1}), stdlib::box({0, 0, 1}, {1, 1, 2})});
  for (const Camera& cam :
       {lookat({3.3, -2.1, 5.2}, {0.5, 0.5, 1}), ortho({3.3, -2.1, 5.2}, {0.5, 0.5, 1})}) {
    const std::string label = "stacked " + cam.kind;
    const FrameResult r = render_frame(scene, cam);
    expect_sane(r, cam, label);
    std::vector<Expected> lower;
    for (const Expected& e : nine_edges(0, {0, 0, 0}, {1, 1, 1})) {
      const bool far_top =
          e.a.z == 1 && e.b.z == 1 && ((e.a.x == 0 && e.b.x == 0) || (e.a.y == 1 && e.b.y == 1));
      if (!far_top) lower.push_back(e);
    }
    ASSERT_EQ(lower.size(), 7u);
    // The upper box's two front bottom edges lie on the lower box's front top edges: drawn once, by the
    // lower box (the earlier object).
    std::vector<Expected> upper;
    for (const Expected& e : nine_edges(1, {0, 0, 1}, {1, 1, 2}))
      if (!(e.a.z == 1 && e.b.z == 1)) upper.push_back(e);
    ASSERT_EQ(upper.size(), 7u);
    expect_segments(r, join(lower, upper), 1e-12, label);
    EXPECT_EQ(r.stats.intersection_lines, 0u) << label;
  }
}

// ---- the camera inside a solid --------------------------------------------------------------------------

// From the centre of a big box looking along +x: nothing is culled (the solid surrounds the eye) and
// nothing hides anything (it is convex). Exactly the x = 5 face's edges whole, and the four edges along x
// from the near plane (x = near = 1e-4) to x = 5.
TEST(DegenerateInside, CameraAtTheCentreOfABigBox) {
  const Scene scene = scene_of({stdlib::box({-5, -5, -5}, {5, 5, 5})});
  const Camera cam = lookat({0, 0, 0}, {1, 0, 0});
  ASSERT_DOUBLE_EQ(cam.near_depth, 1e-4);
  const FrameResult r = render_frame(scene, cam);
  expect_sane(r, cam, "inside");
  std::vector<Expected> want = loop(0, {{5, -5, -5}, {5, 5, -5}, {5, 5, 5}, {5, -5, 5}});
  for (double y : {-5.0, 5.0})
    for (double z : {-5.0, 5.0}) want.push_back({0, {1e-4, y, z}, {5, y, z}});
  expect_segments(r, want, 1e-12, "inside");
}

// An off-centre, oblique eye inside the box: every edge is visible exactly where it lies beyond the near
// plane (computed here by clipping each edge to depth ≥ near), and nowhere else.
TEST(DegenerateInside, ObliqueEyeInsideSeesEveryEdgeBeyondTheNearPlane) {
  const Solid b = stdlib::box({-5, -4, -3}, {5, 4, 3});
  const Scene scene = scene_of({b});
  const Point3 eye{1, -2, 0.5}, target{3, 1, 2};
  const Camera cam = lookat(eye, target);
  const Vector3 fwd = normalize(target - eye);
  const double near = cam.near_depth;
  std::vector<Expected> want;
  for (const SolidEdge& e : b.edges) {
    Point3 p = b.vertices[e.v0], q = b.vertices[e.v1];
    const double dp = dot(p - eye, fwd), dq = dot(q - eye, fwd);
    if (dp < near && dq < near) continue;
    if (dp < near) p = lerp(p, q, (near - dp) / (dq - dp));
    if (dq < near) q = lerp(p, q, (near - dp) / (dq - dp));
    want.push_back({0, p, q});
  }
  ASSERT_GE(want.size(), 6u);
  const FrameResult r = render_frame(scene, cam);
  expect_sane(r, cam, "oblique inside");
  expect_segments(r, want, 1e-9, "oblique inside");
}

// ---- nothing in front -----------------------------------------------------------------------------------

TEST(DegenerateBehind, EverythingBehindTheEyeDrawsNothing) {
  const Scene scene =
      scene_of({stdlib::box({-10, -1, -1}, {-5, 1, 1}), free_lines({{{-3, 0, 0}, {-1, 2, 1}}})});
  const Camera cam = lookat({0, 0, 0}, {1, 0, 0});
  HlrOptions opt;
  opt.include_hidden = true;
  const FrameResult r = render_frame(scene, cam, opt);
  EXPECT_TRUE(r.segments.empty()) << dump(r);
  EXPECT_EQ(r.stats.candidate_edges, 0u);
  EXPECT_EQ(r.stats.visible_segments, 0u);
  // Orthographic has no eye to be behind (depth −∞): the same camera axes show the box's x = −10 face,
  // which now lies in front of the line and hides its first half (picture (y, z) inside [−1, 1]²).
  const Camera o = ortho({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 4);
  const FrameResult ro = render_frame(scene, o);
  expect_sane(ro, o, "ortho behind");
  expect_segments(ro,
                  join(loop(0, {{-10, -1, -1}, {-10, 1, -1}, {-10, 1, 1}, {-10, -1, 1}}),
                       {{1, {-2, 1, 0.5}, {-1, 2, 1}}}),
                  1e-12, "ortho behind");
}

// ---- open and empty scenes ------------------------------------------------------------------------------

// One quad, an open surface: its four boundary edges are drawn whole from either side.
TEST(DegenerateOpen, SingleQuadShowsItsFourEdgesFromBothSides) {
  const Solid quad = single_quad({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
  ASSERT_FALSE(quad.closed);
  ASSERT_EQ(quad.edges.size(), 4u);
  for (const SolidEdge& e : quad.edges) EXPECT_EQ(e.kind, EdgeKind::Boundary);
  const Scene scene = scene_of({quad});
  const std::vector<Expected> want = loop(0, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  for (const Camera& cam : {lookat({0.3, -1.5, 2}, {0.5, 0.5, 0}), lookat({0.3, -1.5, -2}, {0.5, 0.5, 0}),
                            ortho({0.3, -1.5, 2}, {0.5, 0.5, 0}), ortho({0.3, -1.5, -2}, {0.5, 0.5, 0})}) {
    const std::string label = "quad " + cam.kind + " eye z " + std::to_string(cam.eye_world().z);
    const FrameResult r = render_frame(scene, cam);
    expect_sane(r, cam, label);
    expect_segments(r, want, 1e-12, label);
  }
}

// The single face hides from both sides: a box under it seen from above, a box over it seen from below.
TEST(DegenerateOpen, SingleQuadHidesFromBothSides) {
  const Solid quad = single_quad({-1, -1, 0}, {2, -1, 0}, {2, 2, 0}, {-1, 2, 0});
  const std::vector<Expected> want = loop(0, {{-1, -1, 0}, {2, -1, 0}, {2, 2, 0}, {-1, 2, 0}});
  {
    const Scene scene = scene_of({quad, stdlib::box({0.25, 0.25, -1}, {0.75, 0.75, -0.5})});
    const Camera cam = lookat({0.5, 0.4, 4}, {0.5, 0.5, 0});
    const FrameResult r = render_frame(scene, cam);
    expect_sane(r, cam, "quad over box");
    expect_segments(r, want, 1e-12, "quad over box");
  }
  {
    const Scene scene = scene_of({quad, stdlib::box({0.25, 0.25, 0.5}, {0.75, 0.75, 1})});
    const Camera cam = lookat({0.5, 0.4, -4}, {0.5, 0.5, 0});
    const FrameResult r = render_frame(scene, cam);
    expect_sane(r, cam, "quad under box");
    expect_segments(r, want, 1e-12, "quad under box");
  }
}

TEST(DegenerateEmpty, EmptySceneAndEmptySolid) {
  HlrOptions opt;
  opt.include_hidden = true;
  for (const Camera& cam : {lookat({3, -2, 2}, {0, 0, 0}), ortho({3, -2, 2}, {0, 0, 0})}) {
    for (const Scene& scene : {Scene{}, scene_of({Solid{}}), scene_of({Solid{}, Solid{}})}) {
      for (unsigned threads : {1u, 2u}) {
        opt.threads = threads;
        const FrameResult r = render_frame(scene, cam, opt);
        EXPECT_TRUE(r.segments.empty());
        EXPECT_EQ(r.stats.candidate_edges, 0u);
        EXPECT_EQ(r.stats.occluder_faces, 0u);
        EXPECT_EQ(r.stats.face_tests, 0u);
        EXPECT_EQ(r.stats.intersection_lines, 0u);
        EXPECT_EQ(r.stats.visible_segments, 0u);
      }
    }
  }
}

// Free lines alone hide nothing: all drawn whole (crossing in the picture or not); a line running past
// the eye is cut at the near plane.
TEST(DegenerateFreeLines, OnlyFreeLines) {
  const std::vector<std::pair<Point3, Point3>> lines = {
      {{0, 0, 0}, {2, 0, 0}}, {{1, -1, 0.5}, {1, 1, 0.5}}, {{0, 0, 0}, {0, 0, 2}}, {{3, 3, 3}, {3, 3, 3.5}}};
  const Point3 eye{6, -5, 4}, target{1, 0, 1};
  for (const Camera& cam : {lookat(eye, target), ortho(eye, target)}) {
    const FrameResult r = render_frame(scene_of({free_lines(lines)}), cam);
    expect_sane(r, cam, "free lines " + cam.kind);
    std::vector<Expected> want;
    for (const auto& [a, b] : lines) want.push_back({0, a, b});
    expect_segments(r, want, 1e-12, "free lines " + cam.kind);
    EXPECT_EQ(r.stats.occluder_faces, 0u);
  }
  // (1, 0, 1) → (11, −9, 7) passes beside the eye to behind it.
  const Camera cam = lookat(eye, target);
  const Point3 a{1, 0, 1}, b{11, -9, 7};
  const Vector3 fwd = normalize(target - eye);
  const double da = dot(a - eye, fwd), db = dot(b - eye, fwd);
  ASSERT_GT(da, cam.near_depth);
  ASSERT_LT(db, 0);
  const Point3 cut = lerp(a, b, (cam.near_depth - da) / (db - da));
  const FrameResult r = render_frame(scene_of({free_lines({{a, b}})}), cam);
  expect_sane(r, cam, "free line past the eye");
  expect_segments(r, {{0, a, cut}}, 1e-9, "free line past the eye");
}

// ---- a face seen edge-on through its own edge -----------------------------------------------------------

// The eye on the line of the box edge x = 0, z = 1: the top and x = 0 faces are edge-on, that edge projects
// to a point. Only the y = 0 face is on view: its 4 edges, whole.
TEST(DegenerateEdgeOn, EyeOnTheLineOfAnEdge) {
  const Scene scene = scene_of({stdlib::box({0, 0, 0}, {1, 1, 1})});
  const Camera cam = lookat({0, -3, 1}, {0.5, 0.5, 0.5});
  const FrameResult r = render_frame(scene, cam);
  expect_sane(r, cam, "eye on edge line");
  expect_segments(r, loop(0, {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}), 1e-12, "eye on edge line");
}

// An open quad seen exactly edge-on, the eye on the line of one of its edges: that edge is a point in the
// picture (not drawn), the other three lie on the horizon y = 0 and nothing hides them.
TEST(DegenerateEdgeOn, OpenQuadEdgeOnThroughItsOwnEdge) {
  const Scene scene = scene_of({single_quad({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0})});
  const Camera cam = lookat({0, -3, 0}, {0.5, 0.5, 0});
  const FrameResult r = render_frame(scene, cam);
  expect_sane(r, cam, "quad edge-on");
  expect_segments(r, {{0, {0, 0, 0}, {1, 0, 0}}, {0, {1, 0, 0}, {1, 1, 0}}, {0, {1, 1, 0}, {0, 1, 0}}}, 1e-12,
                  "quad edge-on");
  for (const VisibleSegment& s : r.segments) {
    EXPECT_NEAR(s.s0.y, 0, 1e-12);
    EXPECT_NEAR(s.s1.y, 0, 1e-12);
  }
}

// ---- the eye very close to a face -----------------------------------------------------------------------

TEST(DegenerateEye, OneMicrometreAboveTheTopFace) {
  const Scene scene = scene_of({stdlib::box({0, 0, 0}, {1, 1, 1})});
  const Point3 eye{0.5, 0.5, 1 + 1e-6};
  {
    // Near plane closer than the face: the box is wholly in front, only the top is on view: its 4 edges
    // whole, at picture coordinates ≈ focal·0.5/1e-6.
    const Camera cam = lookat(eye, {0.5, 0.5, 0.5}, {0, 1, 0}, 1e-7);
    const FrameResult r = render_frame(scene, cam);
    expect_sane(r, cam, "near 1e-7");
    expect_segments(r, loop(0, {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}), 1e-12, "near 1e-7");
    for (const VisibleSegment& s : r.segments)
      for (Point2 q : {s.s0, s.s1}) {
        EXPECT_NEAR(std::abs(q.x), cam.focal * 0.5 / 1e-6, 1e-3 * cam.focal * 0.5 / 1e-6);
        EXPECT_NEAR(std::abs(q.y), cam.focal * 0.5 / 1e-6, 1e-3 * cam.focal * 0.5 / 1e-6);
      }
  }
  {
    // Default near plane (1e-4 · 0.5 beyond the eye) lies below the top face: the top is cut away and the
    // inside shows: the bottom's 4 edges whole and the verticals from the near plane down.
    const Camera cam = lookat(eye, {0.5, 0.5, 0.5}, {0, 1, 0});
    const double zcut = eye.z - cam.near_depth;
    ASSERT_LT(zcut, 1);
    const FrameResult r = render_frame(scene, cam);
    expect_sane(r, cam, "default near");
    std::vector<Expected> want = loop(0, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    for (double x : {0.0, 1.0})
      for (double y : {0.0, 1.0}) want.push_back({0, {x, y, 0}, {x, y, zcut}});
    expect_segments(r, want, 1e-12, "default near");
  }
}

// ---- huge and tiny coordinates --------------------------------------------------------------------------

// A scene with occlusion, a concave solid and intersection lines, rendered at scale 1 and again scaled by
// 1e6 and 1e-6 (scene and camera) and translated far from the origin: the same visible segments (same
// edges, same order) with the same picture coordinates and world points that scale, and the same hidden
// length per edge. (How the hidden layer is split into pieces is checked in engine_cases_test.cpp.)
std::vector<Solid> scale_scene() {
  return {stdlib::box({0, 0, 0}, {1, 1, 1}), stdlib::box({-0.5, 2, -0.25}, {1.5, 3, 0.75}),
          stdlib::l_block({1.5, -1, 0}, {2, 1, 2}, 1, 1), stdlib::box({0.2, 2.5, 0.5}, {0.6, 2.8, 1.2}),
          stdlib::sphere({3, 2, 0.5}, 0.6, 8, 5, 0)};
}

std::vector<VisibleSegment> visible_only(const FrameResult& r) {
  std::vector<VisibleSegment> out;
  for (const VisibleSegment& s : r.segments)
    if (!s.hidden) out.push_back(s);
  return out;
}

// Total hidden world length per (source, object, edge): the hidden layer's extent, independent of how it
// is split into pieces.
std::map<std::tuple<int, std::uint32_t, std::uint32_t>, double> hidden_lengths(const FrameResult& r,
                                                                               double scale) {
  std::map<std::tuple<int, std::uint32_t, std::uint32_t>, double> out;
  for (const VisibleSegment& s : r.segments)
    if (s.hidden) out[{static_cast<int>(s.source), s.object, s.edge}] += distance(s.p0, s.p1) / scale;
  return out;
}

// The visible segments must be the same (same edges, same pieces, same order) with the same picture
// coordinates and world points mapped by `map`; the hidden layer must cover the same length of each edge.
void expect_same_topology(const FrameResult& ref_all, const FrameResult& got_all, const Affine3& map,
                          double scale, double world_tol, double picture_tol, const std::string& label) {
  const std::vector<VisibleSegment> ref = visible_only(ref_all), got = visible_only(got_all);
  ASSERT_EQ(ref.size(), got.size()) << label << ": reference" << dump(ref_all) << "\ngot" << dump(got_all);
  for (std::size_t i = 0; i < ref.size(); ++i) {
    const VisibleSegment &a = ref[i], &b = got[i];
    ASSERT_EQ(a.source, b.source) << label << " #" << i;
    ASSERT_EQ(a.object, b.object) << label << " #" << i;
    ASSERT_EQ(a.edge, b.edge) << label << " #" << i;
    ASSERT_EQ(a.other, b.other) << label << " #" << i;
    EXPECT_LE(distance(a.s0, b.s0), picture_tol) << label << " #" << i << " " << str(a);
    EXPECT_LE(distance(a.s1, b.s1), picture_tol) << label << " #" << i << " " << str(a);
    EXPECT_LE(distance(map.apply(a.p0), b.p0), world_tol) << label << " #" << i << " " << str(a);
    EXPECT_LE(distance(map.apply(a.p1), b.p1), world_tol) << label << " #" << i << " " << str(a);
  }
  const auto hr = hidden_lengths(ref_all, 1), hg = hidden_lengths(got_all, scale);
  ASSERT_EQ(hr.size(), hg.size()) << label << ": a different set of edges has hidden parts";
  for (const auto& [key, len] : hr) {
    const auto it = hg.find(key);
    ASSERT_TRUE(it != hg.end()) << label << ": edge " << std::get<2>(key) << " of object " << std::get<1>(key)
                                << " lost its hidden part";
    EXPECT_NEAR(it->second, len, 1e-7)
        << label << ": hidden length of edge " << std::get<2>(key) << " of object " << std::get<1>(key);
  }
}

TEST(DegenerateScale, HugeAndTinyCoordinatesKeepTheTopology) {
  const std::vector<Solid> base = scale_scene();
  const Point3 eye{5, -6, 4}, target{0.8, 0.8, 0.5};
  HlrOptions opt;
  opt.include_hidden = true;
  const FrameResult ref_p = render_frame(scene_of(base), lookat(eye, target), opt);
  const FrameResult ref_o = render_frame(scene_of(base), ortho(eye, target, {0, 0, 1}, 6), opt);
  expect_sane(ref_p, lookat(eye, target), "reference lookat");
  ASSERT_GT(ref_p.stats.intersection_lines, 0u);
  ASSERT_GT(ref_p.stats.visible_segments, 40u);
  // Some edges are cut: the scene really exercises occlusion.
  std::size_t hidden = 0;
  for (const VisibleSegment& s : ref_p.segments) hidden += s.hidden && s.source == SegmentSource::Edge;
  ASSERT_GT(hidden, 10u);

  for (double k : {1e6, 1e-6}) {
    const Affine3 map = Affine3::scaling(k, k, k);
    std::vector<Solid> solids;
    for (const Solid& s : base) solids.push_back(s.transformed(map));
    const Camera cp = lookat(map.apply(eye), map.apply(target));
    const Camera co = ortho(map.apply(eye), map.apply(target), {0, 0, 1}, 6 * k);
    const std::string label = "scale " + std::to_string(k);
    const FrameResult rp = render_frame(scene_of(solids), cp, opt);
    const FrameResult ro = render_frame(scene_of(solids), co, opt);
    expect_sane(rp, cp, label + " lookat");
    expect_sane(ro, co, label + " ortho");
    expect_same_topology(ref_p, rp, map, k, 1e-10 * k, 1e-10, label + " lookat");
    expect_same_topology(ref_o, ro, map, k, 1e-10 * k, 1e-10, label + " ortho");
  }
  {
    const Affine3 map = Affine3::translation({1e6, -2e6, 5e5});
    std::vector<Solid> solids;
    for (const Solid& s : base) solids.push_back(s.transformed(map));
    const Camera cp = lookat(map.apply(eye), map.apply(target));
    const Camera co = ortho(map.apply(eye), map.apply(target), {0, 0, 1}, 6);
    const FrameResult rp = render_frame(scene_of(solids), cp, opt);
    const FrameResult ro = render_frame(scene_of(solids), co, opt);
    expect_sane(rp, cp, "far from the origin lookat");
    expect_sane(ro, co, "far from the origin ortho");
    expect_same_topology(ref_p, rp, map, 1, 1e-7, 1e-7, "far from the origin lookat");
    expect_same_topology(ref_o, ro, map, 1, 1e-7, 1e-7, "far from the origin ortho");
  }
}

}  // namespace
}  // namespace hlr
