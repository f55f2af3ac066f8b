#include "core/device/pdf_device.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/device/atomic_file.hpp"

namespace hlr {
namespace {

namespace fs = std::filesystem;

class PdfDevice : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("hlr-pdf-test-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  static std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  static std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
  }
  static std::vector<DrawingPage> pages() {
    VisibleSegment visible, hidden;
    visible.s0 = {-0.5, -0.5};
    visible.s1 = {0.5, 0.5};
    hidden.s0 = {-0.5, 0.5};
    hidden.s1 = {0.5, -0.5};
    hidden.hidden = true;
    return {{{visible, hidden}, Rect2{-1, -1, 1, 1}, "framed"},
            {{visible}, std::nullopt, ""},
            {{}, std::nullopt, ""}};
  }
  fs::path dir_;
};

// One page per drawing (an empty one included), each the requested size in points.
TEST_F(PdfDevice, PagesAndPaperSize) {
  const fs::path target = dir_ / "out.pdf";
  PdfOptions o;
  const Paper letter = *paper_by_name("Letter");
  o.page_width_mm = letter.width_mm;
  o.page_height_mm = letter.height_mm;
  write_pdf(target, pages(), o);
  const std::string pdf = slurp(target);
  EXPECT_EQ(pdf.rfind("%PDF-", 0), 0u);
  EXPECT_NE(pdf.find("%%EOF"), std::string::npos);
  EXPECT_EQ(count(pdf, "/Type /Page\n") + count(pdf, "/Type /Page "), 3u) << "pages";
  EXPECT_EQ(count(pdf, "/MediaBox [ 0 0 612 792 ]"), 3u);  // 8.5 × 11 in
  EXPECT_EQ(o.page_spec().paper.width_mm, letter.width_mm);
  EXPECT_EQ(o.page_spec().margin_mm, 12);
}

TEST_F(PdfDevice, DefaultIsA4Landscape) {
  const fs::path target = dir_ / "a4.pdf";
  write_pdf(target, pages());
  EXPECT_EQ(count(slurp(target), "/MediaBox [ 0 0 841.889764 595.275591 ]"), 3u);
}

TEST_F(PdfDevice, BadMarginOrMissingDirectoryLeavesNothing) {
  PdfOptions o;
  o.margin_mm = 120;
  EXPECT_THROW(write_pdf(dir_ / "bad.pdf", pages(), o), DeviceError);
  EXPECT_THROW(write_pdf(dir_ / "missing" / "x.pdf", pages()), DeviceError);
  EXPECT_TRUE(fs::is_empty(dir_));
}

}  // namespace
}  // namespace hlr
