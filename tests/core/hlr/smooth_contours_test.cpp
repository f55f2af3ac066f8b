// Smooth contours of curved meshes (tracker issue 36): corner normals, the contour's geometry and its
// visibility. The reference contour here is computed apart from the engine (per-vertex normals summed face
// by face, the zero set triangle by triangle) and its visibility by the ray caster with the faces round the
// contour's own face left out.
//   hlr_core_tests --gtest_filter='SmoothContours*'
#include "core/hlr/smooth_contours.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <tuple>

#include "core/camera/lookat_camera.hpp"
#include "core/camera/ortho_camera.hpp"
#include "core/hlr/render_frame.hpp"
#include "stdlib/generators.hpp"
#include "tests/support/mesh_views.hpp"
#include "tests/support/ray_caster.hpp"
#include "tests/support/ray_caster_checks.hpp"
#include "tests/support/seeded_rng.hpp"

namespace hlr::test {
namespace {

namespace gen = hlr::stdlib;

Solid smooth(Solid s) {
  s.smooth_contours = true;
  return s;
}

TEST(SmoothContours, CornerNormalsOfASpherePointOutward) {
  const Solid s = gen::sphere({0, 0, 0}, 1, 24, 12, 30);
  const CornerNormals& n = s.corner_normals();
  ASSERT_EQ(n.first.size(), s.faces.size() + 1);
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    const auto& ring = s.faces[f].rings[0].vertices;
    ASSERT_EQ(n.first[f + 1] - n.first[f], ring.size());
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Vector3 radial = normalize(s.vertices[ring[k]] - Point3{0, 0, 0});
      const Vector3 got = n.normals[n.first[f] + k];
      EXPECT_NEAR(length(got), 1, 1e-12);
      // Within a few degrees of the sphere's own normal (the faces round a vertex are not symmetric).
      EXPECT_GT(dot(got, radial), std::cos(3 * std::numbers::pi / 180)) << "face " << f << " corner " << k;
    }
  }
}

TEST(SmoothContours, CreasesKeepANormalASide) {
  // A cylinder at crease 30: its side is smooth, its rims are creases. Corners on a cap have the cap's
  // normal; corners on the side are horizontal.
  const Solid s = gen::cylinder({0, 0, 0}, 1, 2, 24, 30);
  const CornerNormals& n = s.corner_normals();
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    const bool cap = std::abs(s.planes[f].normal.z) > 0.5;
    for (std::uint32_t c = n.first[f]; c < n.first[f + 1]; ++c) {
      if (cap) {
        EXPECT_NEAR(n.normals[c].z, s.planes[f].normal.z, 1e-12);
      } else {
        EXPECT_NEAR(n.normals[c].z, 0, 1e-12);
      }
    }
  }
}

// How many closed loops the pieces make, or −1 if some end is not met by exactly one other piece. Ends
// meet up to the rounding of their way from world to view space and back: they are compared on a 1e-9 grid.
int closed_loops(const std::vector<VisibleSegment>& pieces) {
  using Key = std::tuple<long long, long long, long long>;
  auto key = [](Point3 p) {
    return Key{std::llround(p.x * 1e9), std::llround(p.y * 1e9), std::llround(p.z * 1e9)};
  };
  std::map<Key, std::vector<std::size_t>> at;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    at[key(pieces[i].p0)].push_back(i);
    at[key(pieces[i].p1)].push_back(i);
  }
  for (const auto& [point, list] : at)
    if (list.size() != 2) return -1;
  std::vector<bool> seen(pieces.size(), false);
  int loops = 0;
  for (std::size_t start = 0; start < pieces.size(); ++start) {
    if (seen[start]) continue;
    ++loops;
    std::vector<std::size_t> stack = {start};
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      if (seen[i]) continue;
      seen[i] = true;
      for (const Point3 p : {pieces[i].p0, pieces[i].p1})
        for (std::size_t j : at[key(p)]) stack.push_back(j);
    }
  }
  return loops;
}

TEST(SmoothContours, ASphereSeenAlongAnAxisHasOneClosedRoundOutline) {
  Scene scene;
  scene.objects.push_back(
      {"ball", std::make_shared<const Solid>(smooth(gen::sphere({0, 0, 0}, 1, 64, 32, 30)))});
  const Camera camera = ortho_camera(OrthoParameters{{5, 0.3, 0.2}, {0, 0, 0}, {0, 0, 1}, 3, 0});
  const FrameResult result = render_frame(scene, camera);
  std::vector<VisibleSegment> contour;
  for (const VisibleSegment& s : result.segments) {
    EXPECT_EQ(s.source, SegmentSource::Contour) << "a smooth sphere draws no edges";
    if (s.source == SegmentSource::Contour) contour.push_back(s);
  }
  ASSERT_GT(contour.size(), 64u);
  EXPECT_EQ(closed_loops(contour), 1);
  // Round: every point between the mesh's inscribed radius and the sphere's, from the centre of the picture.
  const Point2 centre = camera.project({0, 0, 0});
  const Vector3 across = normalize(cross(camera.direction_world(), Vector3{0, 0, 1}));  // square to the view
  const double unit = distance(centre, camera.project(Point3{0, 0, 0} + across));
  const double inscribed = std::cos(std::numbers::pi / 32);  // the coarser (stacks) direction
  for (const VisibleSegment& s : contour)
    for (const Point2 p : {s.s0, s.s1}) {
      const double r = distance(p, centre) / unit;
      EXPECT_GT(r, inscribed - 1e-9);
      EXPECT_LT(r, 1 + 1e-9);
    }
}

