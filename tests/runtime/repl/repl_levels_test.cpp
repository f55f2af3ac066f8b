// The REPL's :levels N and :hidden with occlusion levels: the range, what :save writes (the session's
// own `style hidden` statement rewritten, its pen kept), :undo, :help, and :render's JSON.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "runtime/repl/repl_session.hpp"
#include "tests/runtime/cli_run.hpp"
#include "tests/support/temp_dir.hpp"

namespace hlr::runtime {
namespace {

namespace fs = std::filesystem;

const char* kCamera = "camera main = lookat(eye: (4, -5, 3), target: (0.5, 0.5, 0.5))";

TEST(ReplLevels, TheRange) {
  ReplSession s;
  for (const char* bad : {":levels", ":levels 0", ":levels 17", ":levels 2.5", ":levels x", ":levels 3 4"}) {
    const ReplReply r = s.feed(bad);
    EXPECT_EQ(r.kind, ReplReply::Kind::Error) << bad;
    EXPECT_EQ(r.text, ":levels needs a whole number from 1 to 16, as in :levels 3\n") << bad;
  }
  EXPECT_EQ(s.feed(":levels 16").text, "hidden lines by occlusion level, levels 1 to 16\n");
  EXPECT_EQ(s.feed(":hidden off").text, "hidden lines off\n");
  EXPECT_EQ(s.feed(":hidden on").text, "hidden lines dashed\n");
  EXPECT_EQ(s.feed(":l").text, "':l' could be :load, :levels\n");
  EXPECT_NE(s.feed(":help").text.find(":levels N"), std::string::npos);
}

TEST(ReplLevels, SaveWritesTheStyleAndUndoTakesItBack) {
  ReplSession s;
  ASSERT_EQ(s.feed("draw cube(1)").kind, ReplReply::Kind::Done);
  ASSERT_EQ(s.feed(kCamera).kind, ReplReply::Kind::Done);
  const std::string plain = s.script();
  ASSERT_EQ(s.feed(":levels 3").kind, ReplReply::Kind::Done);
  // No style statement in the session: one is added.
  EXPECT_EQ(s.script(), plain + "style hidden levels 3\n");
  ASSERT_EQ(s.feed(":hidden off").kind, ReplReply::Kind::Done);  // off ends the levels
  EXPECT_EQ(s.script(), plain + "style hidden off\n");
  EXPECT_EQ(s.feed(":undo").text, "undone: :hidden off\n");
  EXPECT_EQ(s.script(), plain + "style hidden levels 3\n");
  EXPECT_EQ(s.feed(":undo").text, "undone: :levels 3\n");
  EXPECT_EQ(s.script(), plain);
}

TEST(ReplLevels, TheSessionsStyleStatementIsRewrittenKeepingItsPen) {
  ReplSession s;
  ASSERT_EQ(s.feed("draw cube(1)").kind, ReplReply::Kind::Done);
  ASSERT_EQ(s.feed("let n = 2").kind, ReplReply::Kind::Done);
  ASSERT_EQ(s.feed("style hidden levels (n)  pen 2  # the hidden pen").kind, ReplReply::Kind::Done);
  ASSERT_EQ(s.feed(kCamera).kind, ReplReply::Kind::Done);
  const std::string before = s.script();
  ASSERT_EQ(s.feed(":levels 4").kind, ReplReply::Kind::Done);
  const std::string levels = s.script();
  EXPECT_NE(levels.find("style hidden levels 4 pen 2  # the hidden pen\n"), std::string::npos) << levels;
  EXPECT_EQ(levels.find("(n)"), std::string::npos) << levels;
  ASSERT_EQ(s.feed(":hidden on").kind, ReplReply::Kind::Done);
  EXPECT_NE(s.script().find("style hidden dashed pen 2  # the hidden pen\n"), std::string::npos)
      << s.script();
  ASSERT_EQ(s.feed(":undo").kind, ReplReply::Kind::Done);
  // Off drops the pen, which off does not take.
  ASSERT_EQ(s.feed(":hidden off").kind, ReplReply::Kind::Done);
  EXPECT_NE(s.script().find("style hidden off  # the hidden pen\n"), std::string::npos) << s.script();
  // Each :undo puts back the statement as it was before: levels with the pen, then the session's own.
  ASSERT_EQ(s.feed(":undo").kind, ReplReply::Kind::Done);
  EXPECT_EQ(s.script(), levels);
  ASSERT_EQ(s.feed(":undo").kind, ReplReply::Kind::Done);
  EXPECT_EQ(s.script(), before);

  // The saved script runs, with the levels' pens.
  const hlr::test::TempDir dir("repl-levels");
  ASSERT_EQ(s.feed(":levels 2").kind, ReplReply::Kind::Done);
  const fs::path saved = dir.path() / "saved.hls";
  ASSERT_EQ(s.feed(":save " + saved.string()).kind, ReplReply::Kind::Done);
  const std::string text = test::read_text(saved);
  EXPECT_NE(text.find("style hidden levels 2 pen 2"), std::string::npos) << text;
  const test::CliResult check = test::run({"check", saved.string()});
  EXPECT_EQ(check.code, 0) << check.err << text;
}

TEST(ReplLevels, RenderWritesLevels) {
  ReplSession s;
  ASSERT_EQ(s.feed("draw cube(1)").kind, ReplReply::Kind::Done);
  ASSERT_EQ(s.feed(kCamera).kind, ReplReply::Kind::Done);
  ASSERT_EQ(s.feed(":levels 2").kind, ReplReply::Kind::Done);
  const hlr::test::TempDir dir("repl-levels-render");
  const fs::path json = dir.path() / "out.json";
  const ReplReply r = s.feed(":render " + json.string());
  ASSERT_EQ(r.kind, ReplReply::Kind::Done) << r.text;
  const nlohmann::json frame = nlohmann::json::parse(test::read_text(json))["frames"][0];
  EXPECT_TRUE(frame.contains("hidden_stroke_levels"));
  // :show and :stats draw and plan with the levels too (and say so without failing).
  EXPECT_EQ(s.feed(":stats").kind, ReplReply::Kind::Done);
}

}  // namespace
}  // namespace hlr::runtime
