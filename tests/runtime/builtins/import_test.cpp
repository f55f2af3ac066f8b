// import("mesh"): relative to the script, cached across frames, warnings kept, errors located at the path
// with the mesh file's own line, and the exit class (unreadable file: input; bad content: script).
#include <gtest/gtest.h>

#include "core/hlr/render_frame.hpp"
#include "tests/runtime/runtime_test_support.hpp"
#include "tests/support/ray_caster_checks.hpp"

namespace hlr::runtime {
namespace {

// A unit cube as OFF: 8 vertices, 6 quads (counter-clockwise seen from outside).
constexpr const char* kCubeOff =
    "OFF\n8 6 12\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

TEST(Import, ReadsAMeshRelativeToTheScript) {
  const test::TempDir dir("runtime-import");
  dir.write("parts/cube.off", kCubeOff);
  const auto main = dir.write("scene.hls",
                              "let c = import(\"parts/cube.off\")\n"
                              "draw c at translate(2, 0, 0)\n"
                              "camera v = orbit()\n");
  const auto program = Program::load(main, "scene.hls");
  ASSERT_TRUE(program->parsed());
  const FrameScene scene = program->evaluate({});
  ASSERT_EQ(scene.scene.objects.size(), 1U);
  const Solid& cube = *scene.scene.objects[0].solid;
  EXPECT_EQ(cube.vertices.size(), 8U);
  EXPECT_EQ(cube.faces.size(), 6U);
  EXPECT_EQ(cube.edges.size(), 12U);
  EXPECT_TRUE(cube.closed);
  EXPECT_EQ(scene.scene.objects[0].name, "cube");
  // Placed by the draw's transform.
  double min_x = 1e9;
  for (const Point3& p : cube.vertices) min_x = std::min(min_x, p.x);
  EXPECT_DOUBLE_EQ(min_x, 2.0);
  // The mesh is an input of the run: no output may overwrite it, and watch mode follows it.
  const std::vector<std::filesystem::path> inputs = program->sources().paths();
  EXPECT_NE(std::find(inputs.begin(), inputs.end(),
                      std::filesystem::weakly_canonical(dir.path() / "parts/cube.off")),
            inputs.end());
}

// An assembly exported as one mesh (examples/showcase/assembly.hls imports meshes/bracket.obj: a plate, a
// post through it, a bar through the post) is one solid whose parts cross: the lines where they do are
// drawn, and the frame passes the ray-casting oracle, its check of crossings within one solid included.
TEST(Import, AnAssemblyInOneMeshShowsWhereItsPartsCross) {
  const std::filesystem::path script =
      std::filesystem::path(HLR_TEST_DATA_DIR).parent_path().parent_path() / "examples/showcase/assembly.hls";
  const auto program = Program::load(script, "assembly.hls");
  ASSERT_TRUE(program->parsed());
  const FrameScene scene = program->evaluate({});
  ASSERT_EQ(scene.scene.objects.size(), 1U);
  ASSERT_TRUE(scene.scene.objects[0].solid->closed);
  ASSERT_EQ(scene.cameras.size(), 1U);
  const Camera& camera = scene.cameras[0].camera;
  const FrameResult result = render_frame(scene.scene, camera);
  std::size_t crossings = 0;
  for (const VisibleSegment& s : result.segments) crossings += s.source == SegmentSource::Intersection;
  // The post's outline on the plate's top (8 sides, those in front seen) and the bar entering the post.
  EXPECT_GE(crossings, 6U);
  const hlr::test::CheckReport report = hlr::test::check_frame(scene.scene, camera, result);
  EXPECT_TRUE(report.ok()) << report.summary();
  EXPECT_GT(report.intersection_expected, 0U) << report.summary();
}

TEST(Import, RepairsAreWarningsAtThePath) {
  const test::TempDir dir("runtime-import-warn");
  // The cube with its top face wound the wrong way: the builder turns it round and says so.
  std::string off = kCubeOff;
  off.replace(off.find("4 4 5 6 7"), 9, "4 7 6 5 4");
  dir.write("cube.off", off);
  const auto main = dir.write("scene.hls", "draw import(\"cube.off\")\ncamera v = orbit()\n");
  const auto program = Program::load(main, "scene.hls");
  const FrameScene scene = program->evaluate({});
  ASSERT_FALSE(scene.warnings.empty());
  EXPECT_EQ(scene.warnings[0].severity, lang::Severity::Warning);
  EXPECT_EQ(test::line_col(scene.warnings[0], program->sources()).substr(0, 5), "1:13:");
  EXPECT_NE(scene.warnings[0].message.find("import 'cube.off'"), std::string::npos);
}

TEST(Import, ErrorsNameTheMeshLineAndTheirKind) {
  const test::TempDir dir("runtime-import-errors");
  dir.write("short.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n");
  const auto bad = dir.write("bad.hls", "let m = import(\"short.off\")\n");
  const auto program = Program::load(bad, "bad.hls");
  try {
    program->evaluate({});
    ADD_FAILURE() << "no error";
  } catch (const EvalError& e) {
    EXPECT_EQ(e.kind, ErrorKind::Script);
    ASSERT_FALSE(e.diagnostics.empty());
    EXPECT_EQ(test::line_col(e.diagnostics[0], program->sources()).substr(0, 5), "1:16:");
    EXPECT_NE(e.diagnostics[0].message.find("short.off:7"), std::string::npos) << e.diagnostics[0].message;
  }
  const auto missing = dir.write("missing.hls", "let m = import(\"nowhere.stl\")\n");
  try {
    Program::load(missing, "missing.hls")->evaluate({});
    ADD_FAILURE() << "no error";
  } catch (const EvalError& e) {
    EXPECT_EQ(e.kind, ErrorKind::Input);
    EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos);
  }
  EXPECT_EQ(test::first_error("let m = import(\"x.off\", crease: 200)\n").substr(0, 5), "1:33:");
  EXPECT_EQ(test::first_error("let m = import(3)\n").substr(0, 5), "1:16:");
}

}  // namespace
}  // namespace hlr::runtime
