// Each group of built-ins: math, lists and strings, vectors and outlines, transforms, solids, cameras.
#include "runtime/builtins/builtins.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/camera/desens_camera.hpp"
#include "core/camera/lookat_camera.hpp"
#include "core/camera/orbit_camera.hpp"
#include "stdlib/generators.hpp"
#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

using test::value;

TEST(BuiltinsMath, TrigonometryInDegreesExactAtSimpleAngles) {
  EXPECT_EQ(value("sin(30)"), "0.5");
  EXPECT_EQ(value("sin(180)"), "0");
  EXPECT_EQ(value("sin(-90)"), "-1");
  EXPECT_EQ(value("cos(60)"), "0.5");
  EXPECT_EQ(value("cos(90)"), "0");
  EXPECT_EQ(value("cos(180)"), "-1");
  EXPECT_EQ(value("tan(45)"), "1");
  EXPECT_EQ(value("tan(-45)"), "-1");
  EXPECT_EQ(value("asin(1)"), "90");
  EXPECT_EQ(value("acos(0)"), "90");
  EXPECT_EQ(value("atan(1)"), "45");
  EXPECT_EQ(value("atan2(1, -1)"), "135");
  EXPECT_EQ(value("round(sin(37) * 1e6)"),
            std::to_string(std::lround(std::sin(37 * std::numbers::pi / 180) * 1e6)));
}

TEST(BuiltinsMath, PowersRoundingAndInterpolation) {
  EXPECT_EQ(value("sqrt(16)"), "4");
  EXPECT_EQ(value("pow(2, 10)"), "1024");
  EXPECT_EQ(value("exp(0)"), "1");
  EXPECT_EQ(value("log(exp(2))"), "2");
  EXPECT_EQ(value("abs(-3)"), "3");
  EXPECT_EQ(value("[floor(-1.5), ceil(-1.5), round(-1.5), round(2.5)]"), "[-2, -1, -2, 3]");
  EXPECT_EQ(value("min(3, 1, 2)"), "1");
  EXPECT_EQ(value("max([3, 1, 2])"), "3");
  EXPECT_EQ(value("max(0..5)"), "4");
  EXPECT_EQ(value("clamp(5, 0, 3)"), "3");
  EXPECT_EQ(value("lerp(0, 10, 0.25)"), "2.5");
  EXPECT_EQ(value("lerp((0, 0, 0), (2, 4, 6), 0.5)"), "(1, 2, 3)");
  EXPECT_EQ(value("smoothstep(0, 1, 0.5)"), "0.5");
  EXPECT_EQ(value("smoothstep(0, 1, 2)"), "1");
  EXPECT_EQ(value("pi"), "3.141592653589793");
  EXPECT_EQ(value("lerp(0, (1, 1, 1), 0.5)"),
            "error: 2:24: bad argument 'b' to lerp(): expected a number like 'a', got a vector");
}

TEST(BuiltinsCore, LenRangeStr) {
  EXPECT_EQ(value("len([1, 2, 3])"), "3");
  EXPECT_EQ(value("len(\"abc\")"), "3");
  EXPECT_EQ(value("range(0, 3)"), "0..3");
  EXPECT_EQ(value("range(0, 10, step: 5)"), "[0, 5]");
  EXPECT_EQ(value("str((1, 2, 3))"), "(1, 2, 3)");
  EXPECT_EQ(value("str(1) + str(true)"), "1true");
}

TEST(BuiltinsVectors, Operations) {
  EXPECT_EQ(value("vec(1, 2, 3)"), "(1, 2, 3)");
  EXPECT_EQ(value("dot((1, 2, 3), (4, 5, 6))"), "32");
  EXPECT_EQ(value("cross((1, 0, 0), (0, 1, 0))"), "(0, 0, 1)");
  EXPECT_EQ(value("norm((3, 4, 0))"), "5");
  EXPECT_EQ(value("normalize((0, 0, 5))"), "(0, 0, 1)");
  EXPECT_EQ(value("distance((1, 1, 1), (1, 1, 4))"), "3");
}

TEST(BuiltinsVectors, Outlines) {
  EXPECT_EQ(value("rect(2, 4)"), "[(-1, -2, 0), (1, -2, 0), (1, 2, 0), (-1, 2, 0)]");
  EXPECT_EQ(value("len(regular(6, 1))"), "6");
  EXPECT_EQ(value("regular(4, 1)[0]"), "(1, 0, 0)");
  EXPECT_EQ(value("round(regular(4, 2, phase: 90)[0].y)"), "2");
}

