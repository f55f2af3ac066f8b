// The command line in-process (run_cli): options, usage errors (64), script errors (65), unreadable
// files (66), check, and that nothing is written on failure. tests/e2e/ runs the built binary.
#include "runtime/cli/cli.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "runtime/base/file_access.hpp"
#include "tests/runtime/cli_run.hpp"
#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

using Result = test::CliResult;
using test::run;

const char* kScene =
    "animate frames 3\n"
    "draw cube(2) at rotate(z: 30 * frame)\n"
    "camera main = lookat(eye: (6, -8, 5), target: (0, 0, 0))\n";

TEST(Cli, HelpAndVersion) {
  const Result help = run({"--help"});
  EXPECT_EQ(help.code, 0);
  EXPECT_NE(help.out.find("examples:"), std::string::npos);
  EXPECT_NE(help.out.find("--shard"), std::string::npos);
  const Result version = run({"--version"});
  EXPECT_EQ(version.code, 0);
  // From the build folder the modules are the source tree's (an installed program names its own).
  EXPECT_EQ(version.out, "hlrscript 0.1.0\nlibrary modules: " + stdlib_module_directory().string() + "\n");
}

TEST(Cli, UsageErrors) {
  // No script: standard input is the script (here empty, so it declares no camera).
  EXPECT_EQ(run({}).code, 65);
  EXPECT_EQ(run({"--bogus", "a.hls"}).code, 64);
  EXPECT_EQ(run({"a.hls", "b.hls"}).code, 64);
  EXPECT_EQ(run({"a.hls", "--frames", "x"}).code, 64);
  EXPECT_EQ(run({"a.hls", "--shard", "4/3"}).code, 64);
  EXPECT_EQ(run({"a.hls", "--hidden", "dotted"}).code, 64);
  EXPECT_EQ(run({"a.hls", "--jobs", "-2"}).code, 64);
  EXPECT_EQ(run({"check"}).code, 64);
  const Result r = run({"a.hls", "--frames", "9-2"});
  EXPECT_NE(r.err.find("hlrscript: error: --frames 9-2: expected frame numbers 0 <= A <= B as A-B"),
            std::string::npos)
      << r.err;
}

TEST(Cli, RendersChecksAndRefuses) {
  const test::TempDir dir("runtime-cli");
  const std::string script = dir.write("scene.hls", kScene).string();
  const std::string pdf = (dir.path() / "out.pdf").string();

  const Result check = run({"check", script});
  EXPECT_EQ(check.code, 0) << check.err;
  EXPECT_NE(check.out.find(": ok: 3 frames evaluated"), std::string::npos) << check.out;
  EXPECT_FALSE(std::filesystem::exists(pdf));

  const Result ok = run({script, "-o", pdf, "--jobs", "2", "--stats"});
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_TRUE(std::filesystem::exists(pdf));
  EXPECT_NE(ok.out.find("wrote " + pdf + ": 3 frames"), std::string::npos) << ok.out;
  EXPECT_NE(ok.err.find("frame 2: camera main, 1 objects, 6 faces"), std::string::npos) << ok.err;

  const Result per_frame = run({script, "-o", (dir.path() / "f-{frame:02}.pdf").string(), "--frames", "1-2"});
  EXPECT_EQ(per_frame.code, 0) << per_frame.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "f-00.pdf"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "f-01.pdf"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "f-02.pdf"));

  EXPECT_EQ(run({script, "-o", (dir.path() / "out.svgz").string()}).code, 64);
  EXPECT_EQ(run({script, "-o", script}).code, 64);
  EXPECT_EQ(run({script, "--camera", "nope", "-o", pdf}).code, 64);
  EXPECT_EQ(run({script, "--frames", "5-9", "-o", pdf}).code, 64);
  EXPECT_EQ(run({(dir.path() / "missing.hls").string()}).code, 66);
}

TEST(Cli, WritesJsonFrames) {
  const test::TempDir dir("runtime-cli-json");
  const std::string script = dir.write("scene.hls", kScene).string();
  const std::string out = (dir.path() / "lines.json").string();
  const Result r = run({script, "-o", out, "--frames", "1-2"});
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(out);
  const nlohmann::json json = nlohmann::json::parse(in);
  EXPECT_EQ(json["format"], "hlrscript.lines/1");
  ASSERT_EQ(json["frames"].size(), 2U);
  EXPECT_EQ(json["frames"][0]["frame"], 1);
  EXPECT_EQ(json["frames"][1]["frame"], 2);
  EXPECT_GT(json["frames"][0]["segments"].size(), 0U);
  EXPECT_EQ(json["frames"][0]["segments"][0]["object"], "cube");
}

