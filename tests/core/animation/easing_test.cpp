// The easing curves at hand-computed points, their ends, and the symmetry of the in-out ones.
#include "core/animation/easing.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace hlr {
namespace {

double at(const char* name, double x) { return ease(*easing_named(name), x); }

TEST(Easing, EveryCurveRunsFromZeroToOne) {
  for (std::string_view name : easing_names()) {
    const std::optional<Easing> e = easing_named(name);
    ASSERT_TRUE(e) << name;
    EXPECT_NEAR(ease(*e, 0), 0, 1e-15) << name;
    EXPECT_NEAR(ease(*e, 1), 1, 1e-15) << name;
    EXPECT_EQ(ease(*e, -3), ease(*e, 0)) << name;  // clamped
    EXPECT_EQ(ease(*e, 7), ease(*e, 1)) << name;
  }
  EXPECT_EQ(easing_names().size(), 22U);
  EXPECT_FALSE(easing_named("in_out_cubc"));
}

TEST(Easing, ValuesAtTheMiddle) {
  EXPECT_EQ(at("linear", 0.5), 0.5);
  EXPECT_EQ(at("step", 0.5), 0);
  EXPECT_EQ(at("step", 0.999), 0);
  EXPECT_EQ(at("smoothstep", 0.5), 0.5);
  EXPECT_EQ(at("smoothstep", 0.25), 0.15625);        // 0.0625 · 2.5
  EXPECT_EQ(at("smootherstep", 0.25), 0.103515625);  // 0.015625 · (0.25 · (1.5 − 15) + 10) = 0.015625 · 6.625
  EXPECT_NEAR(at("in_sine", 0.5), 1 - std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(at("out_sine", 0.5), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(at("in_out_sine", 0.5), 0.5, 1e-15);
  EXPECT_EQ(at("in_quad", 0.5), 0.25);
  EXPECT_EQ(at("out_quad", 0.5), 0.75);
  EXPECT_EQ(at("in_out_quad", 0.25), 0.125);  // 2 · 0.25²
  EXPECT_EQ(at("in_cubic", 0.5), 0.125);
  EXPECT_EQ(at("out_cubic", 0.5), 0.875);
  EXPECT_EQ(at("in_out_cubic", 0.25), 0.0625);  // 4 · 0.25³
  EXPECT_EQ(at("in_quart", 0.5), 0.0625);
  EXPECT_EQ(at("in_out_quart", 0.25), 0.03125);  // 8 · 0.25⁴
  EXPECT_EQ(at("in_expo", 0.5), 0.03125);        // 2^−5
  EXPECT_EQ(at("out_expo", 0.5), 0.96875);
  EXPECT_EQ(at("in_out_expo", 0.25), 0.03125 / 2);  // 2^(5 − 10) / 2
  // Back overshoots: below 0 early on. 2.70158 · 0.125 − 1.70158 · 0.25 = −0.0876975
  EXPECT_NEAR(at("in_back", 0.5), -0.0876975, 1e-12);
  EXPECT_NEAR(at("out_back", 0.5), 1.0876975, 1e-12);
}

TEST(Easing, InOutCurvesAreSymmetric) {
  for (const char* name : {"smoothstep", "smootherstep", "in_out_sine", "in_out_quad", "in_out_cubic",
                           "in_out_quart", "in_out_expo", "in_out_back"})
    for (double x : {0.1, 0.2, 0.3, 0.45})
      EXPECT_NEAR(at(name, x) + at(name, 1 - x), 1, 1e-12) << name << " at " << x;
}

}  // namespace
}  // namespace hlr
