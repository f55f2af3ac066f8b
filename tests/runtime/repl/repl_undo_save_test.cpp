// The REPL keeps what it says: every change is taken back by exactly one :undo, and :save writes a
// script that runs and draws what the session shows — random sequences of inputs and commands (fixed
// seed), each ended by :render in the session and by hlrscript on the saved script, the segments of
// every frame compared.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "runtime/repl/repl_session.hpp"
#include "tests/runtime/cli_run.hpp"
#include "tests/support/seeded_rng.hpp"
#include "tests/support/temp_dir.hpp"

namespace hlr::runtime {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::vector<std::string> kStart = {
    "let w = 2",
    "animate frames 3",
    "draw box(w, 1, 1)",
    "draw cube(0.5) at translate(frame - 1, 2, 0)",
    "camera a = lookat(eye: (6, -7, 5), target: (0, 0, 0.5), fov: 40)",
    "camera b = ortho(eye: (1, -10, 3), target: (0, 0, 0.5), height: 5)",
};

// One random input: a statement or a command that changes the session (or fails and changes nothing).
std::string random_input(hlr::test::Rng& rng) {
  const auto pick = [&](int n) { return rng.integer(0, n - 1); };
  const auto number = [&](int lo, int hi) { return std::to_string(rng.integer(lo, hi)); };
  switch (pick(14)) {
    case 0:
      return "let w = " + number(1, 4);
    case 1:
      return "draw cube(0.6) at translate(" + number(-3, 3) + ", -2, 0)";
    case 2:
      return "camera c = lookat(eye: (" + number(-6, 6) + ", -8, 4), target: (0, 0, 0.5), fov: 45)";
    case 3: {
      const char* styles[] = {"style hidden dashed", "style hidden off", "style hidden levels 2",
                              "style hidden levels 3 pen 2"};
      return styles[pick(4)];
    }
    case 4:
    case 5:
      return ":orbit " + number(-40, 40) + (pick(2) ? " " + number(-20, 20) : "");
    case 6:
      return ":zoom " + std::string(pick(2) ? "1.5" : "0.8");
    case 7:
      return ":dolly " + number(-2, 2);
    case 8: {
      const char* names[] = {"", " a", " b", " c"};
      return std::string(":camera") + names[pick(4)];
    }
    case 9: {
      const char* hidden[] = {":hidden on", ":hidden off", ":levels 2", ":levels 3"};
      return hidden[pick(4)];
    }
    case 10:
      return ":frame " + number(0, 2);
    default:
      return ":undo";
  }
}

// Every frame's segments (world and picture end points, object, hidden) from a JSON file.
json segments_of(const fs::path& file) {
  const json doc = json::parse(test::read_text(file));
  json out = json::array();
  for (const json& f : doc["frames"]) out.push_back(f["segments"]);
  return out;
}

bool same_numbers(const json& a, const json& b) {
  if (a.is_number() && b.is_number()) return std::abs(a.get<double>() - b.get<double>()) <= 1e-9;
  if (a.type() != b.type() || a.size() != b.size()) return false;
  if (a.is_array()) {
    for (std::size_t i = 0; i < a.size(); ++i)
      if (!same_numbers(a[i], b[i])) return false;
    return true;
  }
  if (a.is_object()) {
    for (auto it = a.begin(); it != a.end(); ++it)
      if (!b.contains(it.key()) || !same_numbers(it.value(), b[it.key()])) return false;
    return true;
  }
  return a == b;
}

TEST(ReplUndoSave, SavedSessionsDrawWhatTheSessionDraws) {
  const hlr::test::TempDir dir("repl-undo-save");
  hlr::test::Rng rng(20261206);
  int compared = 0;
  for (int round = 0; round < 40; ++round) {
    ReplSession s;
    for (const std::string& line : kStart) ASSERT_EQ(s.feed(line).kind, ReplReply::Kind::Done) << line;
    std::string transcript;
    for (int step = 0; step < 8; ++step) {
      const std::string input = random_input(rng);
      const ReplReply r = s.feed(input);
      transcript += input + (r.kind == ReplReply::Kind::Error ? "   (refused)\n" : "\n");
    }
    SCOPED_TRACE("round " + std::to_string(round) + ":\n" + transcript);
    const fs::path shown = dir.path() / "shown.json", saved = dir.path() / "saved.hls",
                   drawn = dir.path() / "drawn.json";
    const ReplReply rendered = s.feed(":render " + shown.string());
    ASSERT_EQ(s.feed(":save " + saved.string()).kind, ReplReply::Kind::Done);
    // As a user would run it: the saved script's own style decides the hidden layer.
    const test::CliResult run = test::run({saved.string(), "-o", drawn.string()});
    if (rendered.kind != ReplReply::Kind::Done) {  // undone back past every camera, say: both refuse
      EXPECT_NE(run.code, 0) << rendered.text << test::read_text(saved);
      continue;
    }
    ++compared;
    ASSERT_EQ(run.code, 0) << run.err << "\n" << test::read_text(saved);
    EXPECT_TRUE(same_numbers(segments_of(shown), segments_of(drawn))) << test::read_text(saved);
  }
  EXPECT_GE(compared, 30);  // most rounds end with something to draw
}

// Each change is one :undo: the script goes back step by step to where the changes began. (Inputs that
// may change nothing when accepted — :frame to the frame shown, a bare :camera — are left out here.)
TEST(ReplUndoSave, EveryChangeIsUndoneByOneUndo) {
  hlr::test::Rng rng(7);
  for (int round = 0; round < 20; ++round) {
    ReplSession s;
    for (const std::string& line : kStart) ASSERT_EQ(s.feed(line).kind, ReplReply::Kind::Done);
    std::vector<std::string> history = {s.script()};
    std::string transcript;
    while (history.size() < 9) {
      const std::string input = random_input(rng);
      if (input == ":undo" || input == ":camera" || input.rfind(":frame", 0) == 0) continue;
      const ReplReply r = s.feed(input);
      transcript += input + (r.kind == ReplReply::Kind::Error ? "   (refused)\n" : "\n");
      if (r.kind == ReplReply::Kind::Done) history.push_back(s.script());
    }
    SCOPED_TRACE("round " + std::to_string(round) + ":\n" + transcript);
    for (std::size_t k = history.size() - 1; k > 0; --k) {
      const ReplReply r = s.feed(":undo");
      ASSERT_EQ(r.kind, ReplReply::Kind::Done) << r.text;
      EXPECT_EQ(s.script(), history[k - 1]) << "after undoing change " << k;
    }
  }
}

// The cases, one by one.
TEST(ReplUndoSave, TheReportedCases) {
  const hlr::test::TempDir dir("repl-undo-cases");
  const fs::path file = dir.write("a.hls",
                                  "draw box(4, 1, 2)\n"
                                  "camera view = lookat(eye: (8, -9, 6), target: (2, 0.5, 1), fov: 30)\n"
                                  "style hidden dashed\n");
  ReplSession s;
  ASSERT_EQ(s.feed(":load " + file.string()).kind, ReplReply::Kind::Done);
  const std::string loaded = s.script();
  // :orbit then :undo takes back the orbit, not the loaded file.
  ASSERT_EQ(s.feed(":orbit 30").kind, ReplReply::Kind::Done);
  EXPECT_EQ(s.feed(":undo").text, "undone: :orbit 30\n");
  EXPECT_EQ(s.script(), loaded);
  // :hidden off over the file's own style hidden: the saved script runs.
  ASSERT_EQ(s.feed(":hidden off").kind, ReplReply::Kind::Done);
  const fs::path saved = dir.path() / "saved.hls";
  EXPECT_EQ(s.feed(":save " + saved.string()).text,
            "saved the session to " + saved.string() + " (1 input)\n");
  const test::CliResult check = test::run({"check", saved.string()});
  EXPECT_EQ(check.code, 0) << check.err << test::read_text(saved);
  // :camera with no name says that the steps are dropped.
  ASSERT_EQ(s.feed(":zoom 2").kind, ReplReply::Kind::Done);
  EXPECT_NE(s.feed(":camera").text.find("the :orbit, :zoom and :dolly steps are dropped"), std::string::npos);
  // An unknown name typed alone: the message quotes what was typed, at its column.
  const ReplReply unknown = s.feed("foo");
  EXPECT_EQ(unknown.kind, ReplReply::Kind::Error);
  EXPECT_NE(unknown.text.find(":1: error: unknown name 'foo'"), std::string::npos) << unknown.text;
  EXPECT_EQ(unknown.text.find("__repl_value"), std::string::npos) << unknown.text;
  EXPECT_NE(unknown.text.find(" | foo\n"), std::string::npos) << unknown.text;
  // The stepped camera's name says what it is.
  ASSERT_EQ(s.feed(":orbit 10").kind, ReplReply::Kind::Done);
  EXPECT_NE(s.script().find("camera adjusted_view = adjust("), std::string::npos) << s.script();
  // :render of an unknown type names the command.
  EXPECT_EQ(s.feed(":render out.xyz").text.rfind(":render out.xyz: unknown output type '.xyz'", 0), 0U);
}

}  // namespace
}  // namespace hlr::runtime
