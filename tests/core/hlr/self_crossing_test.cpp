// Parts of one mesh that pass through each other (an assembly exported as one file, a scan folding
// through itself): their intersection lines are drawn as two solids' are, and hide correctly. Checked
// against the ray-casting oracle (tests/support), whose search for crossings within one solid is its own
// brute force over every pair of faces that share at most one vertex.
//   hlr_core_tests --gtest_filter='*SelfCrossing*'
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/camera/lookat_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "core/hlr/render_frame.hpp"
#include "core/solid/face_crossing.hpp"
#include "core/solid/solid_builder.hpp"
#include "core/tolerance.hpp"
#include "stdlib/generators.hpp"
#include "tests/support/ray_caster.hpp"
#include "tests/support/ray_caster_checks.hpp"
#include "tests/support/seeded_rng.hpp"

namespace hlr::test {
namespace {

namespace gen = hlr::stdlib;

// One solid made of the parts' faces, as a mesh file holding several bodies would be imported.
Solid one_mesh(const std::vector<Solid>& parts) {
  SolidBuilder builder;
  for (const Solid& part : parts) {
    std::vector<VertexIndex> index(part.vertices.size());
    for (std::size_t v = 0; v < part.vertices.size(); ++v) index[v] = builder.add_vertex(part.vertices[v]);
    for (const Face& face : part.faces) {
      std::vector<std::vector<VertexIndex>> rings;
      for (const Ring& ring : face.rings) {
        rings.emplace_back();
        for (VertexIndex v : ring.vertices) rings.back().push_back(index[v]);
      }
      builder.add_indexed_face(rings);
    }
  }
  SolidBuildResult built = builder.build();
  if (!built.ok()) {
    std::string why;
    for (const auto& d : built.diagnostics) why += d.message + "\n";
    ADD_FAILURE() << "the merged mesh does not build:\n" << why;
    return gen::box({0, 0, 0}, {1, 1, 1});
  }
  return std::move(*built.solid);
}

double length_of(const FrameResult& r, SegmentSource source) {
  double sum = 0;
  for (const VisibleSegment& s : r.segments)
    if (s.source == source && !s.hidden) sum += distance(s.p0, s.p1);
  return sum;
}

Camera side_view() { return lookat_camera(LookatParameters{{3, 8, 4}, {0, 0, 0}, {0, 0, 1}, 40, 0, 0}); }

// A bar through a box, as one mesh: the lines where the bar enters and leaves are drawn and pass the
// oracle; as two solids the same lines come out.
TEST(SelfCrossing, BarThroughBoxAsOneMesh) {
  const Solid box = gen::box({-1, -1, -1}, {1, 1, 1});
  const Solid bar = gen::box({-2, -0.2, -0.3}, {2, 0.2, 0.3});
  Scene merged;
  merged.objects.push_back({"assembly", one_mesh({box, bar})});
  ASSERT_TRUE(merged.objects[0].solid->closed);
  // Each end of the bar crosses the box's side in a 0.4 × 0.6 rectangle: 4 faces × 2 sides = 8 pieces.
  EXPECT_EQ(merged.objects[0].solid->self_crossings().size(), 8u);
  const FrameResult result = render_frame(merged, side_view());
  const CheckReport report = check_frame(merged, side_view(), result);
  EXPECT_TRUE(report.ok()) << report.summary();
  EXPECT_GT(report.intersection_expected, 0u) << report.summary();

  Scene apart;
  apart.objects.push_back({"box", box});
  apart.objects.push_back({"bar", bar});
  const FrameResult two = render_frame(apart, side_view());
  EXPECT_NEAR(length_of(result, SegmentSource::Intersection), length_of(two, SegmentSource::Intersection),
              1e-9);
  EXPECT_GT(length_of(result, SegmentSource::Intersection), 0.5);
  EXPECT_NEAR(length_of(result, SegmentSource::Edge), length_of(two, SegmentSource::Edge), 1e-9);
}

// The oracle notices when the lines inside one mesh are missing (its check has teeth).
TEST(SelfCrossing, OracleNoticesMissingLines) {
  Scene scene;
  scene.objects.push_back(
      {"assembly", one_mesh({gen::box({-1, -1, -1}, {1, 1, 1}), gen::box({-2, -0.2, -0.3}, {2, 0.2, 0.3})})});
  HlrOptions without;
  without.intersection_lines = false;
  const FrameResult result = render_frame(scene, side_view(), without);
  EXPECT_FALSE(check_frame(scene, side_view(), result).ok());
}

// Solids that do not pass through themselves have no self-crossings: adjacent faces (sharing an edge)
// and faces meeting at a vertex never count, on flat, curved and concave meshes.
TEST(SelfCrossing, NoneWhereNothingCrosses) {
  EXPECT_TRUE(gen::box({0, 0, 0}, {1, 2, 3}).self_crossings().empty());
  EXPECT_TRUE(gen::sphere({0, 0, 0}, 1, 24, 12, 0).self_crossings().empty());
  EXPECT_TRUE(gen::torus({0, 0, 0}, 2, 0.5, 40, 20, 0).self_crossings().empty());
  EXPECT_TRUE(gen::l_block({0, 0, 0}, {3, 2, 4}, 1, 1).self_crossings().empty());
  EXPECT_TRUE(gen::stairs(6, 2, 0.3, 0.5).self_crossings().empty());
  EXPECT_TRUE(gen::closed_mesh(2000, 7).self_crossings().empty());
  // Two boxes side by side in one mesh, touching along a face: touching is not crossing.
  EXPECT_TRUE(one_mesh({gen::box({0, 0, 0}, {1, 1, 1}), gen::box({1, 0.2, 0.2}, {2, 0.8, 0.8})})
                  .self_crossings()
                  .empty());
}

// A large mesh takes the grid path (more than a few dozen faces): two tori at right angles, their tubes
// crossing around (±2, 0, 0), cross along closed curves, found the same after the mesh is moved; a
// copied solid finds them afresh.
TEST(SelfCrossing, CrossedToriOnTheGrid) {
  const Solid a = gen::torus({0, 0, 0}, 2, 0.5, 24, 10, 0);
  // Turned a little about z too, so that no vertex of one lands on a vertex of the other.
  const Solid b =
      gen::torus({0, 0, 0}, 2, 0.5, 24, 10, 0)
          .transformed(
              Affine3::rotation({1, 0, 0}, std::numbers::pi / 2).then(Affine3::rotation({0, 0, 1}, 0.05)));
  const Solid linked = one_mesh({a, b});  // (crossed, not linked)
  const auto& found = linked.self_crossings();
  ASSERT_GT(found.size(), 40u);
  for (std::size_t i = 1; i < found.size(); ++i)
    EXPECT_TRUE(found[i - 1].face0 < found[i].face0 ||
                (found[i - 1].face0 == found[i].face0 && found[i - 1].face1 <= found[i].face1));
  for (const SelfCrossing& x : found) {
    EXPECT_LT(x.face0, x.face1);
    // Every piece pairs a face of one torus with a face of the other.
    EXPECT_TRUE(x.face0 < static_cast<FaceIndex>(a.faces.size()) &&
                x.face1 >= static_cast<FaceIndex>(a.faces.size()));
  }
  const Affine3 move = Affine3::rotation({0, 0, 1}, 0.7).then(Affine3::translation({5, -3, 1}));
  const Solid moved = linked.transformed(move);
  ASSERT_EQ(moved.self_crossings().size(), found.size());
  for (std::size_t i = 0; i < found.size(); ++i) {
    EXPECT_EQ(moved.self_crossings()[i].face0, found[i].face0);
    EXPECT_LT(distance(moved.self_crossings()[i].p0, move.apply(found[i].p0)), 1e-9);
  }
  const Solid copy = linked;
  EXPECT_EQ(copy.self_crossings().size(), found.size());

  for (const bool ortho : {false, true}) {
    SCOPED_TRACE(ortho ? "ortho" : "perspective");
    Scene scene;
    scene.objects.push_back({"crossed", linked});
    const Camera camera = ortho ? ortho_camera(OrthoParameters{{9, -7, 6}, {0, 0, 0}, {0, 0, 1}, 8, 0})
                                : lookat_camera(LookatParameters{{9, -7, 6}, {0, 0, 0}, {0, 0, 1}, 45, 0, 0});
    const FrameResult result = render_frame(scene, camera);
    const CheckReport report = check_frame(scene, camera, result);
    EXPECT_TRUE(report.ok()) << report.summary();
    EXPECT_GT(report.intersection_expected, 10u) << report.summary();
  }
}

// Every pair of faces sharing no vertex, each tested as the search tests the pairs it meets (the same
// tolerance, widened by the faces' warp), without the search's grid: what it finds must be what the grid
// finds, piece for piece.
std::vector<SelfCrossing> every_pair(const Solid& s) {
  double extent = 0;
  for (Point3 p : s.vertices) extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  const double tol = Tolerance::for_extent(extent).length;
  const auto n = static_cast<FaceIndex>(s.faces.size());
  std::vector<double> warp(s.faces.size(), 0.0);
  std::vector<std::vector<VertexIndex>> named(s.faces.size());
  for (FaceIndex f = 0; f < n; ++f)
    for (const Ring& ring : s.faces[f].rings)
      for (VertexIndex v : ring.vertices) {
        warp[f] = std::max(warp[f], std::abs(s.planes[f].signed_distance(s.vertices[v])));
        named[f].push_back(v);
      }
  std::vector<SelfCrossing> found;
  FaceCrossingScratch scratch;
  std::vector<CrossingPiece> pieces;
  for (FaceIndex a = 0; a < n; ++a)
    for (FaceIndex b = a + 1; b < n; ++b) {
      const bool shared = std::any_of(named[a].begin(), named[a].end(), [&](VertexIndex v) {
        return std::find(named[b].begin(), named[b].end(), v) != named[b].end();
      });
      if (shared) continue;
      const double t = tol + warp[a] + warp[b];
      if (!face_meets_plane(s, b, s.planes[a], t) || !face_meets_plane(s, a, s.planes[b], t)) continue;
      pieces.clear();
      face_crossings(s, a, s, b, t, scratch, pieces);
      for (const CrossingPiece& p : pieces) found.push_back({p.p0, p.p1, a, b});
    }
  return found;
}

// The search's grid misses no pair and meets none twice, on meshes that take each of its paths: crossed
// tori (cells of a few faces), a 240-sided cylinder pierced by two bars (its tall thin sides crowd a few
// cells: the sweep), and a fine sphere cut by a plate (the plate's faces span thousands of the sphere's
// small cells: met against every face).
TEST(SelfCrossing, TheGridFindsWhatEveryPairFinds) {
  const Solid crossed_tori = one_mesh(
      {gen::torus({0, 0, 0}, 2, 0.5, 24, 10, 0),
       gen::torus({0, 0, 0}, 2, 0.5, 24, 10, 0)
           .transformed(
               Affine3::rotation({1, 0, 0}, std::numbers::pi / 2).then(Affine3::rotation({0, 0, 1}, 0.05)))});
  const Solid pierced_cylinder =
      one_mesh({gen::cylinder({0, 0, 0}, 1, 1, 240, 0), gen::box({-2, -0.1, 0.3}, {2, 0.1, 0.5}),
                gen::box({-0.1, -0.3, -0.5}, {0.1, 0.3, 1.5})});
  const Solid cut_sphere =
      one_mesh({gen::sphere({0, 0, 0}, 1, 48, 24, 0), gen::box({-3, -3, -0.05}, {3, 3, 0.05})});
  for (const auto& [name, mesh] :
       {std::pair{"crossed tori", &crossed_tori}, std::pair{"pierced cylinder", &pierced_cylinder},
        std::pair{"cut sphere", &cut_sphere}}) {
    SCOPED_TRACE(name);
    const std::vector<SelfCrossing> want = every_pair(*mesh);
    const std::vector<SelfCrossing>& got = mesh->self_crossings();
    EXPECT_GT(want.size(), 10u);
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
      EXPECT_EQ(got[i].face0, want[i].face0) << i;
      EXPECT_EQ(got[i].face1, want[i].face1) << i;
      EXPECT_TRUE(got[i].p0 == want[i].p0 && got[i].p1 == want[i].p1) << i;
    }
  }
}

// ---- random assemblies ----------------------------------------------------------------------------

constexpr int kKinds = 4;
constexpr int kSeeds = 15 * kKinds;

// Scene `seed`: one mesh of interpenetrating parts (boxes and a bar; a sphere and a poking box; a torus
// and a pin; a bumpy mesh and a bar), sometimes beside a separate solid that also cuts into it.
Scene assembly(unsigned seed, std::string& description) {
  Rng r(seed * 104729u + 5u);
  std::vector<Solid> parts;
  const int kind = static_cast<int>(seed % kKinds);
  switch (kind) {
    case 0: {
      Point3 a = r.point({-2, -2, 0}, {-1, -1, 0.5});
      Vector3 size{r(1.5, 3), r(1.5, 3), r(1.5, 3)};
      parts.push_back(gen::box(a, a + size));
      for (int i = 1; i < r.integer(2, 4); ++i) {
        const Point3 b = a + Vector3{r(0.3, 0.8) * size.x, r(0.3, 0.8) * size.y, r(-0.5, 0.6) * size.z};
        size = {r(1.5, 3), r(1.5, 3), r(1.5, 3)};
        parts.push_back(gen::box(b, b + size));
        a = b;
      }
      parts.push_back(gen::rotated_box({r(-0.5, 0.5), r(-0.5, 0.5), r(1, 2)}, {r(3, 5), r(0.3, 1), r(0.3, 1)},
                                       r.direction(), r(0, 180)));
      description = "boxes and a bar";
      break;
    }
    case 1:
      parts.push_back(
          gen::sphere({0, 0, 1.5}, 1.5, r.integer(8, 14), r.integer(5, 9), r.integer(0, 1) ? 0.0 : 60.0));
      parts.push_back(
          gen::rotated_box({r(0.8, 1.4), r(-0.3, 0.3), r(1, 2)}, {2, 0.6, 0.6}, r.direction(), r(0, 40)));
      description = "a sphere and a poking box";
      break;
    case 2:
      parts.push_back(gen::torus({0, 0, 1}, 2, r(0.5, 0.9), r.integer(10, 18), r.integer(6, 10),
                                 r.integer(0, 1) ? 0.0 : 50.0)
                          .transformed(Affine3::rotation(r.direction(), r(0, 1.5))));
      parts.push_back(gen::rotated_box({0, 0, 1}, {0.5, 0.5, 5}, r.direction(), r(0, 60)));
      parts.push_back(gen::rotated_box({r(1.5, 2.2), 0, 1}, {0.4, 0.4, 3}, r.direction(), r(0, 60)));
      description = "a torus and two pins";
      break;
    default:
      parts.push_back(gen::closed_mesh(r.integer(100, 400), static_cast<unsigned>(r.integer(0, 1000)))
                          .transformed(Affine3::scaling(2, 2, 2).then(Affine3::translation({0, 0, 1.5}))));
      parts.push_back(gen::rotated_box({r(-1, 1), r(-1, 1), 1.5}, {5, 0.6, 0.6}, r.direction(), r(0, 180)));
      description = "a bumpy mesh and a bar";
      break;
  }
  Scene scene;
  scene.objects.push_back({"assembly", one_mesh(parts)});
  if (r.integer(0, 2) == 0) {
    scene.objects.push_back(
        {"cutter", gen::rotated_box({r(-1, 1), r(-1, 1), 1.2}, {4, 0.5, 0.5}, r.direction(), r(0, 180))});
    description += ", and a separate bar cutting through";
  }
  return scene;
}

class SelfCrossingProperty : public ::testing::TestWithParam<int> {};

TEST_P(SelfCrossingProperty, Random) {
  const auto seed = static_cast<unsigned>(GetParam());
  std::string description;
  const Scene scene = assembly(seed, description);
  Rng r(seed * 31u + 1u);
  const bool ortho = seed % 2 == 1;
  const double az = r(0, 2 * std::numbers::pi), el = r(0.1, 1.3);
  const Point3 target{r(-0.3, 0.3), r(-0.3, 0.3), 1.2};
  const Point3 eye =
      target + r(8, 16) * Vector3{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
  const Camera camera = ortho ? ortho_camera(OrthoParameters{eye, target, {0, 0, 1}, r(7, 10), 0})
                              : lookat_camera(LookatParameters{eye, target, {0, 0, 1}, r(35, 60), 0, 0});
  std::ostringstream d;
  d << "seed " << seed << ": " << description << ", " << (ortho ? "ortho" : "lookat") << " eye (" << eye.x
    << ", " << eye.y << ", " << eye.z << ")";
  SCOPED_TRACE(d.str());
  ASSERT_FALSE(scene.objects[0].solid->self_crossings().empty()) << "the parts should cross";
  const FrameResult result = render_frame(scene, camera);
  const CheckReport report = check_frame(scene, camera, result);
  EXPECT_TRUE(report.ok()) << report.summary();
  // (From some views every crossing is hidden: that the seeds are not vacuous is checked over all of them
  // below.)
  // Threads do not change the result.
  HlrOptions one;
  one.threads = 1;
  const FrameResult single = render_frame(scene, camera, one);
  ASSERT_EQ(single.segments.size(), result.segments.size());
  for (std::size_t i = 0; i < single.segments.size(); ++i)
    EXPECT_TRUE(single.segments[i].p0 == result.segments[i].p0 &&
                single.segments[i].p1 == result.segments[i].p1);
}

INSTANTIATE_TEST_SUITE_P(Seeds, SelfCrossingProperty, ::testing::Range(0, kSeeds));

// The random scenes are not vacuous: from most of the views the oracle sees crossings within the mesh,
// and the engine draws lines there.
TEST(SelfCrossingSeeds, MostViewsSeeCrossingsWithinTheMesh) {
  int seen = 0;
  for (int seed = 0; seed < kSeeds; ++seed) {
    std::string description;
    Scene scene = assembly(static_cast<unsigned>(seed), description);
    scene.objects.resize(1);  // the assembly alone: every expected crossing is its own
    const Camera camera = lookat_camera(LookatParameters{{9, -7, 6}, {0, 0, 1.2}, {0, 0, 1}, 45, 0, 0});
    const FrameResult result = render_frame(scene, camera);
    const CheckReport report = check_intersections(scene, RayCaster(scene, camera), result);
    EXPECT_TRUE(report.ok()) << "seed " << seed << ": " << report.summary();
    std::size_t own = 0;
    for (const VisibleSegment& s : result.segments) own += s.source == SegmentSource::Intersection;
    if (report.intersection_expected > 0 && own > 0) ++seen;
  }
  EXPECT_GE(seen, kSeeds * 3 / 4);
}

}  // namespace
}  // namespace hlr::test
