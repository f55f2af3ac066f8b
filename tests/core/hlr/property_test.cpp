// Property tests of render_frame() against the brute-force ray-casting oracle (tests/support/ray_caster):
// seeded random scenes — boxes, rotated boxes, L-blocks, stairs, interpenetrating boxes, plates with
// holes, spheres, tori, bumpy meshes, a small city on its ground plate, stacked and touching boxes, open
// and marked boxes, edge-on faces, a cube lattice seen along its diagonal (exact coincidences on the
// picture), sizes four orders of magnitude apart, the eye close in, inside a room, and the near plane
// cutting solids — under perspective and orthographic cameras, with and without a (zoomed) picture frame.
// Each seed is its own test case and prints its scene and camera on failure; rerun one with
//   hlr_core_tests --gtest_filter='Seeds/HlrProperty.Random/17'
// (Scenes are reproducible for a given compiler: the order in which function arguments draw random
// numbers is unspecified in C++.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>

#include "core/camera/lookat_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "core/hlr/render_frame.hpp"
#include "stdlib/generators.hpp"
#include "tests/support/ray_caster.hpp"
#include "tests/support/ray_caster_checks.hpp"
#include "tests/support/seeded_rng.hpp"

namespace hlr::test {
namespace {

namespace gen = hlr::stdlib;

// Scene families, chosen by seed % kFamilies.
enum Family {
  kBoxes, kRotated, kLBlocks, kStairs, kInterpenetrating, kPlates, kSphere, kCloseIn, kMixed,
  kTorus, kMesh, kCity, kStacked, kAxisView, kRoom, kLattice, kScales, kManySided, kFamilies
};
// 20 seeds per family, 360 scenes: about 2 s in Release, 40 s under ASan+UBSan (Debug), on one core.
constexpr int kSeeds = 20 * kFamilies;

const char* family_name(int f) {
  static const char* names[] = {"boxes", "rotated boxes", "L-blocks", "stairs", "interpenetrating boxes",
                                "plates with holes", "sphere", "eye close in", "mixed", "torus",
                                "bumpy closed mesh", "box city", "stacked and touching boxes",
                                "axis-aligned view (edge-on faces)", "eye inside a room",
                                "cube lattice seen along a diagonal", "sizes from 0.01 to 100",
                                "faces of many sides (ring-edge grids)"};
  return names[f];
}


struct Case {
  std::string description;
  Scene scene;
  Camera camera;
  Point3 eye, target;
  bool zoomed = false;  // the frame clips the scene; the zoomed-on vertex may be hidden
};

std::string str(Point3 p) {
  std::ostringstream s;
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

void add(Case& c, const std::string& name, Solid s) { c.scene.objects.push_back({name, std::move(s)}); }

Solid random_box(Rng& r, Point3 lo, Point3 hi, double min_size, double max_size) {
  const Point3 a = r.point(lo, hi);
  return gen::box(a, a + Vector3{r(min_size, max_size), r(min_size, max_size), r(min_size, max_size)});
}

// Builds the scene of one family; returns the point the camera should look at and the scene's radius.
void build_scene(int family, Rng& r, Case& c, Point3& center, double& radius) {
  center = {0, 0, 1};
  radius = 5;
  switch (family) {
    case kBoxes: {
      const int n = r.integer(2, 5);
      for (int i = 0; i < n; ++i) add(c, "box" + std::to_string(i), random_box(r, {-4, -4, 0}, {2, 2, 2}, 0.5, 2.5));
      break;
    }
    case kRotated: {
      const int n = r.integer(2, 4);
      for (int i = 0; i < n; ++i)
        add(c, "rbox" + std::to_string(i),
            gen::rotated_box(r.point({-3, -3, 0}, {3, 3, 2}), {r(0.5, 3), r(0.5, 3), r(0.5, 3)}, r.direction(), r(0, 180)));
      break;
    }
    case kLBlocks: {
      add(c, "l0", gen::l_block(r.point({-4, -4, 0}, {-1, -1, 0}), {r(2, 4), r(1, 3), r(2, 4)}, 1, 1));
      // A second L turned by Solid::transformed, and a box.
      const Solid l = gen::l_block({-1, -1, 0}, {2.5, 2, 3}, r(0.5, 1.5), r(0.5, 1.5));
      add(c, "l1", l.transformed(Affine3::rotation({0, 0, 1}, r(0, 2 * std::numbers::pi))
                                     .then(Affine3::translation({r(0, 3), r(0, 3), 0}))));
      add(c, "box", random_box(r, {-2, 1, 0}, {1, 3, 0.5}, 0.5, 2));
      break;
    }
    case kStairs: {
      const int steps = r.integer(2, 6);
      const Solid s = gen::stairs(steps, r(1.5, 3), r(0.2, 0.6), r(0.3, 0.8));
      add(c, "stairs", s.transformed(Affine3::rotation({0, 0, 1}, r(0, 2 * std::numbers::pi))
                                         .then(Affine3::translation({-1.5, -1.5, 0}))));
      add(c, "box", random_box(r, {-4, -4, 0}, {3, 3, 0.5}, 0.5, 1.5));
      center = {0, 0, 0.8};
      radius = 4;
      break;
    }
    case kInterpenetrating: {
      // Overlapping boxes by construction: each one straddles the previous one's corner region.
      Point3 a = r.point({-2, -2, 0}, {-1, -1, 0.5});
      Vector3 size{r(1.5, 3), r(1.5, 3), r(1.5, 3)};
      add(c, "ibox0", gen::box(a, a + size));
      for (int i = 1; i < r.integer(2, 4); ++i) {
        const Point3 b = a + Vector3{r(0.3, 0.8) * size.x, r(0.3, 0.8) * size.y, r(-0.5, 0.6) * size.z};
        size = {r(1.5, 3), r(1.5, 3), r(1.5, 3)};
        add(c, "ibox" + std::to_string(i), gen::box(b, b + size));
        a = b;
      }
      add(c, "irot", gen::rotated_box({r(-0.5, 0.5), r(-0.5, 0.5), r(1, 2)}, {r(3, 5), r(0.3, 1), r(0.3, 1)},
                                      r.direction(), r(0, 180)));
      break;
    }
    case kPlates: {
      // A horizontal plate over boxes (seen through its holes) and a standing plate turned about z.
      add(c, "plate", gen::plate_with_holes({-3, -3, 2}, {3, 3, 2.3}, r.integer(1, 3), r.integer(1, 3), r(0.3, 0.7),
                                            r.integer(3, 6)));
      add(c, "under", random_box(r, {-2, -2, 0}, {0.5, 0.5, 0.3}, 0.8, 1.5));
      const Solid wall = gen::plate_with_holes({-2, -2, -0.15}, {2, 1, 0.15}, 2, 1, 0.6, 4);
      add(c, "wall", wall.transformed(Affine3::rotation({1, 0, 0}, std::numbers::pi / 2)
                                          .then(Affine3::rotation({0, 0, 1}, r(0, std::numbers::pi)))
                                          .then(Affine3::translation({r(-1, 1), r(-1, 1), 2.5}))));
      center = {0, 0, 2};
      break;
    }
    case kSphere: {
      const int slices = r.integer(8, 14), stacks = r.integer(5, 9);
      // Crease 0 (all Feature) or above the mesh's dihedral angles (all Smooth: contour only).
      const double crease = r.integer(0, 1) ? 0.0 : 60.0;
      add(c, "sphere", gen::sphere({0, 0, 1.5}, 1.5, slices, stacks, crease));
      // A box poking into the sphere (intersection lines on a curved mesh) and one beside it.
      add(c, "poke", gen::rotated_box({r(0.8, 1.4), r(-0.3, 0.3), r(1, 2)}, {2, 0.6, 0.6}, r.direction(), r(0, 40)));
      add(c, "side", random_box(r, {-4, -4, 0}, {-2.5, 2, 0.5}, 0.5, 1.5));
      center = {0, 0, 1.5};
      radius = 4;
      break;
    }
    case kCloseIn: {
      add(c, "near", gen::box({0, 0, 0}, {2, 2, 2}));
      for (int i = 0; i < 3; ++i)
        add(c, "far" + std::to_string(i), random_box(r, {-4, -8, 0}, {4, -3, 1}, 0.5, 2));
      // A long box reaching behind the eye: the near plane cuts it open.
      add(c, "through", gen::box({r(-1.5, -0.8), -6, r(0.2, 0.6)}, {r(-0.6, -0.2), 3, r(0.8, 1.4)}));
      center = {0, -5, 1};
      break;
    }
    case kMixed: {
      add(c, "open", gen::open_box({-3, -3, 0}, {-1, -1, r(1, 2)}));
      add(c, "marked", gen::marked_box({0.5, -3, 0}, {2.5, -1, r(0.5, 1.5)}));
      add(c, "cyl", gen::cylinder({-1.5, 1.5, 0}, r(0.5, 1), r(1, 3), r.integer(6, 12), r.integer(0, 1) ? 0 : 70));
      add(c, "stairs", gen::stairs(3, 1.5, 0.4, 0.5).transformed(Affine3::translation({0.5, 0.5, 0})));
      center = {-0.5, -0.5, 0.8};
      break;
    }
    case kManySided: {
      // Faces of more points than RingEdgeGrid::kMinPoints, so the engine tests against them through
      // its grid: a prism of many sides (caps of 130 to 400 points) at a random tilt, a plate with many
      // holes above it, a bar through the prism and a box beside it.
      const Solid prism = gen::cylinder({0, 0, 0}, r(1, 2), r(0.5, 2.5), r.integer(130, 400), 0);
      add(c, "prism", prism.transformed(Affine3::rotation(r.direction(), r(0, 1.5))
                                            .then(Affine3::translation({0, 0, 1.5}))));
      add(c, "plate", gen::plate_with_holes({-3, -3, 3.2}, {3, 3, 3.4}, r.integer(6, 8), r.integer(6, 8),
                                            r(0.3, 0.7), 4));
      add(c, "through", gen::rotated_box({r(-1, 1), r(-1, 1), 1.5}, {4, 0.5, 0.5}, r.direction(), r(0, 90)));
      add(c, "under", random_box(r, {-3, 1.5, 0}, {1, 1, 0.5}, 0.5, 1.5));
      center = {0, 0, 2};
      radius = 4;
      break;
    }
    case kTorus: {
      const double crease = r.integer(0, 1) ? 0.0 : 50.0;
      add(c, "torus", gen::torus({0, 0, 1}, 2, r(0.5, 0.9), r.integer(10, 18), r.integer(6, 10), crease)
                          .transformed(Affine3::rotation(r.direction(), r(0, 1.5))));
      add(c, "pin", gen::rotated_box({0, 0, 1}, {0.5, 0.5, 5}, r.direction(), r(0, 60)));
      center = {0, 0, 1};
      radius = 3.5;
      break;
    }
    case kMesh: {
      add(c, "mesh", gen::closed_mesh(r.integer(100, 400), static_cast<unsigned>(r.integer(0, 1000)))
                         .transformed(Affine3::scaling(2, 2, 2).then(Affine3::translation({0, 0, 2}))));
      add(c, "poke", gen::rotated_box({r(-1, 1), r(-1, 1), 2}, {5, 0.6, 0.6}, r.direction(), r(0, 180)));
      center = {0, 0, 2};
      radius = 3;
      break;
    }
    case kCity: {
      gen::CityOptions o;
      o.cell = 3, o.street = 1, o.min_height = 0.5, o.max_height = 5, o.tower_chance = 0.3;
      const int nx = r.integer(2, 5), ny = r.integer(2, 5);
      int i = 0;
      // The buildings stand on the ground plate: their bottom faces touch its top face.
      for (Solid& b : gen::box_city(nx, ny, static_cast<unsigned>(r.integer(0, 1000)), o))
        add(c, "city" + std::to_string(i++), std::move(b));
      center = {0.5 * nx * o.cell, 0.5 * ny * o.cell, 1};
      radius = 0.6 * std::max(nx, ny) * o.cell;
      break;
    }
    case kStacked: {
      // Coplanar contacts: a box on a box, a box against a box's side, all on a ground plate; edges lying
      // in faces, T-junctions and coincident edges.
      const double h = r(1, 2.5);
      add(c, "base", gen::box({0, 0, 0}, {2, 2, h}));
      const double bx = r(0, 1), by = r(0, 1);
      add(c, "top", gen::box({bx, by, h}, {bx + r(0.5, 1), by + r(0.5, 1), h + r(0.3, 1.5)}));
      const double sy = r(-0.5, 1);
      add(c, "side", gen::box({2, sy, 0}, {r(2.5, 3.5), sy + r(0.5, 2), r(0.5, 2.5)}));
      add(c, "flush", gen::box({-1, 0, 0}, {0, 2, h}));  // shares the base's whole x = 0 face
      add(c, "ground", gen::box({-2, -2, -0.3}, {4, 4, 0}));
      center = {1, 1, 1};
      radius = 4;
      break;
    }
    case kAxisView: {
      // Boxes on a grid; the camera looks exactly along an axis (set in make_case) so faces are edge-on.
      for (int i = 0; i < 4; ++i) {
        const double x = -3 + 1.6 * i;
        add(c, "grid" + std::to_string(i), gen::box({x, r(-2, 1), 0}, {x + r(0.5, 1.2), r(1.5, 3), i % 2 ? 1.0 : 2.0}));
      }
      center = {0, 0, 1};
      break;
    }
    case kRoom: {
      // An interior: the eye (set in make_case) is inside a closed box, the room, with furniture.
      add(c, "room", gen::box({-5, -5, 0}, {5, 5, 3}));
      for (int i = 0; i < 3; ++i)
        add(c, "furniture" + std::to_string(i), random_box(r, {-4, -4, 0}, {3, 3, 0.5}, 0.4, 1.5));
      add(c, "beam", gen::rotated_box({0, 0, 2.5}, {12, 0.3, 0.3}, {0, 0, 1}, r(0, 180)));  // pierces the walls
      center = {0, 0, 1};
      break;
    }
    case kLattice: {
      // Unit cubes on an integer lattice, seen (in make_case) exactly along a lattice diagonal: corners
      // and edges of different cubes project onto each other exactly.
      int i = 0;
      for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y)
          for (int z = 0; z < 3; ++z)
            if (r.integer(0, 2) == 0)
              add(c, "cube" + std::to_string(i++), gen::box({2.0 * x, 2.0 * y, 2.0 * z}, {2.0 * x + 1, 2.0 * y + 1, 2.0 * z + 1}));
      if (i == 0) add(c, "cube", gen::box({0, 0, 0}, {1, 1, 1}));
      center = {2.5, 2.5, 2.5};
      radius = 5;
      break;
    }
    case kScales: {
      // Small boxes on a slab four orders of magnitude larger, the camera close to them: the tolerances
      // must scale with what is seen, not be absolute. The slab reaches far behind the eye, so the near
      // plane clips it far off-axis.
      add(c, "slab", gen::box({-100, -100, -20}, {100, 100, -0.002}));
      for (int i = 0; i < 4; ++i)
        add(c, "small" + std::to_string(i), random_box(r, {-0.05, -0.05, 0}, {0.03, 0.8, 0.03}, 0.01, 0.05));
      add(c, "tilted", gen::rotated_box({0, 0.5, 0.05}, {0.1, 0.02, 0.04}, r.direction(), r(0, 180)));
      center = {0, 0.3, 0.02};
      radius = 0.15;
      break;
    }
  }
}

Case make_case(unsigned seed) {
  Rng r(seed * 7919u + 13u);
  Case c;
  const int family = static_cast<int>(seed % kFamilies);
  Point3 center;
  double radius;
  build_scene(family, r, c, center, radius);
  const bool ortho = (seed / kFamilies) % 2 == 1;
  double aspect = seed % 3 == 0 ? r(1.0, 1.6) : 0.0;  // a picture frame on a third of the seeds
  std::ostringstream d;
  d << "family '" << family_name(family) << "', " << c.scene.objects.size() << " objects";
  if (family == kCloseIn && !ortho) {
    // The eye just outside the near box's y = 0 face: looking away from it, along it, or into it.
    c.eye = {r(0.3, 1.7), -r(0.005, 0.05), r(0.3, 1.7)};
    const int mode = r.integer(0, 2);
    if (mode == 2) aspect = 0;  // looking into the face: only the wide-angle edges are visible
    c.target = mode == 0 ? Point3{r(-2, 2), -8, r(0, 1)}
                         : (mode == 1 ? Point3{r(6, 10), c.eye.y - r(0, 2), r(0.5, 1.5)} : Point3{1, 3, 1});
    LookatParameters p{c.eye, c.target, {0, 0, 1}, r(40, 90), aspect, r.integer(0, 1) ? 0.0 : r(0.01, 0.5)};
    c.camera = lookat_camera(p);
    d << ", close-in mode " << mode << ", near " << p.near;
  } else if (family == kRoom) {
    c.eye = r.point({-4.5, -4.5, 0.2}, {4.5, 4.5, 2.8});
    c.target = r.point({-4, -4, 0}, {4, 4, 1});
    if (ortho)  // from outside, the room's walls hide the furniture
      c.camera = ortho_camera(OrthoParameters{c.eye + Vector3{12, -9, 8}, c.target, {0, 0, 1}, 14, aspect});
    else
      c.camera = lookat_camera(LookatParameters{c.eye, c.target, {0, 0, 1}, r(50, 100), aspect, 0});
  } else if (family == kLattice) {
    // Along (1, 1, 1) or (1, −1, 1) from an eye on the diagonal through the lattice's centre.
    const Vector3 diag = r.integer(0, 1) ? Vector3{1, 1, 1} : Vector3{1, -1, 1};
    c.target = {2.5, 2.5, 2.5};
    c.eye = c.target + (ortho ? 10.0 : 6.0) * diag;
    if (ortho)
      c.camera = ortho_camera(OrthoParameters{c.eye, c.target, {0, 0, 1}, 12, aspect});
    else
      c.camera = lookat_camera(LookatParameters{c.eye, c.target, {0, 0, 1}, 60, aspect, 0});
  } else if (family == kAxisView) {
    // Exactly along −y, the eye at the height of the boxes' top faces (perspective: those faces are
    // edge-on; orthographic: every face parallel to y is).
    c.eye = {r(-1, 1), -10, r.integer(0, 1) ? 1.0 : 2.0};
    c.target = c.eye + Vector3{0, 10, 0};
    if (ortho)
      c.camera = ortho_camera(OrthoParameters{c.eye, c.target, {0, 0, 1}, 8, aspect});
    else
      c.camera = lookat_camera(LookatParameters{c.eye, c.target, {0, 0, 1}, 50, aspect, 0});
  } else {
    // From a random direction above the horizon, far enough to see the whole scene (or most of it).
    const double az = r(0, 2 * std::numbers::pi), el = r(0.1, 1.3);
    const Vector3 dir{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
    c.target = center + radius * Vector3{r(-0.1, 0.1), r(-0.1, 0.1), r(-0.1, 0.1)};
    c.eye = c.target + r(2, 4) * radius * dir;
    // With a frame, half the time zoom in on a vertex so that the frame clips the scene.
    const bool zoom = aspect > 0 && r.integer(0, 1) == 1;
    if (zoom) {
      const Solid& s = *c.scene.objects[static_cast<std::size_t>(r.integer(0, static_cast<int>(c.scene.objects.size()) - 1))].solid;
      c.target = s.vertices[static_cast<std::size_t>(r.integer(0, static_cast<int>(s.vertices.size()) - 1))];
      c.zoomed = true;
    }
    if (ortho) {
      const double height = (zoom ? r(0.4, 0.9) : r(1.5, 3)) * radius;
      c.camera = ortho_camera(OrthoParameters{c.eye, c.target, {0, 0, 1}, height, aspect});
    } else {
      c.camera = lookat_camera(LookatParameters{c.eye, c.target, {0, 0, 1}, zoom ? r(8, 20) : r(30, 70), aspect, 0});
    }
    if (zoom) d << ", zoomed in";
  }
  d << ", " << (ortho ? "ortho" : "lookat") << " eye " << str(c.eye) << " target " << str(c.target) << " aspect "
    << aspect;
  for (const auto& o : c.scene.objects) d << "\n  " << o.name << ": " << o.solid->faces.size() << " faces";
  c.description = d.str();
  return c;
}

class HlrProperty : public ::testing::TestWithParam<int> {};

TEST_P(HlrProperty, Random) {
  const auto seed = static_cast<unsigned>(GetParam());
  const Case c = make_case(seed);
  SCOPED_TRACE("seed " + std::to_string(seed) + ": " + c.description);
  const FrameResult result = render_frame(c.scene, c.camera);
  const CheckReport report = check_frame(c.scene, c.camera, result);
  EXPECT_TRUE(report.ok()) << report.summary();
  // The checks must not be vacuous: something is visible and judged. (Zoomed views, and eyes that may
  // stand inside furniture or face a wall through a frame, can legitimately see nothing.)
  const int family = static_cast<int>(seed % kFamilies);
  if (!c.zoomed && family != kRoom && family != kCloseIn) {
    EXPECT_GT(report.edge_visible, 0u) << report.summary();
    EXPECT_GT(report.drawn_samples, 0u) << report.summary();
  }
  // Ambiguity is for degenerate configurations; a random scene should be decidable almost everywhere.
  // (The close-in views are degenerate by design: rays at grazing angles meet the near plane where it
  // cuts the face beside the eye.)
  // In the sizes family the oracle's tol (1e-6 of the 280-unit slab) is 1–3% of the small boxes, so many
  // of their samples are Ambiguous by design.
  if (family != kCloseIn && family != kAxisView && family != kLattice && family != kScales) {
    EXPECT_LT(report.drawn_ambiguous, report.drawn_samples / 4 + 8) << report.summary();
  }
  if (HasFailure() || std::getenv("HLR_PROPERTY_VERBOSE")) std::cout << "seed " << seed << ": " << report.summary() << "\n";
  // The result must not depend on the number of threads (checked on every fourth seed).
  if (seed % 4 == 2) {
    HlrOptions one;
    one.threads = 1;
    const FrameResult single = render_frame(c.scene, c.camera, one);
    ASSERT_EQ(single.segments.size(), result.segments.size());
    for (std::size_t i = 0; i < single.segments.size(); ++i) {
      const VisibleSegment &a = single.segments[i], &b = result.segments[i];
      EXPECT_TRUE(a.p0 == b.p0 && a.p1 == b.p1 && a.object == b.object && a.edge == b.edge && a.source == b.source)
          << "segment " << i << " differs between 1 thread and the default";
    }
  }
}

// The hidden layer: with include_hidden, the visible pieces are unchanged and no hidden piece is visible.
TEST_P(HlrProperty, HiddenLayer) {
  const auto seed = static_cast<unsigned>(GetParam());
  if (seed % 4 != 1) return;  // checked on every fourth seed, to keep the suite fast
  const Case c = make_case(seed);
  SCOPED_TRACE("seed " + std::to_string(seed) + ": " + c.description);
  HlrOptions options;
  options.include_hidden = true;
  const FrameResult with = render_frame(c.scene, c.camera, options);
  const FrameResult without = render_frame(c.scene, c.camera);
  std::size_t visible = 0;
  for (const auto& s : with.segments) visible += !s.hidden;
  EXPECT_EQ(visible, without.segments.size());
  const RayCaster oracle(c.scene, c.camera);
  int reported = 0;
  for (const auto& s : with.segments) {
    if (!s.hidden) continue;
    for (Point3 p : segment_samples(s)) {
      const Verdict v = oracle.classify(p);
      const bool in_front = c.camera.projection == Projection::Orthographic || c.camera.view(p).z > c.camera.near_depth;
      if (v.visibility == Visibility::Visible && in_front && reported++ < 5)
        ADD_FAILURE() << "hidden piece of object " << s.object << " edge " << s.edge << " from " << str(s.p0) << " to "
                      << str(s.p1) << " has a visible point " << str(p);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, HlrProperty, ::testing::Range(0, kSeeds));

// A hand-made scene with a known answer for the intersection check itself: a thin bar through the middle
// of a box, seen from the side, must produce visible intersection lines where it enters.
TEST(HlrPropertyOracle, BarThroughBoxHasVisibleIntersectionLines) {
  Scene scene;
  scene.objects.push_back({"box", gen::box({-1, -1, -1}, {1, 1, 1})});
  scene.objects.push_back({"bar", gen::box({-2, -0.2, -0.3}, {2, 0.2, 0.3})});
  const Camera camera = lookat_camera(LookatParameters{{3, 8, 4}, {0, 0, 0}, {0, 0, 1}, 40, 0, 0});
  const FrameResult result = render_frame(scene, camera);
  const CheckReport report = check_frame(scene, camera, result);
  EXPECT_TRUE(report.ok()) << report.summary();
  EXPECT_GT(report.intersection_expected, 0u);
  EXPECT_GT(report.intersection_samples, 0u);
}

// The oracle on its own: a unit box seen from +x hides a point behind it, shows one beside it, and calls a
// point on its silhouette edge's own faces visible (its own faces cannot hide it).
TEST(HlrPropertyOracle, BoxHidesWhatIsBehindIt) {
  Scene scene;
  scene.objects.push_back({"box", gen::box({-1, -1, -1}, {1, 1, 1})});
  const Camera camera = lookat_camera(LookatParameters{{10, 0, 0}, {0, 0, 0}, {0, 0, 1}, 40, 0, 0});
  const RayCaster oracle(scene, camera);
  EXPECT_EQ(oracle.visibility({-3, 0, 0}), Visibility::Hidden);
  EXPECT_EQ(oracle.visibility({-3, 5, 0}), Visibility::Visible);
  EXPECT_EQ(oracle.visibility({1, 1, 0.3}), Visibility::Visible);    // front silhouette edge
  EXPECT_EQ(oracle.visibility({-1, 0.5, 1}), Visibility::Hidden);    // back top edge: the ray enters the front face
  EXPECT_EQ(oracle.visibility({-1, 1, 0}), Visibility::Hidden);      // back vertical edge behind the box
  EXPECT_EQ(oracle.visibility({11, 0, 0}), Visibility::Hidden);      // behind the eye
  // The near plane clips: a point just past the eye is in front of the near plane.
  EXPECT_EQ(oracle.visibility({10 - 1e-5, 0, 0}), Visibility::Hidden);
}


// The checks have teeth: a frame with a piece removed, a hidden piece shown, or a piece stretched past
// its end must fail them. (A checker that passes everything would make the property tests worthless.)
TEST(HlrPropertyOracle, ChecksCatchInjectedErrors) {
  Scene scene;
  scene.objects.push_back({"front", gen::box({0, 0, 0}, {2, 2, 2})});
  scene.objects.push_back({"back", gen::box({-3, 3, 0}, {3, 5, 3})});
  scene.objects.push_back({"bar", gen::box({1, -1, 0.5}, {1.5, 4, 1})});  // pierces both boxes
  const Camera camera = lookat_camera(LookatParameters{{4, -8, 5}, {0, 2, 1}, {0, 0, 1}, 45, 0, 0});
  HlrOptions with_hidden;
  with_hidden.include_hidden = true;
  const FrameResult full = render_frame(scene, camera, with_hidden);
  FrameResult visible;
  for (const auto& s : full.segments)
    if (!s.hidden) visible.segments.push_back(s);
  ASSERT_TRUE(check_frame(scene, camera, visible).ok()) << check_frame(scene, camera, visible).summary();

  // 1. Dropping any one edge piece longer than a tenth of the scene is noticed.
  int dropped = 0;
  for (std::size_t i = 0; i < visible.segments.size(); ++i) {
    const auto& s = visible.segments[i];
    if (s.source != SegmentSource::Edge || distance(s.p0, s.p1) < 1) continue;
    FrameResult broken = visible;
    broken.segments.erase(broken.segments.begin() + static_cast<std::ptrdiff_t>(i));
    EXPECT_FALSE(check_frame(scene, camera, broken).ok()) << "dropping segment " << i << " went unnoticed";
    ++dropped;
  }
  EXPECT_GT(dropped, 5);
  // 2. Dropping the intersection pieces is noticed.
  FrameResult no_lines;
  for (const auto& s : visible.segments)
    if (s.source == SegmentSource::Edge) no_lines.segments.push_back(s);
  ASSERT_LT(no_lines.segments.size(), visible.segments.size()) << "the bar should make intersection lines";
  EXPECT_FALSE(check_frame(scene, camera, no_lines).ok());
  // 3. Showing a hidden piece (longer than a tenth of the scene) is noticed.
  int shown = 0;
  for (const auto& s : full.segments) {
    if (!s.hidden || distance(s.p0, s.p1) < 1) continue;
    FrameResult wrong = visible;
    wrong.segments.push_back(s);
    wrong.segments.back().hidden = false;
    EXPECT_FALSE(check_frame(scene, camera, wrong).ok()) << "showing hidden " << str(s.p0) << " -> " << str(s.p1);
    ++shown;
  }
  EXPECT_GT(shown, 3);
  // 4. Duplicating a piece (an edge drawn twice) is noticed.
  FrameResult twice = visible;
  twice.segments.push_back(visible.segments.front());
  EXPECT_FALSE(check_frame(scene, camera, twice).ok());
}


// ---- minimal reproductions of engine bugs the random scenes found (kept as regression tests) -----------

// Found by seeds 32, 66, 134, 168, 236, 253, 270, 304, 321 (cube lattice). An edge whose picture coincides
// with an edge between two front faces of an occluder lies on the boundary of both faces' projections, and
// each face treats its boundary band as "not hidden" — so the edge is drawn although the sight line passes
// through the occluder's interior. Here a cube sits exactly behind another along the view direction: the
// three edges of its nearest corner project onto the front cube's three front edges and are drawn.
TEST(HlrEngineRepro, EdgeBehindAnOccludersInteriorEdgeIsHidden) {
  for (const bool ortho : {true, false}) {
    SCOPED_TRACE(ortho ? "isometric ortho" : "perspective");
    const Point3 eye{5, -5, 5};
    Scene scene;
    scene.objects.push_back({"front", gen::box({0, 0, 0}, {1, 1, 1})});
    // Ortho: "front" moved by −2·(1, −1, 1) along the view; perspective: "front" scaled by 2 about the eye.
    scene.objects.push_back({"behind", ortho ? gen::box({-2, 2, -2}, {-1, 3, -1})
                                             : gen::box(eye + 2.0 * (Point3{0, 0, 0} - eye),
                                                        eye + 2.0 * (Point3{1, 1, 1} - eye))});
    const Camera camera = ortho ? ortho_camera(OrthoParameters{eye, {0, 0, 0}, {0, 0, 1}, 6, 0})
                                : lookat_camera(LookatParameters{eye, {0, 0, 0}, {0, 0, 1}, 40, 0, 0});
    // (Its six silhouette edges coincide with the front cube's silhouette: Ambiguous, not judged.)
    const FrameResult result = render_frame(scene, camera);
    const CheckReport report = check_frame(scene, camera, result);
    EXPECT_TRUE(report.ok()) << report.summary();
  }
}

// Found by seeds 152, 254, 322 of the sizes family (then with a 200 × 59 × 40 block beside the boxes). Without a frame the engine's picture tolerance is
// 1e-9 × the largest |picture coordinate| of any candidate; geometry clipped at the near plane far off-axis
// projects to ~focal·size/near (here ~3e8), so the tolerance grows to ~0.3 picture units and small, nearby
// objects lose whole edges (pieces shorter than it are dropped) and show hidden parts. The tolerance should
// not depend on how far off-axis the near plane clips something.
TEST(HlrEngineRepro, GeometryClippedFarOffAxisDoesNotCoarsenThePicture) {
  Scene scene;
  scene.objects.push_back({"A", gen::box({0, 0, 0}, {0.04, 0.04, 0.04})});
  scene.objects.push_back({"B", gen::box({0.005, -0.1, 0.0}, {0.02, -0.08, 0.03})});  // hides part of A
  // Mostly behind the eye; its far side reaches in front of the near plane about 90° off the view axis.
  scene.objects.push_back({"big", gen::box({-100, -60, 0}, {100, -1, 40})});
  const Camera camera = lookat_camera(LookatParameters{{-0.05, -0.3, 0.1}, {0.02, 0.02, 0.02}, {0, 0, 1}, 40, 0, 1e-6});
  const FrameResult result = render_frame(scene, camera);
  const CheckReport report = check_frame(scene, camera, result);
  EXPECT_TRUE(report.ok()) << report.summary();
  // Without the big block the same two boxes come out right.
  scene.objects.pop_back();
  const FrameResult alone = render_frame(scene, camera);
  EXPECT_TRUE(check_frame(scene, camera, alone).ok()) << check_frame(scene, camera, alone).summary();
}

}  // namespace
}  // namespace hlr::test
