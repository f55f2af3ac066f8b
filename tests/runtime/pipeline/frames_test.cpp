// Frames: animate and the frame globals, settings statements, cameras, running frames (serially and in
// parallel), frame selection and output planning.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>

#include "runtime/pipeline/frame_pipeline.hpp"
#include "runtime/pipeline/frame_selection.hpp"
#include "runtime/pipeline/output_plan.hpp"
#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

const char* kAnimated =
    "animate frames 5 fps 10\n"
    "draw cube(2) at translate(t * 10, 0, 0)\n"
    "draw cylinder(1, 3, sides: 8) at translate(0, 4, 0) then rotate(z: frame * 15)\n"
    "camera side = lookat(eye: (5, -30, 10), target: (5, 0, 0))\n"
    "camera top = lookat(eye: (5, 0, 40), target: (5, 0, 0), up: (0, 1, 0))\n"
    "output \"anim-{frame:03}.pdf\" paper A3 portrait\n"
    "style hidden dashed\n";

TEST(Frames, AnimateBindsFrameTAndTime) {
  EXPECT_EQ(frame_time(0, 5, 10).t, 0);
  EXPECT_EQ(frame_time(4, 5, 10).t, 1);
  EXPECT_EQ(frame_time(2, 5, 10).t, 0.5);
  EXPECT_EQ(frame_time(2, 5, 10).time, 0.2);
  EXPECT_EQ(frame_time(0, 1, 24).t, 0);
  const FrameScene scene = test::run_ok(kAnimated, frame_time(2, 5, 10));
  ASSERT_TRUE(scene.animation);
  EXPECT_EQ(scene.animation->frames, 5);
  EXPECT_EQ(scene.animation->fps, 10);
  ASSERT_EQ(scene.scene.objects.size(), 2U);
  EXPECT_EQ(scene.scene.objects[0].solid->vertices[0], (Point3{4, -1, -1}));  // t = 0.5 → x + 5
}

TEST(Frames, SettingsStatements) {
  const FrameScene scene = test::run_ok(kAnimated, frame_time(2, 5, 10));
  ASSERT_TRUE(scene.output);
  EXPECT_EQ(scene.output->name, "anim-002.pdf");
  EXPECT_TRUE(scene.output->interpolated);
  ASSERT_TRUE(scene.paper);
  EXPECT_EQ(scene.paper->paper.width_mm, 297);
  EXPECT_EQ(scene.paper->paper.height_mm, 420);
  EXPECT_EQ(scene.hidden, HiddenStyle::dashed());
  const FrameScene plain = test::run_ok("output \"x.pdf\"\npaper letter\nstyle hidden off");
  EXPECT_FALSE(plain.output->interpolated);
  EXPECT_GT(plain.paper->paper.width_mm, plain.paper->paper.height_mm);  // landscape unless portrait
  EXPECT_EQ(plain.hidden, HiddenStyle::off());
  const FrameScene none = test::run_ok("draw cube(1)");
  EXPECT_FALSE(none.animation || none.output || none.paper || none.hidden);
}

TEST(Frames, CameraChoice) {
  const FrameScene scene = test::run_ok(kAnimated);
  EXPECT_EQ(choose_camera(scene, std::nullopt, "a.hls").name, "top");  // the last declared
  EXPECT_EQ(choose_camera(scene, std::string("side"), "a.hls").name, "side");
  try {
    choose_camera(scene, std::string("front"), "a.hls");
    FAIL();
  } catch (const RunError& e) {
    EXPECT_EQ(e.exit_code, 64);
    EXPECT_STREQ(e.what(), "--camera front: a.hls declares no camera named 'front'");
    EXPECT_EQ(e.hint, "its cameras: side, top");
  }
  try {
    choose_camera(test::run_ok("let s = 2\ndraw cube(s)"), std::nullopt, "a.hls");
    FAIL();
  } catch (const EvalError& e) {  // at what is drawn
    EXPECT_EQ(test::line_col(e.diagnostics.front(), std::string("let s = 2\ndraw cube(s)")),
              "2:6: the script draws this but declares no camera to look at it");
    EXPECT_NE(e.diagnostics.front().hint.find("camera main = lookat("), std::string::npos);
  }
  try {
    choose_camera(test::run_ok("let s = 2"), std::nullopt, "a.hls");  // nothing drawn either
    FAIL();
  } catch (const RunError& e) {
    EXPECT_EQ(e.exit_code, 65);
    EXPECT_NE(e.hint.find("camera main = lookat("), std::string::npos);
  }
}

