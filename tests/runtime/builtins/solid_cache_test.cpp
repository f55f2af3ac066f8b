// Solids shared across frames: the same generator call and the same placement give the very same solid,
// anything else a solid of its own; the cache forgets the least recently used beyond its face budget.
#include "runtime/builtins/solid_cache.hpp"

#include <gtest/gtest.h>

#include "stdlib/generators.hpp"
#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

std::shared_ptr<const Solid> unit_box() {
  return std::make_shared<const Solid>(stdlib::box({0, 0, 0}, {1, 1, 1}));
}

Arg arg(Value v, std::string label = {}) {
  Arg a;
  a.label = std::move(label);
  a.value = std::move(v);
  return a;
}

TEST(SolidCache, TheSameCallGivesTheSameSolid) {
  SolidCache cache(1000);
  int made = 0;
  auto make = [&] {
    ++made;
    return unit_box();
  };
  const std::vector<Arg> args = {arg(Value::number(2)), arg(Value::vector({1, 2, 3}), "size")};
  const auto a = cache.generated("box(...)", args, make);
  const auto b = cache.generated("box(...)", args, make);
  EXPECT_EQ(a.get(), b.get());
  EXPECT_EQ(made, 1);
  // Another value, label, function or a value that has no key: made anew.
  cache.generated("box(...)", {arg(Value::number(2.0000000000000004)), args[1]}, make);
  cache.generated("box(...)", {arg(Value::number(2), "x"), args[1]}, make);
  cache.generated("cube(s)", args, make);
  cache.generated("box(...)", {arg(Value::solid(unit_box(), "b"))}, make);
  cache.generated("box(...)", {arg(Value::solid(unit_box(), "b"))}, make);
  EXPECT_EQ(made, 6);
  EXPECT_EQ(cache.stats().hits, 1U);
}

TEST(SolidCache, PlacementsAreKeyedBySolidAndExactTransform) {
  SolidCache cache(1000);
  const auto source = unit_box();
  int made = 0;
  const Affine3 t = Affine3::translation({1, 0, 0});
  auto make = [&] {
    ++made;
    return std::make_shared<const Solid>(source->transformed(t));
  };
  const auto a = cache.placed(source, t, make);
  EXPECT_EQ(cache.placed(source, t, make).get(), a.get());
  cache.placed(source, Affine3::translation({1, 1e-15, 0}), make);
  cache.placed(unit_box(), t, make);
  EXPECT_EQ(made, 3);
  EXPECT_EQ(a->vertices[0].x, source->vertices[0].x + 1);
}

TEST(SolidCache, TheLeastRecentlyUsedGoesFirstBeyondTheBudget) {
  const std::size_t faces = unit_box()->faces.size();  // 6
  SolidCache cache(2 * faces);
  int made = 0;
  auto make = [&] {
    ++made;
    return unit_box();
  };
  auto key = [](double x) { return std::vector<Arg>{arg(Value::number(x))}; };
  cache.generated("f", key(1), make);
  cache.generated("f", key(2), make);
  cache.generated("f", key(1), make);  // hit: 1 is now the most recent
  cache.generated("f", key(3), make);  // evicts 2
  EXPECT_EQ(made, 3);
  cache.generated("f", key(1), make);
  EXPECT_EQ(made, 3);
  cache.generated("f", key(2), make);
  EXPECT_EQ(made, 4);
  EXPECT_LE(cache.stats().faces, 2 * faces);
  EXPECT_EQ(cache.stats().entries, 2U);
}

TEST(SolidCache, FramesOfAScriptShareWhatDidNotChange) {
  const char* script =
      "animate frames 3\n"
      "draw torus(3, 1, major: 40, minor: 12)\n"
      "draw box(1, 1, 1) at translate(5, 0, 0)\n"
      "draw sphere(1) at translate(0, 0, frame)\n"
      "camera c = orbit(theta: 30 * frame)\n";
  const FrameScene f0 = test::run_ok(script, {0, 0, 0});
  const FrameScene f1 = test::run_ok(script, {1, 0.5, 1});
  ASSERT_EQ(f0.scene.objects.size(), 3U);
  EXPECT_EQ(f0.scene.objects[0].solid.get(), f1.scene.objects[0].solid.get());  // same call
  EXPECT_EQ(f0.scene.objects[1].solid.get(), f1.scene.objects[1].solid.get());  // same placement
  EXPECT_NE(f0.scene.objects[2].solid.get(), f1.scene.objects[2].solid.get());  // moved by the frame
  EXPECT_EQ(f1.scene.objects[2].solid->vertices[0].z, f0.scene.objects[2].solid->vertices[0].z + 1);
}

}  // namespace
}  // namespace hlr::runtime