// The reference: per-vertex normals of an all-smooth mesh (angle-weighted, face by face), the zero set of
// n·(p − eye) on each triangle of each face's fan.
struct ReferenceContour {
  struct Piece {
    Point3 a, b;
    std::uint32_t face;
  };
  std::vector<Piece> pieces;
};

ReferenceContour reference_contour(const Solid& s, const Camera& camera) {
  std::vector<Vector3> sum(s.vertices.size(), Vector3{});
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    const auto& ring = s.faces[f].rings[0].vertices;
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Point3 p = s.vertices[ring[k]];
      const Point3 prev = s.vertices[ring[(k + ring.size() - 1) % ring.size()]];
      const Point3 next = s.vertices[ring[(k + 1) % ring.size()]];
      const double angle = std::acos(std::clamp(dot(normalize(prev - p), normalize(next - p)), -1.0, 1.0));
      sum[ring[k]] += angle * s.planes[f].normal;
    }
  }
  const bool perspective = camera.projection == Projection::Perspective;
  auto g = [&](VertexIndex v) {
    const Vector3 n = normalize(sum[v]);
    return perspective ? dot(n, s.vertices[v] - camera.eye_world()) : dot(n, camera.direction_world());
  };
  ReferenceContour out;
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    const auto& ring = s.faces[f].rings[0].vertices;
    for (std::size_t k = 1; k + 1 < ring.size(); ++k) {
      const VertexIndex t[3] = {ring[0], ring[k], ring[k + 1]};
      std::vector<Point3> ends;
      for (int i = 0; i < 3; ++i) {
        const double ga = g(t[i]), gb = g(t[(i + 1) % 3]);
        if ((ga < 0) != (gb < 0))
          ends.push_back(lerp(s.vertices[t[i]], s.vertices[t[(i + 1) % 3]], ga / (ga - gb)));
      }
      if (ends.size() == 2) out.pieces.push_back({ends[0], ends[1], static_cast<std::uint32_t>(f)});
    }
  }
  return out;
}

// The faces that hide no contour point on face `face`: those with a vertex within the face's longest
// side of its centroid.
std::vector<std::uint32_t> faces_round(const Solid& s, std::uint32_t face) {
  const auto& own = s.faces[face].rings[0].vertices;
  Point3 centre{0, 0, 0};
  double longest = 0;
  for (std::size_t k = 0; k < own.size(); ++k) {
    centre = centre + (1.0 / static_cast<double>(own.size())) * to_vector(s.vertices[own[k]]);
    longest = std::max(longest, distance(s.vertices[own[k]], s.vertices[own[(k + 1) % own.size()]]));
  }
  std::vector<std::uint32_t> out;
  for (std::uint32_t f = 0; f < s.faces.size(); ++f)
    for (VertexIndex v : s.faces[f].rings[0].vertices)
      if (distance(s.vertices[v], centre) <= longest) {
        out.push_back(f);
        break;
      }
  return out;
}

// Random views of smooth solids, one behind another: every drawn contour piece lies on the reference
// contour and is visible to the ray caster; every visible sample of the reference contour is drawn.
TEST(SmoothContours, MatchTheReferenceFromRandomViews) {
  Scene scene;
  scene.objects.push_back(
      {"ball", std::make_shared<const Solid>(smooth(gen::sphere({0, 0, 0}, 1, 20, 10, 60)))});
  scene.objects.push_back(
      {"ring", std::make_shared<const Solid>(smooth(gen::torus({1.2, 0.8, 0.3}, 0.9, 0.3, 24, 10, 60)))});
  Rng r(36);
  std::size_t drawn = 0, visible = 0;
  for (int n = 0; n < 24; ++n) {
    const Camera camera = random_view(r, {0.6, 0.4, 0.1}, 1.8, n);
    const FrameResult result = render_frame(scene, camera);
    const RayCaster oracle(scene, camera);
    const double eps = 1e-6 * picture_extent(scene, camera, result);
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<const VisibleSegment*>> by_face;
    for (const VisibleSegment& s : result.segments) {
      ASSERT_NE(s.source, SegmentSource::Edge) << "all-smooth solids draw no edges (view " << n << ")";
      if (s.source != SegmentSource::Contour) continue;  // where the two cross
      by_face[{s.object, s.edge}].push_back(&s);
      const Solid& solid = *scene.objects[s.object].solid;
      const std::vector<std::uint32_t> ignore = faces_round(solid, s.edge);
      for (const Point3& p : segment_samples(s)) {
        ++drawn;
        EXPECT_NE(oracle.classify(p, s.object, ignore).visibility, Visibility::Hidden)
            << "view " << n << ": drawn contour point " << p.x << " " << p.y << " " << p.z << " is hidden";
      }
    }
    for (std::uint32_t o = 0; o < scene.objects.size(); ++o) {
      const Solid& solid = *scene.objects[o].solid;
      for (const auto& piece : reference_contour(solid, camera).pieces) {
        const std::vector<std::uint32_t> ignore = faces_round(solid, piece.face);
        for (int i = 0; i < 5; ++i) {
          const Point3 p = lerp(piece.a, piece.b, (i + 0.5) / 5);
          if (oracle.classify(p, o, ignore).visibility != Visibility::Visible) continue;
          ++visible;
          bool covered = false;
          for (const VisibleSegment* s : by_face[{o, piece.face}])
            covered = covered || point_segment_distance(camera.project(p), s->s0, s->s1) < eps;
          EXPECT_TRUE(covered) << "view " << n << ": visible contour point on face " << piece.face << " of "
                               << scene.objects[o].name << " is not drawn";
        }
      }
    }
  }
  EXPECT_GT(drawn, 2000u);
  EXPECT_GT(visible, 2000u);
}

}  // namespace
}  // namespace hlr::test