TEST(Frames, ParallelRunsGiveTheSerialResult) {
  const auto program = Program::from_text("anim.hls", kAnimated);
  const std::vector<int> frames = {0, 1, 2, 3, 4};
  PipelineOptions serial;
  serial.run.frame_count = 5;
  serial.jobs = 1;
  serial.write = false;
  serial.keep_segments = true;
  PipelineOptions parallel = serial;
  parallel.jobs = 3;
  const PipelineResult a = run_pipeline(*program, frames, 10, serial);
  const PipelineResult b = run_pipeline(*program, frames, 10, parallel);
  ASSERT_EQ(a.frames.size(), 5U);
  ASSERT_EQ(b.frames.size(), 5U);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(a.frames[i].time.frame, static_cast<int>(i));
    EXPECT_EQ(a.frames[i].hidden, HiddenStyle::dashed());  // style hidden dashed
    ASSERT_EQ(a.frames[i].kept_segments.size(), b.frames[i].kept_segments.size()) << i;
    EXPECT_GT(a.frames[i].kept_segments.size(), 0U);
    for (std::size_t s = 0; s < a.frames[i].kept_segments.size(); ++s) {
      EXPECT_EQ(a.frames[i].kept_segments[s].p0, b.frames[i].kept_segments[s].p0);
      EXPECT_EQ(a.frames[i].kept_segments[s].p1, b.frames[i].kept_segments[s].p1);
    }
    EXPECT_EQ(a.frames[i].object_names, (std::vector<std::string>{"cube", "cylinder"}));
  }
}

TEST(Frames, TheLowestFailingFrameIsReported) {
  const auto program = Program::from_text("bad.hls",
                                          "animate frames 6\n"
                                          "let x = 1 / (frame % 3 - 2)\n"  // fails in frames 2 and 5
                                          "camera c = orbit()\n");
  for (unsigned jobs : {1U, 4U}) {
    PipelineOptions options;
    options.run.frame_count = 6;
    options.jobs = jobs;
    options.write = false;
    try {
      run_pipeline(*program, {0, 1, 2, 3, 4, 5}, 24, options);
      FAIL();
    } catch (const EvalError& e) {
      EXPECT_EQ(test::line_col(e.diagnostics.front(), program->sources()),
                "2:14: division by zero (in frame 2)")
          << jobs;
    }
  }
}

