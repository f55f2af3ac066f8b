// Tracks and paths at hand-computed points: eased stretches, holding outside the keys, Catmull-Rom and
// the natural spline through three keys (values derived in the comments), and bad keys.
#include "core/animation/keyframe_track.hpp"

#include <gtest/gtest.h>

namespace hlr {
namespace {

std::vector<Keyframe> keys(std::initializer_list<std::pair<double, double>> tv, Easing e = Easing::Linear) {
  std::vector<Keyframe> out;
  for (const auto& [t, v] : tv) out.push_back({t, {v, 0, 0}, e});
  return out;
}

double x_at(const std::vector<Keyframe>& k, TrackCurve c, double at) { return evaluate_track(k, c, at).x; }

TEST(KeyframeTrack, EasedStretchesAndHolds) {
  const auto k = keys({{0, 0}, {10, 100}});
  EXPECT_EQ(x_at(k, TrackCurve::Eased, 2.5), 25);
  EXPECT_EQ(x_at(k, TrackCurve::Eased, -4), 0);
  EXPECT_EQ(x_at(k, TrackCurve::Eased, 12), 100);
  const auto q = keys({{0, 0}, {10, 100}}, Easing::InQuad);
  EXPECT_EQ(x_at(q, TrackCurve::Eased, 5), 25);  // 100 · 0.5²
  const auto s = keys({{0, 0}, {10, 100}}, Easing::Step);
  EXPECT_EQ(x_at(s, TrackCurve::Eased, 9.99), 0);
  EXPECT_EQ(x_at(s, TrackCurve::Eased, 10), 100);
  // Each key's easing shapes the stretch after it.
  std::vector<Keyframe> mixed = keys({{0, 0}, {10, 100}, {20, 0}});
  mixed[1].ease = Easing::Step;
  EXPECT_EQ(x_at(mixed, TrackCurve::Eased, 5), 50);
  EXPECT_EQ(x_at(mixed, TrackCurve::Eased, 15), 100);
  // Vectors component by component.
  const std::vector<Keyframe> v = {{0, {0, 0, 0}, Easing::Linear}, {4, {4, 8, -4}, Easing::Linear}};
  EXPECT_EQ(evaluate_track(v, TrackCurve::Eased, 1), (Vector3{1, 2, -1}));
}

TEST(KeyframeTrack, CatmullRomThroughThreeKeys) {
  // (0, 0), (1, 1), (2, 0): tangents 1 (one-sided), (0 − 0)/2 = 0, −1. At 0.5 the Hermite basis gives
  // h10·m0 + h01·p1 = 0.125 · 1 + 0.5 · 1 = 0.625; by symmetry the same at 1.5.
  const auto k = keys({{0, 0}, {1, 1}, {2, 0}});
  EXPECT_DOUBLE_EQ(x_at(k, TrackCurve::CatmullRom, 0.5), 0.625);
  EXPECT_DOUBLE_EQ(x_at(k, TrackCurve::CatmullRom, 1.5), 0.625);
  EXPECT_EQ(x_at(k, TrackCurve::CatmullRom, 1), 1);
}

TEST(KeyframeTrack, NaturalSplineThroughThreeKeys) {
  // M0 = M2 = 0, 2(1 + 1)·M1 = 6((0 − 1) − (1 − 0)) = −12, M1 = −3. At x = 0.5 of the first stretch:
  // M1·0.5³/6 + (1 − M1/6)·0.5 = −0.0625 + 0.75 = 0.6875.
  const auto k = keys({{0, 0}, {1, 1}, {2, 0}});
  EXPECT_DOUBLE_EQ(x_at(k, TrackCurve::Natural, 0.5), 0.6875);
  EXPECT_DOUBLE_EQ(x_at(k, TrackCurve::Natural, 1.5), 0.6875);
  // Keys on a line: the spline is the line (no curvature anywhere), whatever the spacing.
  const auto line = keys({{0, 1}, {1, 3}, {3, 7}, {4, 9}});
  EXPECT_DOUBLE_EQ(x_at(line, TrackCurve::Natural, 2), 5);
  EXPECT_DOUBLE_EQ(x_at(line, TrackCurve::CatmullRom, 2), 5);
}

TEST(KeyframeTrack, PathsAreEvenlySpacedInU) {
  const std::vector<Point3> p = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}};
  EXPECT_EQ(path_point(p, TrackCurve::Eased, 0.75), (Vector3{10, 5, 0}));
  EXPECT_EQ(path_point(p, TrackCurve::CatmullRom, 0.5), (Vector3{10, 0, 0}));
  const Vector3 d = path_tangent(p, TrackCurve::Eased, 0.25);  // 10 units per half of u
  EXPECT_NEAR(d.x, 20, 1e-9);
  EXPECT_NEAR(d.y, 0, 1e-9);
}

TEST(KeyframeTrack, KeysMustIncrease) {
  EXPECT_THROW(check_keys({}), std::invalid_argument);
  try {
    check_keys(keys({{0, 0}, {5, 1}, {5, 2}}));
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "key 2 must come after key 1: key times increase");
  }
}

}  // namespace
}  // namespace hlr
