// Hand-computed engine cases with exact expected numbers: cuts at another solid's silhouette (orthographic
// and perspective), a T-junction, an edge seen through a hole, interpenetrating boxes and their
// intersection lines, marking lines, the hidden layer as the complement of the visible one, thread-count
// independence and picture-frame clipping. Every expected end point below is derived in the comments.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/camera/lookat_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "core/hlr/render_frame.hpp"
#include "core/solid/solid_builder.hpp"
#include "stdlib/generators.hpp"

namespace hlr {
namespace {

// ---- helpers ------------------------------------------------------------------------------------------

std::string str(Point3 p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

std::string str(const VisibleSegment& s) {
  std::ostringstream o;
  o << (s.source == SegmentSource::Edge ? "edge " : "intersection ") << s.object << ":" << s.edge;
  if (s.source == SegmentSource::Intersection) o << "/" << s.other;
  o << (s.hidden ? " hidden " : " ") << str(s.p0) << "–" << str(s.p1);
  return o.str();
}

std::string dump(const FrameResult& r) {
  std::string out;
  for (const VisibleSegment& s : r.segments) out += "\n  " + str(s);
  return out;
}

Camera lookat(Point3 eye, Point3 target, Vector3 up = {0, 0, 1}, double fov_deg = 40, double aspect = 0) {
  LookatParameters p;
  p.eye = eye;
  p.target = target;
  p.up = up;
  p.fov_deg = fov_deg;
  p.aspect = aspect;
  return lookat_camera(p);
}

Camera ortho(Point3 eye, Point3 target, Vector3 up = {0, 0, 1}, double height = 2) {
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

void expect_sane(const FrameResult& r, const Camera& camera, const std::string& label) {
  for (const VisibleSegment& s : r.segments) {
    EXPECT_TRUE(is_finite(s.p0) && is_finite(s.p1)) << label << ": " << str(s);
    EXPECT_TRUE(std::isfinite(s.s0.x) && std::isfinite(s.s0.y) && std::isfinite(s.s1.x) &&
                std::isfinite(s.s1.y))
        << label << ": " << str(s);
    for (const auto& [p, q] : {std::pair{s.p0, s.s0}, std::pair{s.p1, s.s1}}) {
      const Point2 want = camera.project(p);
      EXPECT_LE(distance(want, q), 1e-9 * std::max({1.0, std::abs(want.x), std::abs(want.y)}))
          << label << ": picture point off the projection of " << str(p);
    }
  }
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
      ADD_FAILURE() << label << ": missing "
                    << (e.source == SegmentSource::Edge ? "edge piece" : "intersection") << " of object "
                    << e.object << " " << str(e.a) << "–" << str(e.b);
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

std::vector<Expected> join(std::vector<Expected> a, const std::vector<Expected>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<Expected> loop(std::uint32_t object, const std::vector<Point3>& c) {
  std::vector<Expected> out;
  for (std::size_t i = 0; i < c.size(); ++i) out.push_back({object, c[i], c[(i + 1) % c.size()]});
  return out;
}

// The edges of box [lo, hi] kept by the back-face rule for an eye on side s (per axis: +1 beyond hi,
// −1 below lo, 0 inside the slab), each clipped to z ∈ [zmin, zmax] (pieces outside are dropped).
std::vector<Expected> box_on_view_edges(std::uint32_t o, Point3 lo, Point3 hi, int sx, int sy, int sz,
                                        double zmin = -1e300, double zmax = 1e300) {
  const double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
  const int s[3] = {sx, sy, sz};
  std::vector<Expected> out;
  for (int axis = 0; axis < 3; ++axis) {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    for (int ib = 0; ib < 2; ++ib)
      for (int ic = 0; ic < 2; ++ic) {
        const bool on_b = ib ? s[b] > 0 : s[b] < 0, on_c = ic ? s[c] > 0 : s[c] < 0;
        if (!on_b && !on_c) continue;
        double p[3], q[3];
        p[axis] = l[axis];
        q[axis] = h[axis];
        p[b] = q[b] = ib ? h[b] : l[b];
        p[c] = q[c] = ic ? h[c] : l[c];
        Point3 a{p[0], p[1], p[2]}, e{q[0], q[1], q[2]};
        if (axis == 2) {
          a.z = std::max(a.z, zmin);
          e.z = std::min(e.z, zmax);
          if (e.z <= a.z) continue;
        } else if (a.z < zmin || a.z > zmax) {
          continue;
        }
        out.push_back({o, a, e});
      }
  }
  return out;
}

double total_length(const FrameResult& r, std::uint32_t object, SegmentSource source, bool hidden) {
  double sum = 0;
  for (const VisibleSegment& s : r.segments)
    if (s.object == object && s.source == source && s.hidden == hidden) sum += distance(s.p0, s.p1);
  return sum;
}

// ---- a small box in front of a large box --------------------------------------------------------------

// Front view, orthographic along +y with height 2: picture = (x, z). Every side face is edge-on; only the
// y = const faces are on view. The small box S = [1, 3] × [0, 1] × [−0.5, 0.5] covers x ∈ [1, 3],
// z ∈ [−0.5, 0.5] of the picture, so the big box's right edge x = 2 (on its front face y = 2) is cut at
// exactly z = ±0.5; its other three front edges and S's four are whole.
TEST(EngineCasesSilhouette, SmallBoxInFrontOrthoFrontView) {
  const Scene scene = scene_of({stdlib::box({-2, 2, -2}, {2, 3, 2}), stdlib::box({1, 0, -0.5}, {3, 1, 0.5})});
  const Camera cam = ortho({0, -10, 0}, {0, 0, 0});
  const FrameResult r = render_frame(scene, cam);
  expect_sane(r, cam, "ortho front");
  expect_segments(r,
                  {{0, {-2, 2, -2}, {2, 2, -2}},
                   {0, {-2, 2, 2}, {2, 2, 2}},
                   {0, {-2, 2, -2}, {-2, 2, 2}},
                   {0, {2, 2, -2}, {2, 2, -0.5}},
                   {0, {2, 2, 0.5}, {2, 2, 2}},
                   {1, {1, 0, -0.5}, {3, 0, -0.5}},
                   {1, {1, 0, 0.5}, {3, 0, 0.5}},
                   {1, {1, 0, -0.5}, {1, 0, 0.5}},
                   {1, {3, 0, -0.5}, {3, 0, 0.5}}},
                  1e-12, "ortho front");
  // The cut points are on S's top and bottom edges in the picture: (2, ±0.5).
  for (const VisibleSegment& s : r.segments)
    if (s.object == 0 && s.p0.x == 2 && s.p1.x == 2)
      for (Point2 q : {s.s0, s.s1})
        if (std::abs(q.y) < 1) {
          EXPECT_NEAR(std::abs(q.y), 0.5, 1e-12);
        }
}

// The same two boxes in perspective from (0, −10, 0): depth = y + 10, picture = f·(x, z)/depth. S's front
// face (depth 10) spans picture y ∈ f·[−0.05, 0.05] and x ∈ f·[0.1, 0.3]; its x = 1 face is also on view
// (the eye has x < 1). The big box's right edge x = 2 at depth 12 has picture x = f/6, inside S's front
// face, and is hidden where |z|/12 < 0.05: it is cut at z = ±0.6. S shows 7 edges (its front face and the
// top, bottom and back edges of its x = 1 face), all whole.
TEST(EngineCasesSilhouette, SmallBoxInFrontPerspective) {
  const Scene scene = scene_of({stdlib::box({-2, 2, -2}, {2, 3, 2}), stdlib::box({1, 0, -0.5}, {3, 1, 0.5})});
  const Camera cam = lookat({0, -10, 0}, {0, 0, 0});
  const FrameResult r = render_frame(scene, cam);
  expect_sane(r, cam, "perspective front");
  expect_segments(r,
                  {{0, {-2, 2, -2}, {2, 2, -2}},
                   {0, {-2, 2, 2}, {2, 2, 2}},
                   {0, {-2, 2, -2}, {-2, 2, 2}},
                   {0, {2, 2, -2}, {2, 2, -0.6}},
                   {0, {2, 2, 0.6}, {2, 2, 2}},
                   {1, {1, 0, -0.5}, {3, 0, -0.5}},
                   {1, {1, 0, 0.5}, {3, 0, 0.5}},
                   {1, {1, 0, -0.5}, {1, 0, 0.5}},
                   {1, {3, 0, -0.5}, {3, 0, 0.5}},
                   {1, {1, 0, 0.5}, {1, 1, 0.5}},
                   {1, {1, 0, -0.5}, {1, 1, -0.5}},
                   {1, {1, 1, -0.5}, {1, 1, 0.5}}},
                  1e-12, "perspective front");
  // In the picture the cuts sit exactly on S's top and bottom edges: y = ±0.05·f.
  for (const VisibleSegment& s : r.segments)
    if (s.object == 0 && s.p0.x == 2 && s.p1.x == 2)
      for (Point2 q : {s.s0, s.s1})
        if (std::abs(q.y) < 0.1 * cam.focal) {
          EXPECT_NEAR(std::abs(q.y), 0.05 * cam.focal, 1e-12);
          EXPECT_NEAR(q.x, cam.focal / 6, 1e-12);
        }
}

// ---- a T-junction -------------------------------------------------------------------------------------

// A = [−1, 1] × [0, 1] × [−1, 1] in front of a long bar C = [−3, 3] × [3, 4] × [−0.2, 0.2], eye (0, −10, 0).
// Only the y = const front faces are on view (the eye is inside both x- and z-slabs). A's silhouette is
// its front face at depth 10: picture |x| ≤ f/10. C's horizontal front edges (depth 13) pass behind it and
// end there: hidden for |x|/13 < 1/10, i.e. cut at x = ±1.3, where they meet A's vertical edges in the
// picture (T-junctions).
TEST(EngineCasesTJunction, BarEdgesEndOnTheOccludingEdge) {
  const Scene scene =
      scene_of({stdlib::box({-1, 0, -1}, {1, 1, 1}), stdlib::box({-3, 3, -0.2}, {3, 4, 0.2})});
  const Camera cam = lookat({0, -10, 0}, {0, 0, 0});
  const FrameResult r = render_frame(scene, cam);
  expect_sane(r, cam, "T-junction");
  std::vector<Expected> want = loop(0, {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}});
  want.push_back({1, {-3, 3, -0.2}, {-3, 3, 0.2}});
  want.push_back({1, {3, 3, -0.2}, {3, 3, 0.2}});
  for (double z : {-0.2, 0.2}) {
    want.push_back({1, {-3, 3, z}, {-1.3, 3, z}});
    want.push_back({1, {1.3, 3, z}, {3, 3, z}});
  }
  expect_segments(r, want, 1e-12, "T-junction");
  // The stems end exactly on A's vertical edges x = ±f/10 in the picture.
  int ends = 0;
  for (const VisibleSegment& s : r.segments) {
    if (s.object != 1) continue;
    for (Point2 q : {s.s0, s.s1})
      if (std::abs(std::abs(q.x) - cam.focal / 10) < 1e-9) {
        ++ends;
        EXPECT_NEAR(std::abs(q.x), cam.focal / 10, 1e-12);
      }
  }
  EXPECT_EQ(ends, 4);
}

// ---- an edge seen through a hole ----------------------------------------------------------------------

Solid plate_with_square_hole() {
  return stdlib::prism({{-2, -2}, {2, -2}, {2, 2}, {-2, 2}},
                       {{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}}, 0, 0.2);
}

// Orthographic from above (picture = (x, y)): the plate [−2, 2]² × [0, 0.2] with the hole [−0.5, 0.5]²; a bar
// [−3, 3] × [−0.1, 0.1] × [−1, −0.8] below it. All walls are edge-on. The bar's long top edges are visible
// for |x| ≥ 2 (outside the plate) and exactly through the hole, |x| ≤ 0.5.
TEST(EngineCasesHole, EdgeBehindAPlateIsVisibleThroughTheHoleOrtho) {
  const Scene scene = scene_of({plate_with_square_hole(), stdlib::box({-3, -0.1, -1}, {3, 0.1, -0.8})});
  const Camera cam = ortho({0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 8);
  const FrameResult r = render_frame(scene, cam);
  expect_sane(r, cam, "hole ortho");
  std::vector<Expected> want =
      join(loop(0, {{-2, -2, 0.2}, {2, -2, 0.2}, {2, 2, 0.2}, {-2, 2, 0.2}}),
           loop(0, {{-0.5, -0.5, 0.2}, {0.5, -0.5, 0.2}, {0.5, 0.5, 0.2}, {-0.5, 0.5, 0.2}}));
  want.push_back({1, {-3, -0.1, -0.8}, {-3, 0.1, -0.8}});
  want.push_back({1, {3, -0.1, -0.8}, {3, 0.1, -0.8}});
  for (double y : {-0.1, 0.1}) {
    want.push_back({1, {-3, y, -0.8}, {-2, y, -0.8}});
    want.push_back({1, {-0.5, y, -0.8}, {0.5, y, -0.8}});
    want.push_back({1, {2, y, -0.8}, {3, y, -0.8}});
  }
  expect_segments(r, want, 1e-12, "hole ortho");
}

// Perspective from (0, 0, 10) (depth = 10 − z, picture = f·(x, y)/depth). The hole's walls are now on view
// and the aperture is bounded by the hole's bottom rim (z = 0, depth 10): the bar's top edges (z = −0.8,
// depth 10.8) are seen through it for |x|/10.8 < 0.5/10, |x| < 0.54. The plate's silhouette is its top
// outer rim (depth 9.8): the bar is visible beyond |x| = 2·10.8/9.8 = 108/49. The plate shows its top
// outer rim and, in the hole, the top rim, the four vertical corner edges and the bottom rim: 16 edges.
TEST(EngineCasesHole, EdgeBehindAPlateIsVisibleThroughTheHolePerspective) {
  const Scene scene = scene_of({plate_with_square_hole(), stdlib::box({-3, -0.1, -1}, {3, 0.1, -0.8})});
  const Camera cam = lookat({0, 0, 10}, {0, 0, 0}, {0, 1, 0});
  const FrameResult r = render_frame(scene, cam);
  expect_sane(r, cam, "hole perspective");
  const std::vector<Point3> rim_top = {
      {-0.5, -0.5, 0.2}, {0.5, -0.5, 0.2}, {0.5, 0.5, 0.2}, {-0.5, 0.5, 0.2}};
  const std::vector<Point3> rim_bottom = {{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}};
  std::vector<Expected> want =
      join(join(loop(0, {{-2, -2, 0.2}, {2, -2, 0.2}, {2, 2, 0.2}, {-2, 2, 0.2}}), loop(0, rim_top)),
           loop(0, rim_bottom));
  for (std::size_t i = 0; i < 4; ++i) want.push_back({0, rim_bottom[i], rim_top[i]});
  const double outer = 108.0 / 49.0;
  want.push_back({1, {-3, -0.1, -0.8}, {-3, 0.1, -0.8}});
  want.push_back({1, {3, -0.1, -0.8}, {3, 0.1, -0.8}});
  for (double y : {-0.1, 0.1}) {
    want.push_back({1, {-3, y, -0.8}, {-outer, y, -0.8}});
    want.push_back({1, {-0.54, y, -0.8}, {0.54, y, -0.8}});
    want.push_back({1, {outer, y, -0.8}, {3, y, -0.8}});
  }
  expect_segments(r, want, 1e-12, "hole perspective");
}

// ---- interpenetrating boxes ----------------------------------------------------------------------------

// ---- faces meeting at a corner ------------------------------------------------------------------------

Solid triangle(Point3 a, Point3 b, Point3 c) {
  SolidBuilder builder;
  const VertexIndex ia = builder.add_vertex(a), ib = builder.add_vertex(b), ic = builder.add_vertex(c);
  const std::vector<VertexIndex> ring{ia, ib, ic};
  builder.add_indexed_polygon(ring);
  SolidBuildResult built = builder.build();
  EXPECT_TRUE(built.ok());
  return built.ok() ? std::move(*built.solid) : stdlib::box({0, 0, 0}, {1, 1, 1});
}

// Two triangles with the corner V = (0, 0, 0) in common, seen from above (orthographic, picture = (x, y)):
// A = V (2, 0, 0) (0, 2, 0) flat, B = V (2, −1, 1) (2, 1, 1) rising over A's first edge (B's plane is
// z = x/2). B's angle at V spans the bearings (2, −1) to (2, 1), so A's edge V → (2, 0, 0) runs inside it
// and under B: hidden whole. A's edge V → (0, 2, 0) leaves V outside B's angle: whole. A's edge
// (2, 0, 0) → (0, 2, 0) (x + y = 2) passes under B until it crosses B's side y = x/2 at (4/3, 2/3, 0). B's
// three edges are whole. (Edges that share an end point with a face are the commonest test in a mesh.)
TEST(EngineCasesCorner, FacesSharingACornerHideWhatRunsInsideTheirAngle) {
  const Point3 v{0, 0, 0};
  const Scene scene = scene_of({triangle(v, {2, 0, 0}, {0, 2, 0}), triangle(v, {2, -1, 1}, {2, 1, 1})});
  const Camera cam = ortho({0.5, 0.5, 10}, {0.5, 0.5, 0}, {0, 1, 0}, 6);
  const FrameResult r = render_frame(scene, cam);
  expect_sane(r, cam, "corner");
  std::vector<Expected> want = loop(1, {v, {2, -1, 1}, {2, 1, 1}});
  want.push_back({0, v, {0, 2, 0}});
  want.push_back({0, {4.0 / 3, 2.0 / 3, 0}, {0, 2, 0}});
  expect_segments(r, want, 1e-12, "corner");
}

// A = [−4, 4]² × [0, 2]; P = [−0.5, 0.5] × [−1, 1] × [1, 3] pokes out of A's top. Its side faces cross the
// top along the rectangle x = ±0.5, y = ±1, z = 2. From an eye at (+x, −y, +z) P's faces x = 0.5 and y = −1
// are on view: two intersection segments, whole. P's three kept vertical edges are cut where they enter A
// (visible z ∈ [2, 3]), its top edges are whole, its bottom edges hidden; A's nine edges are whole (P's
// shadow on the plane z = 2 stays inside [−1.7, 1.7]², clear of A's rim). The opposite eye sees the other two
// sides; together the four sides of the rectangle.
const Point3 kALo{-4, -4, 0}, kAHi{4, 4, 2}, kPLo{-0.5, -1, 1}, kPHi{0.5, 1, 3};

TEST(EngineCasesIntersection, BoxPokingThroughATop) {
  const Scene scene = scene_of({stdlib::box(kALo, kAHi), stdlib::box(kPLo, kPHi)});
  std::set<std::pair<std::pair<double, double>, std::pair<double, double>>> sides_seen;
  struct View {
    Point3 eye;
    int sx, sy;
    std::vector<Expected> lines;
  };
  const std::vector<View> views = {
      {{10, -8, 12},
       1,
       -1,
       {{0, {0.5, -1, 2}, {0.5, 1, 2}, SegmentSource::Intersection},
        {0, {-0.5, -1, 2}, {0.5, -1, 2}, SegmentSource::Intersection}}},
      {{-10, 8, 12},
       -1,
       1,
       {{0, {-0.5, -1, 2}, {-0.5, 1, 2}, SegmentSource::Intersection},
        {0, {-0.5, 1, 2}, {0.5, 1, 2}, SegmentSource::Intersection}}},
  };
  for (const View& v : views) {
    for (const Camera& cam : {lookat(v.eye, {0, 0, 1}), ortho(v.eye, {0, 0, 1}, {0, 0, 1}, 12)}) {
      const std::string label = "poke " + cam.kind + " eye " + str(v.eye);
      const FrameResult r = render_frame(scene, cam);
      expect_sane(r, cam, label);
      std::vector<Expected> want = box_on_view_edges(0, kALo, kAHi, v.sx, v.sy, 1);
      EXPECT_EQ(want.size(), 9u);
      const std::vector<Expected> p = box_on_view_edges(1, kPLo, kPHi, v.sx, v.sy, 1, 2, 3);
      EXPECT_EQ(p.size(), 7u);  // 4 top edges + 3 vertical edges cut at z = 2 (the bottom ones are hidden)
      want = join(join(want, p), v.lines);
      expect_segments(r, want, 1e-12, label);
      for (const VisibleSegment& s : r.segments) {
        if (s.source != SegmentSource::Intersection) continue;
        EXPECT_EQ(s.object, 0u) << label;
        EXPECT_EQ(s.other, 1u) << label;
        auto a = std::pair{std::round(s.p0.x * 2), std::round(s.p0.y)},
             b = std::pair{std::round(s.p1.x * 2), std::round(s.p1.y)};
        if (b < a) std::swap(a, b);
        sides_seen.insert({a, b});
      }
    }
  }
  // The rectangle's four sides (x in halves): (−1,−1)–(1,−1), (1,−1)–(1,1), (−1,1)–(1,1), (−1,−1)–(−1,1).
  const std::set<std::pair<std::pair<double, double>, std::pair<double, double>>> rectangle = {
      {{-1, -1}, {1, -1}}, {{1, -1}, {1, 1}}, {{-1, 1}, {1, 1}}, {{-1, -1}, {-1, 1}}};
  EXPECT_EQ(sides_seen, rectangle);
}

// With include_hidden, the hidden layer is meant for a dashed drawing of everything hidden: the two sides
// of the intersection rectangle behind P (on its faces x = −0.5 and y = 1 for this eye) belong in it, so
// visible + hidden intersection length must be the whole perimeter 2·(1 + 2) = 6, each side once.
TEST(EngineCasesIntersection, IncludeHiddenReturnsTheHiddenIntersectionLines) {
  const Scene scene = scene_of({stdlib::box(kALo, kAHi), stdlib::box(kPLo, kPHi)});
  HlrOptions opt;
  opt.include_hidden = true;
  for (const Camera& cam : {lookat({10, -8, 12}, {0, 0, 1}), ortho({10, -8, 12}, {0, 0, 1}, {0, 0, 1}, 12)}) {
    const FrameResult r = render_frame(scene, cam, opt);
    expect_sane(r, cam, "poke hidden " + cam.kind);
    EXPECT_NEAR(total_length(r, 0, SegmentSource::Intersection, false), 3, 1e-12) << cam.kind;
    EXPECT_NEAR(total_length(r, 0, SegmentSource::Intersection, true), 3, 1e-12)
        << cam.kind
        << ": the sides x = −0.5 and y = 1 of the intersection rectangle are missing from the hidden "
        << "layer" << dump(r);
  }
}

// ---- marking lines ------------------------------------------------------------------------------------

// marked_box: an X on the top face from the quarter points, (0.25, 0.25)–(0.75, 0.75) and
// (0.75, 0.25)–(0.25, 0.75), and a free mast rising from (0.25, 0.25, 1). A small box Q = [0.4, 0.6]² ×
// [1.2, 1.3] floats over the X's centre. Orthographic from above (picture = (x − 0.5, y − 0.5)): the
// markings are drawn where the top face is visible, i.e. except under Q (|x − 0.5| < 0.1); the mast is a
// point in the picture and is not drawn.
TEST(EngineCasesMarking, MarkingIsDrawnWithItsFaceAndHiddenWithIt) {
  const Solid marked = stdlib::marked_box({0, 0, 0}, {1, 1, 1});
  int markings = 0, free_lines = 0;
  for (const SolidEdge& e : marked.edges) {
    markings += e.kind == EdgeKind::Marking;
    free_lines += e.kind == EdgeKind::Free;
  }
  ASSERT_EQ(markings, 2);
  ASSERT_EQ(free_lines, 1);
  const Scene scene = scene_of({marked, stdlib::box({0.4, 0.4, 1.2}, {0.6, 0.6, 1.3})});
  {
    const Camera cam = ortho({0.5, 0.5, 10}, {0.5, 0.5, 0}, {0, 1, 0}, 2);
    const FrameResult r = render_frame(scene, cam);
    expect_sane(r, cam, "marking from above");
    std::vector<Expected> want =
        join(loop(0, {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}),
             loop(1, {{0.4, 0.4, 1.3}, {0.6, 0.4, 1.3}, {0.6, 0.6, 1.3}, {0.4, 0.6, 1.3}}));
    want.push_back({0, {0.25, 0.25, 1}, {0.4, 0.4, 1}});
    want.push_back({0, {0.6, 0.6, 1}, {0.75, 0.75, 1}});
    want.push_back({0, {0.75, 0.25, 1}, {0.6, 0.4, 1}});
    want.push_back({0, {0.4, 0.6, 1}, {0.25, 0.75, 1}});
    expect_segments(r, want, 1e-12, "marking from above");
  }
  {
    // From below the top face is off view: the markings go with it, and the mast and Q are behind the box.
    // Only the bottom face's 4 edges remain. With include_hidden the markings and the mast come back whole
    // as hidden pieces.
    const Camera cam = lookat({0.3, 0.35, -5}, {0.5, 0.5, 0.5});
    const FrameResult r = render_frame(scene, cam);
    expect_sane(r, cam, "marking from below");
    expect_segments(r, loop(0, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}), 1e-12, "marking from below");
    HlrOptions opt;
    opt.include_hidden = true;
    const FrameResult h = render_frame(scene, cam, opt);
    int hidden_markings = 0;
    for (const VisibleSegment& s : h.segments) {
      if (s.object != 0 || s.source != SegmentSource::Edge) continue;
      const SolidEdge& e = marked.edges[s.edge];
      if (e.kind != EdgeKind::Marking && e.kind != EdgeKind::Free) continue;
      ++hidden_markings;
      EXPECT_TRUE(s.hidden);
      EXPECT_TRUE(same_ends(s, marked.vertices[e.v0], marked.vertices[e.v1], 1e-12)) << str(s);
    }
    EXPECT_EQ(hidden_markings, 3);
  }
}

// ---- the hidden layer ---------------------------------------------------------------------------------

// Scenes exercising occlusion: (name, solids, camera).
struct Case {
  std::string name;
  std::vector<Solid> solids;
  Camera camera;
};

std::vector<Case> occlusion_cases() {
  std::vector<Case> cases;
  cases.push_back({"T-junction",
                   {stdlib::box({-1, 0, -1}, {1, 1, 1}), stdlib::box({-3, 3, -0.2}, {3, 4, 0.2})},
                   lookat({0, -10, 0}, {0, 0, 0})});
  cases.push_back({"hole",
                   {plate_with_square_hole(), stdlib::box({-3, -0.1, -1}, {3, 0.1, -0.8})},
                   lookat({0.7, -1.3, 10}, {0, 0, 0}, {0, 1, 0})});
  cases.push_back(
      {"poke", {stdlib::box(kALo, kAHi), stdlib::box(kPLo, kPHi)}, lookat({10, -8, 12}, {0, 0, 1})});
  cases.push_back(
      {"mixed",
       {stdlib::box({0, 0, 0}, {1, 1, 1}), stdlib::box({-0.5, 2, -0.25}, {1.5, 3, 0.75}),
        stdlib::l_block({1.5, -1, 0}, {2, 1, 2}, 1, 1), stdlib::sphere({3, 2, 0.5}, 0.6, 8, 5, 0)},
       lookat({5, -6, 4}, {0.8, 0.8, 0.5})});
  cases.push_back(
      {"mixed ortho",
       {stdlib::box({0, 0, 0}, {1, 1, 1}), stdlib::box({-0.5, 2, -0.25}, {1.5, 3, 0.75}),
        stdlib::l_block({1.5, -1, 0}, {2, 1, 2}, 1, 1), stdlib::sphere({3, 2, 0.5}, 0.6, 8, 5, 0)},
       ortho({5, -6, 4}, {0.8, 0.8, 0.5}, {0, 0, 1}, 6)});
  return cases;
}

struct Piece {
  double t0, t1;
  bool hidden;
};

// Pieces of every Edge-source edge, as parameter intervals along v0 → v1, sorted.
std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<Piece>> pieces_by_edge(const Scene& scene,
                                                                                     const FrameResult& r) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<Piece>> out;
  for (const VisibleSegment& s : r.segments) {
    if (s.source != SegmentSource::Edge) continue;
    const Solid& solid = *scene.objects[s.object].solid;
    const SolidEdge& e = solid.edges[s.edge];
    const Point3 a = solid.vertices[e.v0], b = solid.vertices[e.v1];
    const Vector3 d = b - a;
    double t0 = dot(s.p0 - a, d) / dot(d, d), t1 = dot(s.p1 - a, d) / dot(d, d);
    if (t1 < t0) std::swap(t0, t1);
    out[{s.object, s.edge}].push_back({t0, t1, s.hidden});
  }
  for (auto& [key, v] : out)
    std::sort(v.begin(), v.end(), [](const Piece& x, const Piece& y) { return x.t0 < y.t0; });
  return out;
}

// include_hidden adds the hidden pieces and changes nothing else: the visible pieces are the same, in
// the same order; every drawable edge appears; its visible and hidden pieces tile it without overlap, so
// their lengths add up to the edge length.
TEST(EngineCasesHidden, HiddenPiecesComplementTheVisibleOnes) {
  for (const Case& c : occlusion_cases()) {
    const Scene scene = scene_of(c.solids);
    HlrOptions opt;
    const FrameResult visible = render_frame(scene, c.camera, opt);
    opt.include_hidden = true;
    const FrameResult all = render_frame(scene, c.camera, opt);
    expect_sane(all, c.camera, c.name);
    std::vector<VisibleSegment> vis_of_all;
    std::size_t hidden_count = 0;
    for (const VisibleSegment& s : all.segments) {
      if (s.hidden)
        ++hidden_count;
      else
        vis_of_all.push_back(s);
    }
    EXPECT_GT(hidden_count, 0u) << c.name;
    ASSERT_EQ(vis_of_all.size(), visible.segments.size()) << c.name;
    for (std::size_t i = 0; i < vis_of_all.size(); ++i) {
      EXPECT_TRUE(vis_of_all[i].p0 == visible.segments[i].p0 && vis_of_all[i].p1 == visible.segments[i].p1 &&
                  vis_of_all[i].edge == visible.segments[i].edge &&
                  vis_of_all[i].object == visible.segments[i].object)
          << c.name << " #" << i << ": " << str(vis_of_all[i]) << " vs " << str(visible.segments[i]);
    }
    EXPECT_EQ(all.stats.visible_segments, visible.stats.visible_segments) << c.name;

    const auto pieces = pieces_by_edge(scene, all);
    double hidden_total = 0;
    for (std::uint32_t o = 0; o < scene.objects.size(); ++o) {
      const Solid& solid = *scene.objects[o].solid;
      for (std::uint32_t e = 0; e < solid.edges.size(); ++e) {
        if (solid.edges[e].kind == EdgeKind::Flat) continue;
        const std::string label = c.name + " object " + std::to_string(o) + " edge " + std::to_string(e);
        const auto it = pieces.find({o, e});
        if (it == pieces.end()) {
          ADD_FAILURE() << label << ": neither visible nor hidden";
          continue;
        }
        const std::vector<Piece>& v = it->second;
        const double len = distance(solid.vertices[solid.edges[e].v0], solid.vertices[solid.edges[e].v1]);
        double sum = 0;
        for (std::size_t i = 0; i < v.size(); ++i) {
          sum += (v[i].t1 - v[i].t0) * len;
          if (v[i].hidden) hidden_total += (v[i].t1 - v[i].t0) * len;
          if (i > 0) {
            EXPECT_NEAR(v[i].t0, v[i - 1].t1, 1e-9) << label << ": gap or overlap at piece " << i;
          }
        }
        EXPECT_NEAR(v.front().t0, 0, 1e-9) << label;
        EXPECT_NEAR(v.back().t1, 1, 1e-9) << label;
        EXPECT_NEAR(sum, len, 1e-9 * len) << label << ": visible + hidden length";
      }
    }
    EXPECT_GT(hidden_total, 0) << c.name;
  }
}

// The hidden layer is drawn dashed, so its pieces must be maximal like the visible ones: along every edge
// visible and hidden pieces alternate. Two hidden pieces meeting end to end (a hidden stretch split where
// two occluding faces abut) restart the dash pattern in mid-line.
TEST(EngineCasesHidden, VisibleAndHiddenPiecesAlternate) {
  for (const Case& c : occlusion_cases()) {
    const Scene scene = scene_of(c.solids);
    HlrOptions opt;
    opt.include_hidden = true;
    const FrameResult all = render_frame(scene, c.camera, opt);
    for (const auto& [key, v] : pieces_by_edge(scene, all))
      for (std::size_t i = 1; i < v.size(); ++i)
        EXPECT_NE(v[i].hidden, v[i - 1].hidden)
            << c.name << " object " << key.first << " edge " << key.second << ": two "
            << (v[i].hidden ? "hidden" : "visible") << " pieces meet at t = " << v[i].t0 << " (pieces ["
            << v[i - 1].t0 << ", " << v[i - 1].t1 << "] and [" << v[i].t0 << ", " << v[i].t1 << "])";
  }
}

// ---- thread-count independence ------------------------------------------------------------------------

TEST(EngineCasesThreads, OneAndTwoThreadsGiveIdenticalResults) {
  std::vector<Solid> solids = stdlib::box_city(4, 4, 7);
  solids.push_back(stdlib::sphere({20, 20, 12}, 5, 48, 24, 0));
  solids.push_back(stdlib::box({5, 5, 0}, {12, 9, 25}));  // pokes through buildings: intersection lines
  const Scene scene = scene_of(solids);
  for (const Camera& cam :
       {lookat({-25, -35, 45}, {20, 20, 5}), ortho({-25, -35, 45}, {20, 20, 5}, {0, 0, 1}, 70)}) {
    for (bool hidden : {false, true}) {
      HlrOptions opt;
      opt.include_hidden = hidden;
      opt.threads = 1;
      const FrameResult one = render_frame(scene, cam, opt);
      ASSERT_GT(one.stats.candidate_edges, 3u * 256u) << "the scene must span several work chunks";
      ASSERT_GT(one.stats.intersection_lines, 0u);
      for (unsigned threads : {2u, 3u, 0u}) {
        opt.threads = threads;
        const FrameResult other = render_frame(scene, cam, opt);
        const std::string label =
            cam.kind + " threads " + std::to_string(threads) + (hidden ? " +hidden" : "");
        ASSERT_EQ(one.segments.size(), other.segments.size()) << label;
        for (std::size_t i = 0; i < one.segments.size(); ++i) {
          const VisibleSegment &a = one.segments[i], &b = other.segments[i];
          ASSERT_TRUE(a.p0 == b.p0 && a.p1 == b.p1 && a.s0 == b.s0 && a.s1 == b.s1 && a.object == b.object &&
                      a.edge == b.edge && a.other == b.other && a.source == b.source && a.hidden == b.hidden)
              << label << " #" << i << ": " << str(a) << " vs " << str(b);
        }
        EXPECT_EQ(one.stats.candidate_edges, other.stats.candidate_edges) << label;
        EXPECT_EQ(one.stats.occluder_faces, other.stats.occluder_faces) << label;
        EXPECT_EQ(one.stats.face_tests, other.stats.face_tests) << label;
        EXPECT_EQ(one.stats.intersection_lines, other.stats.intersection_lines) << label;
        EXPECT_EQ(one.stats.visible_segments, other.stats.visible_segments) << label;
      }
    }
  }
}

// ---- picture-frame clipping ---------------------------------------------------------------------------

// lookat from (0, −5, 0) with fov 90° (f = 1) and aspect 1.5: frame [−1.5, 1.5] × [−1, 1], picture =
// (x, z)/(y + 5). A long bar [−20, 20] × [0, 1] × [−0.5, 0.5] (only its front face y = 0 is on view, depth 5)
// runs out of the frame at x = ±7.5; its ends x = ±20 are outside. A tall pole [1, 1.5] × [−1, −0.5] ×
// [−20, 20] in front (faces y = −1 and x = 1 on view) leaves the frame at |z| = 4 (depth 4: its front
// edges) and |z| = 4.5 (depth 4.5: its back edge at x = 1, y = −0.5). The pole's silhouette spans picture
// x ∈ [1/4.5, 1.5/4], hiding the bar's edges (depth 5) for x ∈ [5/4.5, 1.875].
TEST(EngineCasesFrame, LookatFrameClipsExactly) {
  const Scene scene =
      scene_of({stdlib::box({-20, 0, -0.5}, {20, 1, 0.5}), stdlib::box({1, -1, -20}, {1.5, -0.5, 20})});
  const Camera cam = lookat({0, -5, 0}, {0, 0, 0}, {0, 0, 1}, 90, 1.5);
  ASSERT_TRUE(cam.frame.has_value());
  EXPECT_NEAR(cam.focal, 1, 1e-15);
  const double x_frame = 1.5 * 5 / cam.focal;  // 7.5 up to the rounding of tan(45°)
  const FrameResult r = render_frame(scene, cam);
  expect_sane(r, cam, "frame");
  std::vector<Expected> want;
  for (double z : {-0.5, 0.5}) {
    want.push_back({0, {-x_frame, 0, z}, {5 / 4.5, 0, z}});
    want.push_back({0, {1.875, 0, z}, {x_frame, 0, z}});
  }
  const double z4 = 4 / cam.focal, z45 = 4.5 / cam.focal;
  want.push_back({1, {1, -1, -z4}, {1, -1, z4}});
  want.push_back({1, {1.5, -1, -z4}, {1.5, -1, z4}});
  want.push_back({1, {1, -0.5, -z45}, {1, -0.5, z45}});
  expect_segments(r, want, 1e-12, "frame");
  for (const VisibleSegment& s : r.segments)
    for (Point2 q : {s.s0, s.s1}) {
      EXPECT_LE(std::abs(q.x), 1.5 + 1e-12) << str(s);
      EXPECT_LE(std::abs(q.y), 1 + 1e-12) << str(s);
    }
  // The cut ends lie on the frame.
  int on_frame = 0;
  for (const VisibleSegment& s : r.segments)
    for (Point2 q : {s.s0, s.s1})
      on_frame += std::abs(std::abs(q.x) - 1.5) < 1e-12 || std::abs(std::abs(q.y) - 1) < 1e-12;
  EXPECT_EQ(on_frame, 2 + 2 + 6);
}

// The same camera before a large box A = [−20, 20] × [0, 40] × [−20, 20] (its front face y = 0, depth 5,
// fills the frame; its edges lie outside it) and a slab B = [−1000, 1000] × [−4.8, 10] × [−20, −0.5]
// running into it under the eye. B's front top edge (depth 0.2, picture z = −2.5) is outside the frame; its
// far top edge (y = 10, depth 15, picture z = −1/30) lies inside A, hidden. Where B's top meets A's front
// face, the line y = 0, z = −0.5 (picture z = −0.1, across the frame for |x| ≤ 1.5·5/f) is visible: it lies
// beyond the only edge piece in the frame, and the engine looks for its occluders after the edges' (on a
// grid widened to it).
TEST(EngineCasesFrame, AnIntersectionLineBeyondEveryEdgeInTheFrame) {
  const Scene scene =
      scene_of({stdlib::box({-20, 0, -20}, {20, 40, 20}), stdlib::box({-1000, -4.8, -20}, {1000, 10, -0.5})});
  const Camera cam = lookat({0, -5, 0}, {0, 0, 0}, {0, 0, 1}, 90, 1.5);
  ASSERT_TRUE(cam.frame.has_value());
  const FrameResult r = render_frame(scene, cam);
  expect_sane(r, cam, "line beyond the edges");
  const double x5 = 1.5 * 5 / cam.focal;
  expect_segments(r, {{0, {-x5, 0, -0.5}, {x5, 0, -0.5}, SegmentSource::Intersection}}, 1e-9,
                  "line beyond the edges");
}

// A cancel flag that is set stops the frame (the REPL's Ctrl-C); one that is clear changes nothing.
TEST(EngineCases, ACancelFlagStopsTheFrame) {
  const Scene scene = scene_of({stdlib::box({-2, 2, -2}, {2, 3, 2}), stdlib::box({1, 0, -0.5}, {3, 1, 0.5})});
  const Camera camera = lookat({4, -9, 3}, {0, 1, 0});
  std::atomic<bool> cancel{false};
  HlrOptions options;
  options.cancel = &cancel;
  const FrameResult plain = render_frame(scene, camera);
  EXPECT_EQ(render_frame(scene, camera, options).segments.size(), plain.segments.size());
  cancel = true;
  EXPECT_THROW(render_frame(scene, camera, options), RenderCancelled);
}

}  // namespace
}  // namespace hlr