TEST(BuiltinsTransforms, BuildAndCompose) {
  EXPECT_EQ(value("identity()"), "matrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]])");
  EXPECT_EQ(value("translate((1, 2, 3)) == translate(1, 2, 3)"), "true");
  EXPECT_EQ(value("rotate(z: 90)"), "matrix([[0, -1, 0, 0], [1, 0, 0, 0], [0, 0, 1, 0]])");
  EXPECT_EQ(value("rotate(90, axis: (0, 0, 2)) == rotate(z: 90)"), "true");
  EXPECT_EQ(value("rotate(x: 180)"), "matrix([[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, -1, 0]])");
  EXPECT_EQ(value("scale(2)"), "matrix([[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, 2, 0]])");
  EXPECT_EQ(value("scale(1, 2, 3, about: (1, 1, 1))"),
            "matrix([[1, 0, 0, 0], [0, 2, 0, -1], [0, 0, 3, -2]])");
  EXPECT_EQ(value("mirror(normal: (1, 0, 0), about: (2, 0, 0))"),
            "matrix([[-1, 0, 0, 4], [0, 1, 0, 0], [0, 0, 1, 0]])");
  EXPECT_EQ(value("matrix([[1, 0, 0, 5], [0, 1, 0, 6], [0, 0, 1, 7]]) == translate(5, 6, 7)"), "true");
  // `A then B` applies A first: rotate (1, 0, 0) to (0, 1, 0), then move it by (10, 0, 0).
  EXPECT_EQ(value("rotate(z: 90) then translate(10, 0, 0)"),
            "matrix([[0, -1, 0, 10], [1, 0, 0, 0], [0, 0, 1, 0]])");
  EXPECT_EQ(value("translate(10, 0, 0) then rotate(z: 90)"),
            "matrix([[0, -1, 0, 0], [1, 0, 0, 10], [0, 0, 1, 0]])");
  EXPECT_EQ(value("rotate(z: 90, about: (1, 0, 0))"), "matrix([[0, -1, 0, 1], [1, 0, 0, -1], [0, 0, 1, 0]])");
}

TEST(BuiltinsSolids, EachGeneratorMakesItsSolid) {
  struct Row {
    const char* call;
    std::size_t faces;
  };
  const Row rows[] = {
      {"box(1, 2, 3)", 6},
      {"box(min: (0, 0, 0), max: (1, 1, 1))", 6},
      {"box(size: (2, 2, 2), center: (5, 5, 5))", 6},
      {"cube(2)", 6},
      {"prism(regular(6, 1), 2)", 8},
      {"prism(rect(4, 4), 1, holes: [rect(1, 1)])", 10},
      {"cylinder(1, 2, sides: 12)", 14},
      {"sphere(1, slices: 8, stacks: 4)", 32},
      {"torus(3, 1, major: 12, minor: 6)", 72},
      {"stairs(3, 2, 1, 1)", 10},
      {"lblock((2, 1, 2), 1, 1)", 8},
  };
  for (const Row& r : rows) {
    const FrameScene scene = test::run_ok(std::string("draw ") + r.call);
    ASSERT_EQ(scene.scene.objects.size(), 1U) << r.call;
    EXPECT_EQ(scene.scene.objects[0].solid->faces.size(), r.faces) << r.call;
    EXPECT_EQ(scene.scene.objects[0].name, std::string(r.call).substr(0, std::string(r.call).find('(')))
        << r.call;
  }
}

TEST(BuiltinsSolids, SameGeometryAsTheStdlib) {
  const FrameScene scene = test::run_ok("draw box(size: (2, 4, 6), center: (1, 1, 1))");
  ASSERT_EQ(scene.scene.objects.size(), 1U);
  const Solid expected = stdlib::box({0, -1, -2}, {2, 3, 4});
  EXPECT_EQ(scene.scene.objects[0].solid->vertices, expected.vertices);
  const FrameScene cyl = test::run_ok("draw cylinder(1, 2)");
  const Solid expected_cyl = stdlib::cylinder({0, 0, 0}, 1, 2, 32, 30);
  EXPECT_EQ(cyl.scene.objects[0].solid->vertices, expected_cyl.vertices);
  EXPECT_EQ(cyl.scene.objects[0].solid->edges.size(), expected_cyl.edges.size());
}

TEST(BuiltinsSolids, GroupsAndPlacement) {
  const FrameScene scene = test::run_ok(
      "let g = group([cube(1), place(cube(1), translate(3, 0, 0))])\n"
      "draw g at translate(0, 10, 0)\n"
      "draw [cube(1), [cube(1)]]");
  ASSERT_EQ(scene.scene.objects.size(), 4U);
  EXPECT_EQ(scene.scene.objects[0].name, "cube");
  EXPECT_EQ(scene.scene.objects[1].name, "cube#2");
  EXPECT_EQ(scene.scene.objects[3].name, "cube#4");
  EXPECT_EQ(scene.scene.objects[1].solid->vertices[0], (Point3{2.5, 9.5, -0.5}));
}

