// The REPL without a terminal: transcripts written by hand (inputs and the replies they must give), the
// braille picture of a cube checked cell by cell, :save checked by rendering the saved script, and the
// command line's two ways in through standard input (a script, a transcript).
#include "runtime/repl/repl_session.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "runtime/base/interrupt.hpp"
#include "tests/runtime/cli_run.hpp"
#include "tests/runtime/runtime_test_support.hpp"

namespace hlr::runtime {
namespace {

namespace fs = std::filesystem;

std::string feed_all(ReplSession& s, const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) out += s.feed(l).text;
  return out;
}

TEST(ReplSession, AnExpressionShowsItsValue) {
  ReplSession s;
  EXPECT_EQ(s.feed("box(size: (1, 2, 3))").text,
            "solid box: 6 faces, 12 edges, 8 vertices, bounds (-0.5, -1, -1.5) to (0.5, 1, 1.5), closed\n");
  EXPECT_EQ(s.feed("2 + 3 * 4").text, "14\n");
  EXPECT_EQ(s.feed("[1, 2] + [3]").text, "[1, 2, 3]\n");
  EXPECT_EQ(s.script(), "# Saved from an hlrscript session.\n");  // values change nothing
}

TEST(ReplSession, UnfinishedInputWaitsForMoreLines) {
  ReplSession s;
  EXPECT_EQ(s.feed("def twice(x) {").kind, ReplReply::Kind::More);
  EXPECT_TRUE(s.continuing());
  EXPECT_EQ(s.feed("  return x * 2").kind, ReplReply::Kind::More);
  const ReplReply r = s.feed("}");
  EXPECT_EQ(r.kind, ReplReply::Kind::Done);
  EXPECT_EQ(r.text, "twice = function twice(x)\n");
  EXPECT_EQ(s.feed("twice(21)").text, "42\n");
  EXPECT_EQ(s.feed("let y = 1 +").kind, ReplReply::Kind::More);
  EXPECT_EQ(s.feed("  2").text, "y = 3\n");
  // Ctrl-C drops the unfinished statement.
  EXPECT_EQ(s.feed("let z = (1,").kind, ReplReply::Kind::More);
  s.cancel_input();
  EXPECT_FALSE(s.continuing());
  EXPECT_EQ(s.feed("z").kind, ReplReply::Kind::Error);
}

TEST(ReplSession, AnErrorChangesNothing) {
  ReplSession s;
  feed_all(s, {"let a = 1"});
  const std::string before = s.script();
  const ReplReply bad = s.feed("let b = a +* 2");
  EXPECT_EQ(bad.kind, ReplReply::Kind::Error);
  EXPECT_EQ(bad.text,
            "<input>:1:12: error: expected an operand after the operator\n"
            "   1 | let b = a +* 2\n"
            "     |            ^\n");
  const ReplReply unknown = s.feed("draw nothing_here");
  EXPECT_EQ(unknown.kind, ReplReply::Kind::Error);
  EXPECT_NE(unknown.text.find("unknown name 'nothing_here'"), std::string::npos) << unknown.text;
  EXPECT_EQ(s.script(), before);
  EXPECT_EQ(s.feed("let b = a + 2").text, "b = 3\n");
}

TEST(ReplSession, ARedefinitionReplacesTheOldOneInPlace) {
  ReplSession s;
  feed_all(s, {"let w = 2", "draw box(w, 1, 1)", "camera c = orbit()"});
  EXPECT_EQ(s.feed("let w = 5").text, "replaced: let w = 2\nw = 5\n");
  EXPECT_EQ(s.script(),
            "# Saved from an hlrscript session.\nlet w = 5\ndraw box(w, 1, 1)\ncamera c = orbit()\n");
  EXPECT_EQ(s.feed(":undo").text, "undone: 'let w = 5'\n");
  EXPECT_NE(s.script().find("let w = 2"), std::string::npos);
}

TEST(ReplSession, ShowDrawsTheCubesOutlineInBraille) {
  ReplSession s(TerminalSize{40, 22});
  feed_all(
      s, {"draw cube(2)", "camera front = ortho(eye: (0, -10, 0), target: (0, 0, 0), height: 4, aspect: 1)"});
  const std::string out = s.feed(":show").text;
  std::vector<std::u32string> rows;
  std::u32string row;
  for (std::size_t i = 0; i < out.size();) {
    const auto c = static_cast<unsigned char>(out[i]);
    if (c == '\n') {
      rows.push_back(row);
      row.clear();
      ++i;
      continue;
    }
    if (c == 0xe2) {  // U+28xx: three bytes
      row += static_cast<char32_t>(((c & 0x0f) << 12) | ((out[i + 1] & 0x3f) << 6) | (out[i + 2] & 0x3f));
      i += 3;
    } else {
      row += c;
      ++i;
    }
  }
  ASSERT_EQ(rows.size(), 21U) << out;  // 20 picture rows and the caption
  EXPECT_EQ(rows.back().substr(0, 8), U"camera f");
  // A 2 × 2 square seen face on, in a 4-unit-high view of 40 × 20 cells (80 × 80 dots): its outline is
  // the only thing drawn; its middle and the picture's corners are blank.
  auto blank = [&](int r, int c) {
    return rows[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] == 0x2800;
  };
  for (std::size_t r = 0; r + 1 < rows.size(); ++r) {
    EXPECT_EQ(rows[r].size(), 40U) << r;
  }
  EXPECT_TRUE(blank(10, 20));  // the centre of the face
  EXPECT_TRUE(blank(0, 0) && blank(0, 39) && blank(19, 0) && blank(19, 39));
  int drawn = 0;
  for (int r = 0; r < 20; ++r)
    for (int c = 0; c < 40; ++c) drawn += !blank(r, c);
  // The outline: two columns of ≈ 10 cells and two rows of ≈ 20 (the square spans half of each side).
  EXPECT_GT(drawn, 40);
  EXPECT_LT(drawn, 80);
  int left = -1, right = -1;
  for (int c = 0; c < 40; ++c)
    if (!blank(10, c)) {
      (left < 0 ? left : right) = c;
    }
  EXPECT_NEAR(left, 10, 1);
  EXPECT_NEAR(right, 29, 1);
}

TEST(ReplSession, CommandsByUnambiguousPrefix) {
  ReplSession s;
  EXPECT_EQ(s.feed(":q").kind, ReplReply::Kind::Quit);
  EXPECT_EQ(s.feed(":s").text, "':s' could be :show, :stats, :scene, :save\n");
  EXPECT_EQ(s.feed(":frobnicate").text, "unknown command ':frobnicate'; :help lists them\n");
  EXPECT_NE(s.feed(":help").text.find(":render [FILE]"), std::string::npos);
  EXPECT_EQ(s.feed(":show").kind, ReplReply::Kind::Error);  // no camera yet: says how to add one
  EXPECT_NE(s.feed(":show").text.find("camera main = lookat("), std::string::npos);
  EXPECT_EQ(s.feed(":hidden maybe").kind, ReplReply::Kind::Error);
  EXPECT_EQ(s.feed(":frame 3").kind, ReplReply::Kind::Error);  // one frame only
  EXPECT_EQ(s.feed(":frames").text, "one frame (no animate statement); :frame 0 is the drawing\n");
  EXPECT_EQ(s.feed(":fr").text, "':fr' could be :frame, :frames\n");
  s.feed("animate frames 12 fps 6");
  EXPECT_EQ(s.feed(":frame 5").kind, ReplReply::Kind::Done);
  EXPECT_EQ(s.feed(":frames").text,
            "12 frames at 6 fps (frame 0 to 11); looking at frame 5, :frame N for another\n");
}

TEST(ReplSession, CompletionOffersBuiltinsNamesAndCommands) {
  ReplSession s;
  feed_all(s, {"let torque = 3"});
  EXPECT_EQ(s.completions("draw tor", "tor"), (std::vector<std::string>{"torque", "torus"}));
  EXPECT_EQ(s.completions(":sh", ":sh"), (std::vector<std::string>{":show"}));
  EXPECT_EQ(s.completions("ani", "ani"), (std::vector<std::string>{"animate"}));
  EXPECT_TRUE(s.completions(":load ex", "ex").empty());  // file names: libedit's own completion
}

TEST(ReplSession, CompletionInsideACallOffersItsParameterNamesFirst) {
  ReplSession s;
  EXPECT_EQ(s.completions("camera c = lookat(", ""),
            (std::vector<std::string>{"eye:", "target:", "up:", "fov:", "aspect:", "near:"}));
  // After an argument, with a word begun: the parameters, then what an expression may use.
  EXPECT_EQ(s.completions("camera c = lookat(eye: (1, 2, 3), f", "f"),
            (std::vector<std::string>{"fov:", "face", "floor", "follow", "for"}));
  // Inside a nested call, the inner one's; after it closed, the outer one's again.
  EXPECT_EQ(s.completions("draw box(size: vec(", "")[0], "x:");
  EXPECT_EQ(s.completions("draw sphere(2, sl", "sl"), (std::vector<std::string>{"slices:"}));
  // Tab after a name adds a space: "lookat (" is a call of lookat too. Inside a vector, no parameters.
  EXPECT_EQ(s.completions("camera c = lookat (ey", "ey"), (std::vector<std::string>{"eye:"}));
  const std::vector<std::string> in_vector = s.completions("camera c = lookat(eye: (1, 2", "");
  EXPECT_EQ(std::count(in_vector.begin(), in_vector.end(), "eye:"), 0);
  EXPECT_FALSE(in_vector.empty());  // what an expression may use
  // The session's own functions.
  feed_all(s, {"def post(height, width = 1) = box(width, width, height)"});
  EXPECT_EQ(s.completions("draw post(h", "h"),
            (std::vector<std::string>{"height:", "hatch", "heightfield", "hexahedron", "hole"}));
  // A file name after import(": libedit's own completion.
  EXPECT_TRUE(s.completions("let m = import(\"b", "b").empty());
}

TEST(ReplSession, HelpOnABuiltinAStatementOrACommand) {
  ReplSession s;
  const std::string lookat = s.feed(":help lookat").text;
  EXPECT_EQ(lookat.substr(0, lookat.find('\n')),
            "lookat(eye:, target:, up: (0, 0, 1), fov: 40, aspect:, near:)");
  EXPECT_NE(
      lookat.find("\n  parameters: eye (a vector), target (a vector), up = (0, 0, 1) (a vector), fov = 40 "
                  "(a number), aspect (a number, optional), near (a number, optional)\n"),
      std::string::npos)
      << lookat;
  EXPECT_EQ(s.feed(":help draw").text.substr(0, 34), "draw EXPR [at TRANSFORM] [pen N]\n ");
  EXPECT_EQ(
      s.feed(":help :orbit").text,
      ":orbit DTHETA [DPHI]\n  step the camera round the scene (degrees; Albers' theta and phi keys)\n");
  // A word that is a statement and a command: both.
  const std::string camera = s.feed(":help camera").text;
  EXPECT_NE(camera.find(":camera [NAME]"), std::string::npos);
  EXPECT_NE(camera.find("camera NAME = EXPR"), std::string::npos);
  const ReplReply unknown = s.feed(":help bx");
  EXPECT_EQ(unknown.kind, ReplReply::Kind::Error);
  EXPECT_EQ(unknown.text.substr(0, unknown.text.find('\n')), "no help on 'bx'; did you mean 'box'?");
  EXPECT_EQ(s.completions(":help cyl", "cyl"), (std::vector<std::string>{"cylinder"}));
}

// A terminal that speaks sixel or kitty graphics gets the real picture (its pixels are checked in
// terminal_graphics_test.cpp); the line under it is the same.
TEST(ReplSession, ShowSendsTheRealPictureToGraphicsTerminals) {
  ReplSession s({40, 12});
  feed_all(s, {"draw cube(2)", "camera main = lookat(eye: (6, -8, 5), target: (0, 0, 0))"});
  const std::string braille = s.feed(":show").text;
  const std::string caption = braille.substr(braille.rfind("camera main"));
  s.set_graphics(TerminalGraphics::Sixel, {160, 120});
  const std::string sixel = s.feed(":show").text;
  EXPECT_EQ(sixel.substr(0, 3), "\x1bPq");
  EXPECT_EQ(sixel.substr(sixel.size() - caption.size()), caption);
  s.set_graphics(TerminalGraphics::Kitty, {160, 120});
  EXPECT_EQ(s.feed(":show").text.substr(0, 3), "\x1b_G");
}

// Ctrl-C sets interrupt_requested() (runtime/repl/repl.cpp's SIGINT handler); the work under way stops and
// the session is as it was.
TEST(ReplSession, AnInterruptStopsTheWorkAndChangesNothing) {
  ReplSession s({40, 12});
  feed_all(s, {"draw cube(2)", "camera main = lookat(eye: (6, -8, 5), target: (0, 0, 0))"});
  const std::string before = s.script();
  const std::string picture = s.feed(":show").text;
  interrupt_requested() = true;
  EXPECT_EQ(s.feed(":show").text, "stopped (Ctrl-C); the session is as it was\n");
  EXPECT_EQ(s.feed(":orbit 30").text, "stopped (Ctrl-C); the session is as it was\n");
  EXPECT_EQ(s.feed("draw sphere(1) at translate(3, 0, 0)").text,
            "stopped (Ctrl-C); the session is as it was\n");
  interrupt_requested() = false;
  EXPECT_EQ(s.script(), before);
  EXPECT_EQ(s.feed(":show").text, picture);  // the orbit that was stopped left the camera alone
}

class ReplFiles : public ::testing::Test {
 protected:
  // The JSON without its title line (the title is the script's name, which differs).
  static std::string without_title(std::string json) {
    const std::size_t at = json.find("\"title\"");
    if (at != std::string::npos) json.erase(at, json.find('\n', at) - at + 1);
    return json;
  }
  const test::TempDir scratch_{std::string("repl-") +
                               ::testing::UnitTest::GetInstance()->current_test_info()->name()};
  const fs::path dir_ = scratch_.path();
};

TEST_F(ReplFiles, SaveWritesAScriptThatRendersTheSameDrawing) {
  ReplSession s;
  feed_all(s,
           {"let size = (4, 2, 3)", "draw box(size.x, size.y, size.z)", "draw cube(1) at translate(5, 0, 0)",
            "camera side = lookat(eye: (12, -14, 9), target: (2, 1, 1))",
            "camera top = ortho(eye: (2, 1, 20), target: (2, 1, 0), up: (0, 1, 0), height: 12)"});
  feed_all(s, {":camera side", ":hidden on"});
  const fs::path saved = dir_ / "session.hls";
  EXPECT_EQ(s.feed(":save " + saved.string()).text,
            "saved the session to " + saved.string() + " (5 inputs)\n");
  EXPECT_EQ(s.feed(":render " + (dir_ / "from-session.json").string()).kind, ReplReply::Kind::Done);
  const test::CliResult r = test::run({saved.string(), "-o", (dir_ / "from-file.json").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string a = test::read_text(dir_ / "from-session.json"),
                    b = test::read_text(dir_ / "from-file.json");
  EXPECT_NE(a.find("\"hidden\":true"), std::string::npos);  // the session's :hidden on
  EXPECT_EQ(without_title(a), without_title(b));
  // :load reads it back as the whole session.
  ReplSession t;
  EXPECT_EQ(t.feed(":load " + saved.string()).text,
            "loaded " + saved.string() + ": 2 objects, 12 faces, 2 cameras\n");
}

TEST_F(ReplFiles, OrbitZoomAndDollyChangeThePictureAndSaveAsAdjust) {
  ReplSession s(TerminalSize{40, 22});
  feed_all(s, {"draw box(3, 2, 1)", "camera c = lookat(eye: (10, -6, 5), target: (1.5, 1, 0.5))"});
  const std::string before = s.feed(":show").text;
  const ReplReply orbited = s.feed(":orbit 60 15");
  ASSERT_EQ(orbited.kind, ReplReply::Kind::Done) << orbited.text;
  EXPECT_NE(orbited.text, before);  // the picture moved
  EXPECT_NE(orbited.text.find("camera adjusted_c, frame 0"), std::string::npos) << orbited.text;
  EXPECT_EQ(s.feed(":zoom 2").kind, ReplReply::Kind::Done);
  EXPECT_EQ(s.feed(":dolly 1.5").kind, ReplReply::Kind::Done);
  EXPECT_EQ(s.feed(":zoom -1").kind, ReplReply::Kind::Error);
  EXPECT_EQ(s.feed(":orbit left").kind, ReplReply::Kind::Error);
  // Saved as the camera's own expression, adjusted about the middle of the box.
  EXPECT_NE(s.script().find(
                "camera adjusted_c = adjust(lookat(eye: (10, -6, 5), target: (1.5, 1, 0.5)), theta: 60, "
                "phi: 15, zoom: 2, dolly: 1.5, pivot: (1.5, 1, 0.5))"),
            std::string::npos)
      << s.script();
  const fs::path saved = dir_ / "orbit.hls";
  s.feed(":save " + saved.string());
  EXPECT_EQ(s.feed(":render " + (dir_ / "session.json").string()).kind, ReplReply::Kind::Done);
  ASSERT_EQ(test::run({saved.string(), "-o", (dir_ / "file.json").string()}).code, 0);
  EXPECT_EQ(without_title(test::read_text(dir_ / "session.json")),
            without_title(test::read_text(dir_ / "file.json")));
  // Choosing a camera again starts from its statement.
  EXPECT_EQ(s.feed(":camera c").kind, ReplReply::Kind::Done);
  EXPECT_EQ(s.feed(":show").text, before);
}

TEST_F(ReplFiles, StandardInputIsAScriptWhenNoReplIsAskedFor) {
  const test::CliResult ok =
      test::run_with_input({"-o", (dir_ / "piped.json").string()}, "camera c = orbit()\ndraw cube(1)\n");
  const test::CliResult bad =
      test::run_with_input({"-o", (dir_ / "broken.json").string()}, "camera c = orbit()\ndraw cube(nope)\n");
  const test::CliResult repl = test::run_with_input({"repl"}, "let n = 6 * 7\nn\n:quit\nn\n");
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_TRUE(fs::exists(dir_ / "piped.json"));
  EXPECT_EQ(bad.code, 65);
  EXPECT_NE(bad.err.find("<stdin>:2:11: error: unknown name 'nope'"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir_ / "broken.json"));
  EXPECT_EQ(repl.code, 0);
  EXPECT_EQ(repl.out, "n = 42\n42\n");  // nothing after :quit
}

}  // namespace
}  // namespace hlr::runtime
