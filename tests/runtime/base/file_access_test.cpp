// FileAccess (runtime/base/file_access.hpp): which files a script may read and write. The end-to-end escape
// routes are in tests/e2e/confinement.sh; here the path logic on its own.
#include "runtime/base/file_access.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace hlr::runtime {
namespace {

namespace fs = std::filesystem;

TEST(FileAccess, BelowComparesWholeComponents) {
  EXPECT_TRUE(is_below("/work/a", "/work/a"));
  EXPECT_TRUE(is_below("/work/a/b/c.hls", "/work/a"));
  EXPECT_TRUE(is_below("/work/a/b/c.hls", "/work/a/"));
  EXPECT_FALSE(is_below("/work/ab/c.hls", "/work/a"));  // a sibling that shares a prefix
  EXPECT_FALSE(is_below("/work", "/work/a"));
  EXPECT_TRUE(is_below("/anything", "/"));
}

class FileAccessTree : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("hlr-access-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(root_);
    fs::create_directories(root_ / "project" / "sub");
    fs::create_directories(root_ / "project-two");
    fs::create_directories(root_ / "other");
    std::ofstream(root_ / "other" / "x.hls") << "let x = 1\n";
    fs::create_directory_symlink(root_ / "other", root_ / "project" / "link");
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path root_;
};

TEST_F(FileAccessTree, ReadsBelowTheScriptsFolderOnly) {
  const FileAccess access(root_ / "project", {});
  EXPECT_EQ(access.read_refusal(root_ / "project" / "sub" / "a.hls", "sub/a.hls"), std::nullopt);
  EXPECT_EQ(access.read_refusal(root_ / "project" / "sub" / ".." / "a.hls", "sub/../a.hls"), std::nullopt);
  const auto parent = access.read_refusal(root_ / "project" / ".." / "other" / "x.hls", "../other/x.hls");
  ASSERT_TRUE(parent.has_value());
  EXPECT_NE(parent->find("'../other/x.hls': it is outside"), std::string::npos) << *parent;
  EXPECT_TRUE(access.read_refusal(root_ / "project" / "link" / "x.hls", "link/x.hls").has_value());
  EXPECT_TRUE(access.read_refusal(root_ / "project-two" / "x.hls", "x").has_value());  // a prefix sibling
  EXPECT_TRUE(access.read_refusal("/etc/hostname", "/etc/hostname").has_value());
  EXPECT_NE(access.allow_hint(root_ / "project" / "link" / "x.hls")
                .find("--allow-path " + (root_ / "other").string()),
            std::string::npos);
}

TEST_F(FileAccessTree, AllowPathOpensTheNamedFolderThroughLinksToo) {
  AccessOptions options;
  options.allow_paths.push_back(root_ / "other");
  const FileAccess access(root_ / "project", options);
  EXPECT_EQ(access.read_refusal(root_ / "project" / "link" / "x.hls", "link/x.hls"), std::nullopt);
  EXPECT_EQ(access.read_refusal(root_ / "other" / "x.hls", "x"), std::nullopt);
  EXPECT_TRUE(access.read_refusal(root_ / "project-two" / "x.hls", "x").has_value());
}

TEST_F(FileAccessTree, ScriptOutputsStayBelowTheOutputFolder) {
  AccessOptions options;
  options.out_dir = root_ / "project" / "sub";
  const FileAccess access(root_ / "project", options);
  EXPECT_EQ(access.output_path("a.svg"), root_ / "project" / "sub" / "a.svg");
  EXPECT_EQ(access.write_refusal(access.output_path("deeper/a.svg"), "deeper/a.svg"), std::nullopt);
  EXPECT_TRUE(access.write_refusal(access.output_path("../a.svg"), "../a.svg").has_value());
  EXPECT_TRUE(access.write_refusal(access.output_path("../link/a.svg"), "../link/a.svg").has_value());
  EXPECT_TRUE(access.write_refusal("/tmp/a.svg", "/tmp/a.svg").has_value());
}

}  // namespace
}  // namespace hlr::runtime