// A .jsonl file holds a frame a line, each whole: the document's format, title and page, then the same
// members as the .json document's frame; --json keeps only the parts asked for.
TEST(Cli, WritesJsonLinesAndChosenParts) {
  const test::TempDir dir("runtime-cli-jsonl");
  const std::string script = dir.write("scene.hls", kScene).string();
  const std::string doc_path = (dir.path() / "lines.json").string();
  const std::string lines_path = (dir.path() / "lines.jsonl").string();
  ASSERT_EQ(run({script, "-o", doc_path, "--frames", "0-2"}).code, 0);
  const Result r = run({script, "-o", lines_path, "--frames", "0-2"});
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream doc_in(doc_path);
  const nlohmann::json doc = nlohmann::json::parse(doc_in);
  std::ifstream lines_in(lines_path);
  std::vector<nlohmann::json> lines;
  for (std::string line; std::getline(lines_in, line);) lines.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(lines.size(), 3U);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    nlohmann::json frame = lines[i];
    EXPECT_EQ(frame["format"], "hlrscript.lines/1");
    EXPECT_EQ(frame["page"], doc["page"]);
    EXPECT_EQ(frame["title"], doc["title"]);
    frame.erase("format");
    frame.erase("page");
    frame.erase("title");
    EXPECT_EQ(frame, doc["frames"][i]) << "frame " << i;
  }

  const std::string some = (dir.path() / "some.json").string();
  ASSERT_EQ(run({script, "-o", some, "--frames", "0-2", "--json", "strokes,stats"}).code, 0);
  std::ifstream some_in(some);
  const nlohmann::ordered_json chosen = nlohmann::ordered_json::parse(some_in);
  std::vector<std::string> keys;
  for (const auto& [key, value] : chosen["frames"][0].items()) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"frame", "time", "strokes", "stroke_pens", "stats"}));
  EXPECT_EQ(nlohmann::json(chosen["frames"][2]["strokes"]), doc["frames"][2]["strokes"]);

  const Result bad = run({script, "-o", some, "--json", "strokes,colours"});
  EXPECT_EQ(bad.code, 64);
  EXPECT_NE(bad.err.find("--json takes all or a comma-separated list"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("'strokes,colours'"), std::string::npos) << bad.err;
}

TEST(Cli, ABrokenScriptWritesNothing) {
  const test::TempDir dir("runtime-cli-broken");
  const std::string script =
      dir.write("broken.hls", "animate frames 4\ndraw cube(2)\nlet x = 1 / (frame - 3)\ncamera c = orbit()\n")
          .string();
  const std::string pdf = (dir.path() / "out.pdf").string();
  const Result r = run({script, "-o", pdf});
  EXPECT_EQ(r.code, 65);
  EXPECT_NE(r.err.find("broken.hls:3:14: error: division by zero (in frame 3)"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(pdf));
  const Result syntax = run({dir.write("syntax.hls", "draw (\n").string(), "-o", pdf});
  EXPECT_EQ(syntax.code, 65);
  EXPECT_NE(syntax.err.find("syntax.hls:"), std::string::npos);
  const Result no_camera = run({dir.write("nocam.hls", "draw cube(1)\n").string(), "-o", pdf});
  EXPECT_EQ(no_camera.code, 65);
  EXPECT_NE(no_camera.err.find("declares no camera"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(pdf));
}

}  // namespace
}  // namespace hlr::runtime

namespace hlr::runtime {
namespace {

// Desens' carrier asks, by its solid options, to accept its warped hull and crossing hole: a run says
// how many notes that gave and prints none; --verbose prints them.
TEST(Cli, NotesOnAcceptedLegacyDataOnlyWithVerbose) {
  const test::TempDir dir("cli-notes");
  const std::string script =
      (std::filesystem::path(HLR_TEST_DATA_DIR).parent_path().parent_path() / "examples/desens/carrier-2.hls")
          .string();
  const test::CliResult quiet = run({script, "-o", (dir.path() / "a.json").string()});
  ASSERT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(quiet.err,
            "hlrscript: 5 notes on what the script's solid options accept (--verbose shows them)\n");
  const test::CliResult verbose = run({script, "-o", (dir.path() / "b.json").string(), "--verbose"});
  ASSERT_EQ(verbose.code, 0) << verbose.err;
  EXPECT_NE(verbose.err.find("carrier-model.hls:111:3: note: solid 'carrier': face 13 is not planar"),
            std::string::npos)
      << verbose.err;
  EXPECT_NE(verbose.err.find("note: solid 'carrier': hole 1 of face 17 crosses its outer boundary"),
            std::string::npos)
      << verbose.err;
  EXPECT_EQ(verbose.err.find("warning:"), std::string::npos) << verbose.err;
}

}  // namespace
}  // namespace hlr::runtime
