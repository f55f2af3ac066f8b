// The frame pipeline through the command: the files' bytes do not depend on --jobs or on sharding, and a
// failing frame leaves nothing behind, whatever ran beside it.
#include "runtime/pipeline/frame_pipeline.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "runtime/base/interrupt.hpp"
#include "tests/runtime/cli_run.hpp"
#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

namespace fs = std::filesystem;

// Enough frames and pieces that several frames are in flight at once with two or more threads.
const char* kTurntable =
    "animate frames 12 fps 12\n"
    "draw torus(3, 1.2, major: 40, minor: 16, crease: 0)\n"
    "draw box(2, 2, 2) at translate(-1, -1, -1.2) pen 2\n"
    "let a = 360 * frame / 12\n"
    "camera turn = lookat(eye: (14 * cos(a), 14 * sin(a), 7), target: (0, 0, 0), fov: 35)\n"
    "pen 2 (colour: \"red\")\n"
    "style hidden dashed\n";

class FramePipeline : public ::testing::Test {
 protected:
  void SetUp() override {
    script_ = dir_ / "turntable.hls";
    std::ofstream(script_) << kTurntable;
    // A fixed PDF creation date, so that two runs can give the same bytes.
    ::setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
  }
  void TearDown() override { ::unsetenv("SOURCE_DATE_EPOCH"); }

  // Every file of `sub`, by name.
  std::map<std::string, std::string> files_in(const fs::path& sub) const {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::directory_iterator(sub))
      out[e.path().filename().string()] = test::read_text(e.path());
    return out;
  }

  // Renders into a fresh subdirectory `name` with `args`; returns its files.
  std::map<std::string, std::string> render(const std::string& name, const std::string& pattern,
                                            std::vector<std::string> args) {
    const fs::path sub = dir_ / name;
    fs::create_directories(sub);
    args.insert(args.begin(), {script_.string(), "-o", (sub / pattern).string()});
    const test::CliResult r = test::run(args);
    EXPECT_EQ(r.code, 0) << r.err;
    return files_in(sub);
  }

  const test::TempDir scratch_{std::string("pipeline-") +
                               ::testing::UnitTest::GetInstance()->current_test_info()->name()};
  const fs::path dir_ = scratch_.path();
  fs::path script_;
};

TEST_F(FramePipeline, BytesDoNotDependOnJobs) {
  const std::vector<std::string> patterns = {"all.pdf",           "all.json",         "all.jsonl",
                                             "f-{frame:02}.png",  "f-{frame:02}.svg", "f-{frame:02}.hpgl",
                                             "f-{frame:02}.steps"};
  for (const std::string& pattern : patterns) {
    const std::string ext = fs::path(pattern).extension().string().substr(1);
    const auto one = render(ext + "-1", pattern, {"--jobs", "1"});
    const std::size_t expected_files = pattern.find('{') == std::string::npos ? 1 : 12;
    ASSERT_EQ(one.size(), expected_files) << pattern;
    for (const auto& [name, bytes] : one) EXPECT_GT(bytes.size(), 100U) << name;
    for (const char* jobs : {"2", "3", "8"}) {
      const auto many = render(ext + "-" + jobs, pattern, {"--jobs", jobs});
      EXPECT_EQ(many, one) << pattern << " with --jobs " << jobs;
    }
  }
}

// The optimized pen plan's work is counted, never timed: a large frame planned on an idle machine and
// again with every core kept busy by spinning threads (started and stopped here) gives the same bytes.
TEST_F(FramePipeline, PlansAreTheSameUnderLoad) {
  // About 5 000 boxes of varied heights: tens of thousands of pieces, a plan of some 100 ms idle.
  const fs::path city = dir_ / "city.hls";
  std::ofstream(city)
      << "for i in 0..70 { for j in 0..70 {\n"
         "  draw box(4 + (i * 7 + j * 3) % 4, 4 + (i * 5 + j * 11) % 4, 3 + (i * 13 + j * 17) % 23)\n"
         "    at translate(10 * i, 10 * j, 0)\n"
         "} }\n"
         "camera c = lookat(eye: (-200, -300, 400), target: (350, 350, 0), fov: 50)\n";
  const auto render_city = [&](const std::string& name) {
    const fs::path out = dir_ / name;
    const test::CliResult r = test::run({city.string(), "-o", out.string(), "--jobs", "2"});
    EXPECT_EQ(r.code, 0) << r.err;
    return test::read_text(out);
  };
  const std::string idle = render_city("idle.hpgl");
  ASSERT_GT(idle.size(), 100000U);
  std::atomic<bool> stop{false};
  std::vector<std::thread> burners;
  for (unsigned k = 0; k < 2 * std::max(1U, std::thread::hardware_concurrency()); ++k)
    burners.emplace_back([&stop] {
      volatile std::uint64_t x = 0;
      while (!stop.load(std::memory_order_relaxed)) x = x + 1;
    });
  const std::string loaded = render_city("loaded.hpgl");
  stop = true;
  for (std::thread& t : burners) t.join();
  EXPECT_TRUE(idle == loaded) << "the plan changed under load";
}