TEST(BuiltinsSolids, BadShapesAreErrorsAtTheCall) {
  // A self-crossing outline: the builder's complaint, at the call.
  const std::string e = test::first_error("draw prism([(0, 0, 0), (1, 1, 0), (1, 0, 0), (0, 1, 0)], 1)");
  EXPECT_EQ(e.substr(0, 5), "1:6: ") << e;
  EXPECT_EQ(test::first_error("draw torus(1, 2)"),
            "1:15: bad argument 'r' to torus(): must be below R (1), got 2");
  EXPECT_EQ(test::first_error("draw lblock((2, 1, 2), 3, 1)"),
            "1:24: bad argument 'upright' to lblock(): must be below size.x (2)");
}

TEST(BuiltinsCameras, SameCamerasAsCore) {
  const FrameScene scene = test::run_ok(
      "camera a = lookat(eye: (30, 20, 15), target: (0, 0, 0), fov: 50, aspect: 1.5)\n"
      "camera b = orbit(theta: 30, phi: 60)\n"
      "camera c = desens(object: (126, 0, 0), observer: (1914, 151, 112.5), heading: (10, 0, 0))\n"
      "camera d = ortho(eye: (0, -10, 0), target: (0, 0, 0), height: 4)\n");
  ASSERT_EQ(scene.cameras.size(), 4U);
  LookatParameters lp;
  lp.eye = {30, 20, 15};
  lp.fov_deg = 50;
  lp.aspect = 1.5;
  const Camera a = lookat_camera(lp);
  EXPECT_EQ(scene.cameras[0].camera.viewFromWorld.m, a.viewFromWorld.m);
  EXPECT_EQ(scene.cameras[0].camera.focal, a.focal);
  EXPECT_TRUE(scene.cameras[0].camera.frame.has_value());
  OrbitParameters op;
  op.theta_deg = 30;
  op.phi_deg = 60;
  EXPECT_EQ(scene.cameras[1].camera.viewFromWorld.m, orbit_camera(op).viewFromWorld.m);
  DesensParameters dp;
  dp.object_position = {126, 0, 0};
  dp.observer_position = {1914, 151, 112.5};
  dp.heading = {10, 0, 0};
  EXPECT_EQ(scene.cameras[2].camera.viewFromWorld.m, desens_camera(dp).viewFromWorld.m);
  EXPECT_EQ(scene.cameras[3].camera.kind, "ortho");
  EXPECT_EQ(scene.cameras[3].name, "d");
}

// Desens' image offset is a 2-D value: (yoff, zoff), or the list [yoff, zoff]; a third number is an error.
TEST(BuiltinsCameras, DesensOffsetIsATwoDimensionalValue) {
  const std::string c = "desens(object: (126, 0, 0), observer: (1914, 151, 112.5), scale: 0.5, offset: ";
  const FrameScene scene = test::run_ok("camera a = " + c + "(1, -2))\ncamera b = " + c + "[1, -2])\n");
  ASSERT_EQ(scene.cameras.size(), 2U);
  EXPECT_EQ(scene.cameras[0].camera.offset.x, 2);  // the offset in picture units: 1 / scale
  EXPECT_EQ(scene.cameras[0].camera.offset.y, -4);
  EXPECT_EQ(scene.cameras[1].camera.offset.x, 2);
  EXPECT_EQ(scene.cameras[1].camera.offset.y, -4);
  EXPECT_EQ(test::first_error("camera a = " + c + "(1, 2, 3))\n"),
            "1:90: bad argument 'offset' to desens(): must be two numbers (yoff, zoff), got a third one");
}

TEST(BuiltinsTable, EverySpecBuiltinIsRegistered) {
  for (const char* name :
       {"sin",      "cos",    "tan",    "asin",       "acos",     "atan",     "atan2",     "sqrt",
        "pow",      "exp",    "log",    "abs",        "floor",    "ceil",     "round",     "min",
        "max",      "clamp",  "lerp",   "smoothstep", "len",      "range",    "str",       "vec",
        "dot",      "cross",  "norm",   "normalize",  "distance", "identity", "translate", "rotate",
        "scale",    "mirror", "matrix", "regular",    "rect",     "box",      "cube",      "prism",
        "cylinder", "sphere", "torus",  "stairs",     "lblock",   "group",    "lookat",    "ortho",
        "orbit",    "desens", "pi"})
    EXPECT_NE(builtins().find(name), nullptr) << name;
  EXPECT_EQ(builtins().find("inf"), nullptr);
}

}  // namespace
}  // namespace hlr::runtime