TEST(Frames, SelectionByListAndShard) {
  EXPECT_EQ(select_frames(5, std::nullopt, std::nullopt), (std::vector<int>{0, 1, 2, 3, 4}));
  EXPECT_EQ(select_frames(10, FrameList{{2, 5}}, std::nullopt), (std::vector<int>{2, 3, 4, 5}));
  EXPECT_EQ(select_frames(10, FrameList{{8, 20}}, std::nullopt), (std::vector<int>{8, 9}));
  EXPECT_EQ(select_frames(10, std::nullopt, Shard{2, 3}), (std::vector<int>{1, 4, 7}));
  EXPECT_EQ(select_frames(10, FrameList{{2, 8}}, Shard{1, 3}), (std::vector<int>{3, 6}));
  // Lists as Blender's -f: items in any order, overlapping, open-ended; each frame once, in order.
  EXPECT_EQ(select_frames(12, FrameList{{10, std::nullopt}, {0, 0}, {5, 5}, {4, 6}}, std::nullopt),
            (std::vector<int>{0, 4, 5, 6, 10, 11}));
  // Every frame in exactly one shard.
  std::vector<int> all;
  for (int k = 1; k <= 4; ++k)
    for (int f : select_frames(10, std::nullopt, Shard{k, 4})) all.push_back(f);
  std::sort(all.begin(), all.end());
  EXPECT_EQ(all, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_THROW(select_frames(3, FrameList{{5, 6}}, std::nullopt), RunError);
  EXPECT_THROW(select_frames(3, FrameList{{0, 1}, {4, std::nullopt}}, std::nullopt), RunError);

  std::string error;
  EXPECT_EQ(parse_frame_list("3-7", error)->front().last, 7);
  EXPECT_EQ(parse_frame_list("4", error)->front().first, 4);
  const std::optional<FrameList> list = parse_frame_list("0,5,10-20,30-", error);
  ASSERT_TRUE(list);
  ASSERT_EQ(list->size(), 4U);
  EXPECT_EQ((*list)[1].last, 5);
  EXPECT_EQ((*list)[2].first, 10);
  EXPECT_EQ((*list)[2].last, 20);
  EXPECT_EQ((*list)[3].first, 30);
  EXPECT_FALSE((*list)[3].last);
  for (const char* bad : {"7-3", "a-b", "-3", "1,,2", "1,", "", "3--4"})
    EXPECT_FALSE(parse_frame_list(bad, error)) << bad;
  EXPECT_EQ(parse_shard("3/8", error)->index, 3);
  EXPECT_FALSE(parse_shard("0/8", error));
  EXPECT_FALSE(parse_shard("9/8", error));
  EXPECT_FALSE(parse_shard("3", error));
}

// An environment of our own for --shard auto.
Environment environment(std::map<std::string, std::string> vars) {
  auto shared = std::make_shared<std::map<std::string, std::string>>(std::move(vars));
  return [shared](const char* name) -> const char* {
    const auto it = shared->find(name);
    return it == shared->end() ? nullptr : it->second.c_str();
  };
}

TEST(Frames, AutoShardsFromSlurmKubernetesAndGnuParallel) {
  std::string error;
  // sbatch --array=1-8: task 3 is job 3 of 8.
  std::optional<Shard> s = parse_shard(
      "auto", error,
      environment(
          {{"SLURM_ARRAY_TASK_ID", "3"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_MAX", "8"}}));
  ASSERT_TRUE(s) << error;
  EXPECT_EQ(s->index, 3);
  EXPECT_EQ(s->count, 8);
  // --array=0-20:5 (0, 5, 10, 15, 20): task 10 is job 3 of 5.
  s = parse_shard("auto", error,
                  environment({{"SLURM_ARRAY_TASK_ID", "10"},
                               {"SLURM_ARRAY_TASK_MIN", "0"},
                               {"SLURM_ARRAY_TASK_MAX", "20"},
                               {"SLURM_ARRAY_TASK_STEP", "5"}}));
  ASSERT_TRUE(s) << error;
  EXPECT_EQ(s->index, 3);
  EXPECT_EQ(s->count, 5);
  // Only the count given: ids from 0.
  s = parse_shard("auto", error,
                  environment({{"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_COUNT", "4"}}));
  ASSERT_TRUE(s) << error;
  EXPECT_EQ(s->index, 1);
  EXPECT_EQ(s->count, 4);
  EXPECT_FALSE(parse_shard("auto", error, environment({})));
  EXPECT_NE(error.find("SLURM_ARRAY_TASK_ID is not set"), std::string::npos) << error;
  // Kubernetes indexed Jobs count from 0, GNU parallel from 1.
  s = parse_shard("auto/6", error, environment({{"JOB_COMPLETION_INDEX", "5"}}));
  ASSERT_TRUE(s) << error;
  EXPECT_EQ(s->index, 6);
  s = parse_shard("auto/6", error, environment({{"PARALLEL_SEQ", "2"}}));
  ASSERT_TRUE(s) << error;
  EXPECT_EQ(s->index, 2);
  EXPECT_EQ(s->count, 6);
  EXPECT_FALSE(parse_shard("auto/6", error, environment({{"PARALLEL_SEQ", "7"}})));
  EXPECT_EQ(error, "--shard auto/6: PARALLEL_SEQ 7 is not one of 6 jobs");
  EXPECT_FALSE(parse_shard("auto/6", error, environment({})));
}

TEST(Frames, OutputNamesGroupFramesIntoFiles) {
  const auto program = Program::from_text("scene.hls", "camera c = orbit()");
  const std::vector<FrameName> three = {{0, std::nullopt}, {1, std::nullopt}, {2, std::nullopt}};
  auto targets = plan_outputs(std::nullopt, three, *program);
  ASSERT_EQ(targets.size(), 1U);
  EXPECT_EQ(targets[0].path, "scene.pdf");
  EXPECT_EQ(targets[0].frames, (std::vector<std::size_t>{0, 1, 2}));

  targets = plan_outputs(std::string("out-{frame:03}.pdf"), three, *program);
  ASSERT_EQ(targets.size(), 3U);
  EXPECT_EQ(targets[2].path, "out-002.pdf");

  targets = plan_outputs(std::string("lines.json"), three, *program);
  EXPECT_EQ(targets[0].device, DeviceKind::Json);

  OutputSetting s;
  s.name = "mine.pdf";
  targets = plan_outputs(std::nullopt, {{0, s}, {1, s}}, *program);
  ASSERT_EQ(targets.size(), 1U);
  EXPECT_EQ(targets[0].path, "mine.pdf");

  EXPECT_EQ(substitute_frame("f{frame}.pdf", 7), "f7.pdf");
  EXPECT_EQ(substitute_frame("f{frame:04}.pdf", 7), "f0007.pdf");
  EXPECT_THROW(substitute_frame("f{time}.pdf", 7), RunError);
  try {
    plan_outputs(std::string("out.svgz"), three, *program);
    FAIL();
  } catch (const RunError& e) {
    EXPECT_EQ(e.exit_code, 64);
    EXPECT_NE(std::string(e.what()).find("supported: pdf, svg, png, hpgl (or .plt), steps, json"),
              std::string::npos);
  }
  s.name = "mine.gif";
  try {
    plan_outputs(std::nullopt, {{0, s}}, *program);
    FAIL();
  } catch (const EvalError& e) {
    EXPECT_NE(e.diagnostics.front().message.find("unknown output type '.gif'"), std::string::npos);
  }
  // SVG, PNG and HPGL hold one frame: several frames sharing such a name ask for {frame} in it.
  for (const char* name : {"all.svg", "all.png", "all.hpgl"}) {
    try {
      plan_outputs(std::string(name), three, *program);
      FAIL() << name;
    } catch (const RunError& e) {
      EXPECT_EQ(e.exit_code, 64);
      EXPECT_NE(std::string(e.what()).find("would hold several frames"), std::string::npos) << e.what();
      EXPECT_NE(e.hint.find("{frame:03}"), std::string::npos) << e.hint;
    }
  }
  EXPECT_EQ(plan_outputs(std::string("f{frame}.svg"), three, *program).size(), 3U);
  EXPECT_EQ(plan_outputs(std::string("one.hpgl"), {three.front()}, *program).size(), 1U);
  s.name = "same.plt";
  try {
    plan_outputs(std::nullopt, {{0, s}, {1, s}}, *program);
    FAIL();
  } catch (const EvalError& e) {
    EXPECT_NE(e.diagnostics.front().message.find("one HPGL file holds one frame"), std::string::npos);
  }
}

TEST(Frames, AnOutputMustNotBeAnInput) {
  const test::TempDir dir("runtime-frames-input");
  const auto path = dir.write("scene.pdf.hls", "camera c = orbit()");
  const auto program = Program::load(path, "scene.pdf.hls");
  // Not the same file: fine.
  EXPECT_NO_THROW(plan_outputs((dir.path() / "scene.pdf").string(), {{0, std::nullopt}}, *program));
  dir.write("x.pdf", "include \"x.pdf\"");
  const auto tricky = Program::load(dir.path() / "x.pdf", "x.pdf");
  try {
    plan_outputs((dir.path() / "x.pdf").string(), {{0, std::nullopt}}, *tricky);
    FAIL();
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("is an input file of this run"), std::string::npos);
  }
}

}  // namespace
}  // namespace hlr::runtime