TEST_F(FramePipeline, ShardsTogetherWriteWhatOneRunWrites) {
  const auto whole = render("whole", "f-{frame:02}.hpgl", {"--jobs", "2"});
  ASSERT_EQ(whole.size(), 12U);
  std::map<std::string, std::string> joined;
  for (const char* shard : {"1/3", "2/3", "3/3"}) {
    const auto part = render("whole-shards", "f-{frame:02}.hpgl", {"--shard", shard, "--jobs", "2"});
    joined.insert(part.begin(), part.end());
  }
  EXPECT_EQ(joined, whole);
  // A range and its complement, likewise.
  const auto first = render("ranges", "f-{frame:02}.hpgl", {"--frames", "0-4"});
  const auto rest = render("ranges", "f-{frame:02}.hpgl", {"--frames", "5-11", "--jobs", "3"});
  EXPECT_EQ(rest, whole);
  EXPECT_EQ(first.size(), 5U);
}

TEST_F(FramePipeline, PdfPagesComeInFrameOrder) {
  render("pdf", "all.pdf", {"--jobs", "4"});
  // poppler reads the captions back, page by page: "frame K of 12" must come in frame order.
  const fs::path text = dir_ / "pdf.txt";
  const std::string command =
      "pdftotext -layout '" + (dir_ / "pdf" / "all.pdf").string() + "' '" + text.string() + "'";
  ASSERT_EQ(std::system(command.c_str()), 0) << "pdftotext (poppler-utils, installed by scripts/setup.sh)";
  const std::string pages = test::read_text(text);
  std::size_t last = 0;
  for (int k = 0; k < 12; ++k) {
    const std::size_t at = pages.find("frame " + std::to_string(k) + " of 12");
    ASSERT_NE(at, std::string::npos) << "frame " << k;
    if (k > 0) {
      EXPECT_GT(at, last) << "frame " << k;
    }
    last = at;
  }
}

TEST_F(FramePipeline, AFailingFrameKeepsTheWholeFilesBeforeItAndNothingPartial) {
  // Frame 9 divides by zero; the frames before it were rendered, planned and encoded beside it. A file
  // per frame keeps frames 0-8, each whole; a file of every frame (PDF pages, JSON) is not written at all.
  std::ofstream(script_) << kTurntable << "let boom = 1 / (frame - 9)\n";
  for (const std::string pattern : {"all.pdf", "f-{frame:02}.png", "all.json"}) {
    for (const char* jobs : {"1", "2", "4"}) {
      const fs::path sub = dir_ / ("fail-" + fs::path(pattern).extension().string().substr(1) + jobs);
      fs::create_directories(sub);
      const test::CliResult r = test::run({script_.string(), "-o", (sub / pattern).string(), "--jobs", jobs});
      EXPECT_EQ(r.code, 65) << r.err;
      EXPECT_NE(r.err.find("division by zero (in frame 9)"), std::string::npos) << r.err;
      if (pattern[0] == 'a') {
        EXPECT_TRUE(fs::is_empty(sub))
            << pattern << " --jobs " << jobs << ": " << files_in(sub).size() << " files left";
        continue;
      }
      EXPECT_NE(r.err.find("frame 9 of 12 failed; kept 9 complete files (frames 0-8), none partial"),
                std::string::npos)
          << r.err;
      const std::map<std::string, std::string> files = files_in(sub);
      std::vector<std::string> names;
      for (const auto& [name, bytes] : files) {
        names.push_back(name);
        ASSERT_GE(bytes.size(), 12U) << name;  // whole: the signature first, the IEND chunk last
        EXPECT_EQ(bytes.substr(1, 3), "PNG") << name;
        EXPECT_EQ(bytes.substr(bytes.size() - 8, 4), "IEND") << name;
      }
      std::vector<std::string> expected;
      for (int f = 0; f < 9; ++f) expected.push_back("f-0" + std::to_string(f) + ".png");
      EXPECT_EQ(names, expected) << " --jobs " << jobs;
    }
  }
}

