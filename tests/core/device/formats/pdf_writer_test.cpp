// The PDF writer, read back by poppler: metadata in any script, captions, pages in order, the same bytes
// for the same pages and date, and the errors. (Strokes at the right millimetres: cairo_device_test's
// PdfStrokesWhereThePageSays rasterises it against the PNG device.)
#include "core/device/formats/pdf_writer.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "core/device/page/atomic_file.hpp"
#include "tests/support/temp_dir.hpp"

namespace hlr {
namespace {

namespace fs = std::filesystem;

std::string output_of(const std::string& command) {
  std::string out;
  FILE* p = ::popen((command + " 2>&1").c_str(), "r");
  if (!p) return out;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  EXPECT_EQ(::pclose(p), 0) << command << ": " << out;
  return out;
}

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

PlotPage page_with(std::string caption) {
  PlotPage page;
  page.width_mm = 210;
  page.height_mm = 148;
  page.margin_mm = 10;
  page.border = Rect2{10, 10, 200, 130};
  page.strokes.push_back({{{20, 20}, {190, 20}, {190, 120}}, 1, StrokeLayer::Visible});
  page.strokes.push_back({{{20, 120}, {100, 70}}, 2, StrokeLayer::Hidden});
  page.strokes.push_back({{{50, 50}}, 1, StrokeLayer::Visible});  // a dot
  page.caption = std::move(caption);
  return page;
}

class PdfWriterTest : public ::testing::Test {
 protected:
  const test::TempDir scratch_{std::string("pdf-writer-") +
                               ::testing::UnitTest::GetInstance()->current_test_info()->name()};
  const fs::path dir_ = scratch_.path();
};

TEST_F(PdfWriterTest, MetadataInAnyScriptAndAFixedDate) {
  PdfOptions o;
  o.title = "Zahnräder – Ansicht 3 ✓";
  o.creation_date = "2023-11-14T22:13:20Z";
  const fs::path target = dir_ / "meta.pdf";
  write_pdf(target, {page_with("")}, o);
  const std::string info = output_of("pdfinfo '" + target.string() + "'");
  EXPECT_NE(info.find("Title:           Zahnräder – Ansicht 3 ✓\n"), std::string::npos) << info;
  EXPECT_NE(info.find("Creator:         hlrscript\n"), std::string::npos) << info;
  EXPECT_NE(info.find("CreationDate:    Tue Nov 14 22:13:20 2023 UTC"), std::string::npos) << info;
  EXPECT_NE(info.find("Page size:       595.276 x 419.528 pts"), std::string::npos) << info;
  // The same pages, options and date: the same bytes.
  write_pdf(dir_ / "again.pdf", {page_with("")}, o);
  EXPECT_EQ(bytes_of(target), bytes_of(dir_ / "again.pdf"));
}

TEST_F(PdfWriterTest, CaptionsReadBackPageByPage) {
  const fs::path target = dir_ / "pages.pdf";
  std::vector<PlotPage> pages;
  for (int k = 0; k < 40; ++k) pages.push_back(page_with("Seite " + std::to_string(k) + " (größer) \\ fin"));
  write_pdf(target, pages, {});
  const std::string info = output_of("pdfinfo '" + target.string() + "'");
  EXPECT_NE(info.find("Pages:           40\n"), std::string::npos) << info;
  const std::string text = output_of("pdftotext -layout '" + target.string() + "' -");
  std::size_t last = 0;
  for (int k = 0; k < 40; ++k) {
    const std::size_t at = text.find("Seite " + std::to_string(k) + " (größer) \\ fin");
    ASSERT_NE(at, std::string::npos) << k << ":\n" << text.substr(0, 400);
    if (k > 0) {
      EXPECT_GT(at, last) << k;
    }
    last = at;
  }
}

TEST_F(PdfWriterTest, WithoutDecorationsThereIsNoText) {
  PdfOptions o;
  o.decorations = false;
  const fs::path target = dir_ / "plain.pdf";
  write_pdf(target, {page_with("not printed")}, o);
  EXPECT_EQ(output_of("pdftotext '" + target.string() + "' -").find("not printed"), std::string::npos);
}

// A page of many strokes (about 1 MB of operators) is written as several content streams, compressed apart:
// each ends at a line end, they read back in order as every point of every stroke, the page lists them
// all, poppler draws it, and the bytes are the same from run to run.
TEST_F(PdfWriterTest, ALargePageIsSeveralContentStreamsReadInOrder) {
  PlotPage page = page_with("");
  page.strokes.clear();
  std::size_t points = 0;
  for (int i = 0; i < 20000; ++i) {  // zigzags across the drawing area, no two alike
    const double y = 11 + 0.0059 * i, x = 11 + (i % 97) * 1.9;
    page.strokes.push_back({{{x, y}, {x + 0.7, y + 0.3}, {x + 1.3, y}}, 1, StrokeLayer::Visible});
    points += 3;
  }
  const fs::path target = dir_ / "large.pdf";
  PdfOptions o;
  o.creation_date = "2026-12-07T03:00:00Z";  // the same bytes need the same date
  write_pdf(target, {page}, o);
  const std::string file = bytes_of(target);
  std::string text;  // the content streams, inflated and joined in file order
  std::size_t streams = 0;
  for (std::size_t at = file.find("stream\n"); at != std::string::npos; at = file.find("stream\n", at)) {
    const std::size_t begin = at + 7, end = file.find("\nendstream", begin);
    ASSERT_NE(end, std::string::npos);
    std::string part(4u << 20, '\0');
    uLongf size = part.size();
    ASSERT_EQ(uncompress(reinterpret_cast<Bytef*>(part.data()), &size,
                         reinterpret_cast<const Bytef*>(file.data() + begin), end - begin),
              Z_OK);
    part.resize(size);
    ASSERT_FALSE(part.empty());
    EXPECT_EQ(part.back(), '\n') << "stream " << streams + 1;
    text += part;
    ++streams;
    at = end + std::string_view("\nendstream").size();
  }
  EXPECT_GE(streams, 3u);
  EXPECT_NE(file.find("/Contents [5 0 R 6 0 R 7 0 R"), std::string::npos);
  std::size_t moves = 0, lines = 0;
  std::vector<Point2> read;  // the path's points in the order written (millimetres, three decimals)
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const bool move = line.size() > 2 && line.ends_with(" m"), to = line.size() > 2 && line.ends_with(" l");
    moves += move;
    lines += to;
    if (move || to) {
      std::istringstream numbers(line);
      Point2 p;
      numbers >> p.x >> p.y;
      read.push_back(p);
    }
  }
  EXPECT_EQ(moves, page.strokes.size());
  EXPECT_EQ(moves + lines, points);
  // Written in parts side by side (long runs of strokes), the points still come stroke by stroke in order.
  std::size_t k = 0;
  for (const PlotStroke& stroke : page.strokes)
    for (const Point2& p : stroke.points) {
      ASSERT_LT(k, read.size());
      ASSERT_NEAR(read[k].x, p.x, 6e-4) << "point " << k;  // half a thousandth, and rounding
      ASSERT_NEAR(read[k].y, p.y, 6e-4) << "point " << k;
      ++k;
    }
  const std::string info = output_of("pdftoppm -r 20 -png -singlefile '" + target.string() + "' '" +
                                     (dir_ / "large").string() + "'");
  EXPECT_TRUE(fs::exists(dir_ / "large.png")) << info;
  write_pdf(dir_ / "again.pdf", {page}, o);
  EXPECT_EQ(file, bytes_of(dir_ / "again.pdf"));
}

TEST_F(PdfWriterTest, BadPagesAreRefusedAndNothingIsWritten) {
  PlotPage bad = page_with("");
  bad.strokes[0].points[1].x = std::nan("");
  const fs::path target = dir_ / "bad.pdf";
  try {
    write_pdf(target, {page_with(""), bad}, {});
    FAIL();
  } catch (const DeviceError& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot write '" + target.string() + "': page 2: stroke 1 has a non-finite point");
  }
  EXPECT_THROW(write_pdf(target, {}, {}), DeviceError);
  PlotPage roomless = page_with("");
  roomless.margin_mm = 80;
  EXPECT_THROW(write_pdf(target, {roomless}, {}), DeviceError);
  EXPECT_TRUE(fs::is_empty(dir_));
}

}  // namespace
}  // namespace hlr