// Ctrl-C (interrupt_requested(), set here once frame 2 is written): the files holding only frames done
// are kept whole, the one still being written is removed, and the exception says which frames are done.
TEST_F(FramePipeline, AnInterruptKeepsTheCompleteFilesOnly) {
  const auto program = Program::load(script_, "turntable.hls");
  const std::vector<int> frames = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  for (const std::string pattern : {"f-{frame:02}.svg", "f-{frame:02}.pdf", "all.pdf"}) {
    for (const unsigned jobs : {1U, 2U}) {
      const fs::path sub =
          dir_ / ("stop-" + std::to_string(jobs) + "-" + fs::path(pattern).extension().string().substr(1) +
                  (pattern[0] == 'a' ? "-all" : ""));
      fs::create_directories(sub);
      PipelineOptions options;
      options.run.title = "turntable.hls";
      options.run.frame_count = 12;
      options.run.output = (sub / pattern).string();
      options.jobs = jobs;
      options.on_frame = [](std::size_t done, std::size_t) {
        if (done == 3) interrupt_requested() = true;
      };
      try {
        run_pipeline(*program, frames, 12, options);
        ADD_FAILURE() << "not interrupted";
      } catch (const RunInterrupted& e) {
        const std::map<std::string, std::string> left = files_in(sub);
        EXPECT_EQ(left.size(), e.files.size()) << pattern;  // no temporary file stays
        if (pattern == "all.pdf") {
          EXPECT_TRUE(e.files.empty());  // the one file of the sequence was not complete
          EXPECT_TRUE(e.frames_done.empty());
        } else {
          // A file per frame: every frame done is in its own complete file; with one thread exactly 0-2
          // (SVG: written whole at once) or 0-1 (PDF: frame 2's file was still open).
          const std::vector<int> expected =
              pattern.ends_with(".svg") ? std::vector<int>{0, 1, 2} : std::vector<int>{0, 1};
          if (jobs == 1) {
            EXPECT_EQ(e.frames_done, expected) << pattern;
          }
          EXPECT_EQ(e.files.size(), e.frames_done.size()) << pattern;
          for (const fs::path& f : e.files) EXPECT_GT(fs::file_size(f), 0U) << f;
          EXPECT_EQ(left.begin()->first, pattern.ends_with(".svg") ? "f-00.svg" : "f-00.pdf");
        }
      }
      interrupt_requested() = false;
    }
  }
}

TEST_F(FramePipeline, TheLowestFailingFrameIsReportedWhateverTheJobs) {
  // Frames 4 and 7 fail; frame 7 may finish first when frames run side by side.
  std::ofstream(dir_ / "two.hls") << "animate frames 10\n"
                                  << "camera c = orbit()\n"
                                  << "draw cube(1)\n"
                                  << "let b = 1 / ((frame - 4) * (frame - 7))\n";
  for (const char* jobs : {"1", "2", "8"}) {
    const test::CliResult r =
        test::run({(dir_ / "two.hls").string(), "-o", (dir_ / "two.json").string(), "--jobs", jobs});
    EXPECT_EQ(r.code, 65);
    EXPECT_NE(r.err.find("(in frame 4)"), std::string::npos) << jobs << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "two.json"));
  }
}

TEST_F(FramePipeline, ADeviceRefusingTheScriptsPageIsReportedAtItsOutputStatement) {
  // Found while resolving frame 3's device (its paper), with frames on either side in flight.
  std::ofstream(dir_ / "paper.hls") << "animate frames 6\n"
                                    << "camera c = orbit()\n"
                                    << "draw cube(1)\n"
                                    << "output \"" << (dir_ / "p-{frame}.hpgl").string()
                                    << "\" plotter hp7475a\n"
                                    << "if frame == 3 { paper A0 }\n";
  for (const char* jobs : {"1", "2"}) {
    const test::CliResult r =
        test::run({(dir_ / "paper.hls").string(), "--jobs", jobs, "--out-dir", dir_.string()});
    EXPECT_EQ(r.code, 73) << r.err;
    EXPECT_NE(r.err.find("paper.hls:4:8: error: HPGL: plotter 'hp7475a' takes no 1189 × 841 mm page"),
              std::string::npos)
        << r.err;
    // The frames before it are plotter files as complete as any; frame 3 and those after it are absent.
    for (int f = 0; f < 6; ++f)
      EXPECT_EQ(fs::exists(dir_ / ("p-" + std::to_string(f) + ".hpgl")), f < 3) << f;
    EXPECT_NE(r.err.find("frame 3 of 6 failed; kept 3 complete files (frames 0-2), none partial"),
              std::string::npos)
        << r.err;
    for (int f = 0; f < 3; ++f) fs::remove(dir_ / ("p-" + std::to_string(f) + ".hpgl"));
  }
}

}  // namespace
}  // namespace hlr::runtime
