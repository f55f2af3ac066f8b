#include "core/device/formats/cairo_device.hpp"

#include <cairo/cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/device/page/atomic_file.hpp"
#include "core/device/page/page_layout.hpp"

namespace hlr {
namespace {

namespace fs = std::filesystem;

// --- helpers ----------------------------------------------------------------------------------------

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool have_tool(const std::string& name) {
  return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0;
}

// Runs a shell command; its standard output, or nullopt when it fails.
std::optional<std::string> run(const std::string& command) {
  FILE* pipe = ::popen((command + " 2>/dev/null").c_str(), "r");
  if (!pipe) return std::nullopt;
  std::string out;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
  if (::pclose(pipe) != 0) return std::nullopt;
  return out;
}

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

// The value after "key:" at the start of a line of pdfinfo's output.
std::string info_field(const std::string& info, const std::string& key) {
  std::istringstream lines(info);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(key + ":", 0) != 0) continue;
    const std::size_t value = line.find_first_not_of(" \t", key.size() + 1);
    return value == std::string::npos ? std::string() : line.substr(value);
  }
  return "<missing " + key + ">";
}

// pdfinfo -f/-l lines "Page    2 size: 612 x 792 pts (letter)": {width, height} of each page.
std::vector<std::pair<double, double>> page_sizes(const std::string& info) {
  std::vector<std::pair<double, double>> sizes;
  std::istringstream lines(info);
  for (std::string line; std::getline(lines, line);) {
    int page = 0;
    double w = 0, h = 0;
    if (std::sscanf(line.c_str(), "Page %d size: %lf x %lf pts", &page, &w, &h) == 3)
      sizes.emplace_back(w, h);
  }
  return sizes;
}

// The number in attribute `name`="…mm" of the <svg> element; NaN when it is not there in millimetres.
double svg_mm_attribute(const std::string& svg, const std::string& name) {
  const std::size_t element = svg.find("<svg ");
  const std::size_t at = svg.find(" " + name + "=\"", element);
  if (element == std::string::npos || at == std::string::npos || at > svg.find('>', element))
    return std::nan("");
  const std::size_t start = at + name.size() + 3, end = svg.find('"', start);
  const std::string value = svg.substr(start, end - start);
  if (value.size() < 3 || value.substr(value.size() - 2) != "mm") return std::nan("");
  return std::stod(value.substr(0, value.size() - 2));
}

struct Rgba {
  int r = 0, g = 0, b = 0, a = 0;
  bool dark() const { return a > 200 && r < 100 && g < 100 && b < 100; }
  bool white() const { return a > 250 && r > 240 && g > 240 && b > 240; }
  bool reddish() const { return a > 200 && r > 180 && g < 90 && b < 90; }
};

std::ostream& operator<<(std::ostream& os, const Rgba& c) {
  return os << "rgba(" << c.r << ", " << c.g << ", " << c.b << ", " << c.a << ")";
}

struct Image {
  int width = 0, height = 0;
  double px_per_mm = 10;
  std::vector<std::uint32_t> argb;  // premultiplied, row by row

  Rgba pixel(int x, int y) const {
    const std::uint32_t v = argb.at(static_cast<std::size_t>(y) * width + x);
    return {static_cast<int>((v >> 16) & 0xff), static_cast<int>((v >> 8) & 0xff), static_cast<int>(v & 0xff),
            static_cast<int>(v >> 24)};
  }
  // The pixel covering page point (x, y) mm.
  Rgba at_mm(double x, double y) const {
    return pixel(static_cast<int>(std::floor(x * px_per_mm)), static_cast<int>(std::floor(y * px_per_mm)));
  }
};

Image read_png(const fs::path& path, double px_per_mm) {
  Image image;
  image.px_per_mm = px_per_mm;
  cairo_surface_t* s = cairo_image_surface_create_from_png(path.c_str());
  if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
    ADD_FAILURE() << "cannot read " << path << ": " << cairo_status_to_string(cairo_surface_status(s));
    cairo_surface_destroy(s);
    return image;
  }
  const cairo_format_t format = cairo_image_surface_get_format(s);
  image.width = cairo_image_surface_get_width(s);
  image.height = cairo_image_surface_get_height(s);
  const int stride = cairo_image_surface_get_stride(s);
  const unsigned char* data = cairo_image_surface_get_data(s);
  for (int y = 0; y < image.height; ++y) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < image.width; ++x)
      image.argb.push_back(format == CAIRO_FORMAT_RGB24 ? row[x] | 0xff000000u : row[x]);
  }
  cairo_surface_destroy(s);
  return image;
}

PlotStroke line(Point2 a, Point2 b, int pen = 1, StrokeLayer layer = StrokeLayer::Visible) {
  PlotStroke s;
  s.points = {a, b};
  s.pen = pen;
  s.layer = layer;
  return s;
}

// 100 × 50 mm, 5 mm margins; at 254 dpi it is 1000 × 500 pixels, 10 per mm.
//   y = 10: pen 1 from x = 10 to 90;  y = 20: pen 2 (red);  y = 30: pen 1 hidden (dashed);
//   y = 35: pen 4 from x = 10 to far off the page (clipped); border (5, 5)–(95, 40); caption below.
PlotPage test_page() {
  PlotPage page;
  page.width_mm = 100;
  page.height_mm = 50;
  page.margin_mm = 5;
  page.strokes = {line({10, 10}, {90, 10}), line({10, 20}, {90, 20}, 2),
                  line({10, 30}, {90, 30}, 1, StrokeLayer::Hidden), line({10, 35}, {1e12, 35}, 4),
                  line({-1e12, -1e12}, {-1e12 + 5, -1e12}, 3)};
  page.border = Rect2{5, 5, 95, 40};
  page.caption = "test caption";
  return page;
}

// Checks the pixels of test_page() rendered at 10 pixels per mm, whichever device drew them.
void expect_test_page_pixels(const Image& im, bool decorations = true) {
  ASSERT_NEAR(im.width, 1000, 1);  // poppler rounds up
  ASSERT_NEAR(im.height, 500, 1);
  for (double x = 12; x <= 88; x += 0.5) {
    EXPECT_TRUE(im.at_mm(x, 10).dark()) << "pen 1 at x = " << x << ": " << im.at_mm(x, 10);
    EXPECT_TRUE(im.at_mm(x, 13).white()) << "3 mm off the stroke at x = " << x << ": " << im.at_mm(x, 13);
    EXPECT_TRUE(im.at_mm(x, 7).white()) << "3 mm off the stroke at x = " << x << ": " << im.at_mm(x, 7);
    EXPECT_TRUE(im.at_mm(x, 20).reddish()) << "pen 2 at x = " << x << ": " << im.at_mm(x, 20);
    const Rgba blue = im.at_mm(x, 35);
    EXPECT_TRUE(blue.b > 180 && blue.r < 90 && blue.g < 90) << "pen 4 at x = " << x << ": " << blue;
  }
  EXPECT_TRUE(im.at_mm(7, 10).white()) << "left of the stroke";
  EXPECT_TRUE(im.at_mm(8.5, 10).white()) << "left of the stroke's cap";
  // The clipped stroke runs to the page edge.
  EXPECT_TRUE(im.at_mm(99.9, 35).b > 180) << im.at_mm(99.9, 35);
  // The hidden stroke: 2 mm dashes, 1.2 mm gaps.
  int dark = 0, white = 0, runs = 0;
  bool was_dark = false;
  for (int x = 150; x < 850; ++x) {
    const Rgba c = im.pixel(x, 300);
    dark += c.dark();
    white += c.white();
    if (c.dark() && !was_dark) ++runs;
    was_dark = c.dark();
  }
  EXPECT_GT(white, 700 * 0.25) << "gaps";
  EXPECT_GT(dark, 700 * 0.5) << "dashes";
  EXPECT_NEAR(runs, 70 / 3.2, 2) << "one dash per 3.2 mm";
  // Border: grey, thin.
  const Rgba border = im.at_mm(5, 25);
  if (decorations) {
    EXPECT_FALSE(border.white()) << border;
    EXPECT_NEAR(border.r, border.b, 2) << "grey: " << border;
    EXPECT_NEAR(border.r, border.g, 2) << "grey: " << border;
  } else {
    EXPECT_TRUE(border.white()) << border;
  }
  // Caption in the bottom margin (below the border, baseline 3 mm above the page edge).
  int ink = 0;
  for (int y = 420; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) ink += !im.pixel(x, y).white();
  if (decorations)
    EXPECT_GT(ink, 100) << "caption";
  else
    EXPECT_EQ(ink, 0) << "no caption";
}

class CairoDevice : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("hlr-cairo-test-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static CairoOptions options(CairoFormat format) {
    CairoOptions o;
    o.format = format;
    o.dpi = 254;
    return o;
  }
  // write_cairo must throw DeviceError mentioning `needle` and leave the directory empty.
  void expect_error(const fs::path& target, const std::vector<PlotPage>& pages, const CairoOptions& o,
                    const std::string& needle) {
    try {
      write_cairo(target, pages, o);
      ADD_FAILURE() << "no error writing " << target;
    } catch (const DeviceError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::is_empty(dir_)) << "a file was left behind for " << target;
  }

  fs::path dir_;
};

// --- PDF --------------------------------------------------------------------------------------------

TEST_F(CairoDevice, PdfPagesSizesAndMetadata) {
  ASSERT_TRUE(have_tool("pdfinfo")) << "pdfinfo (poppler-utils) is not installed: run scripts/setup.sh";
  PlotPage a4 = test_page(), letter = test_page(), small = test_page();
  a4.width_mm = 297;
  a4.height_mm = 210;
  letter.width_mm = 215.9;
  letter.height_mm = 279.4;
  small.strokes.clear();
  CairoOptions o = options(CairoFormat::Pdf);
  o.title = "Gears, frame 3";
  const fs::path target = dir_ / "out.pdf";
  write_cairo(target, {a4, letter, small}, o);
  const auto info = run("pdfinfo -f 1 -l 3 " + quoted(target));
  ASSERT_TRUE(info) << "pdfinfo failed";
  EXPECT_EQ(info_field(*info, "Pages"), "3");
  EXPECT_EQ(info_field(*info, "Title"), "Gears, frame 3");
  EXPECT_EQ(info_field(*info, "Creator"), "hlrscript");
  const double expected[3][2] = {{297, 210}, {215.9, 279.4}, {100, 50}};
  const auto sizes = page_sizes(*info);
  ASSERT_EQ(sizes.size(), 3u) << *info;
  for (std::size_t page = 0; page < 3; ++page) {
    EXPECT_NEAR(sizes[page].first, expected[page][0] * 72 / 25.4, 0.01) << "page " << page + 1;
    EXPECT_NEAR(sizes[page].second, expected[page][1] * 72 / 25.4, 0.01) << "page " << page + 1;
  }
}

TEST_F(CairoDevice, PdfWithoutTitleHasCreatorOnly) {
  ASSERT_TRUE(have_tool("pdfinfo")) << "pdfinfo (poppler-utils) is not installed: run scripts/setup.sh";
  const fs::path target = dir_ / "plain.pdf";
  write_cairo(target, {test_page()}, options(CairoFormat::Pdf));
  const auto info = run("pdfinfo " + quoted(target));
  ASSERT_TRUE(info);
  EXPECT_EQ(info_field(*info, "Pages"), "1");
  EXPECT_EQ(info_field(*info, "Creator"), "hlrscript");
  EXPECT_EQ(info->find("Title:"), std::string::npos) << *info;
}

// Rasterised by poppler, the PDF has its strokes at the same millimetres as the PNG device.
TEST_F(CairoDevice, PdfStrokesWhereThePageSays) {
  ASSERT_TRUE(have_tool("pdftoppm")) << "pdftoppm (poppler-utils) is not installed: run scripts/setup.sh";
  const fs::path target = dir_ / "page.pdf";
  write_cairo(target, {test_page()}, options(CairoFormat::Pdf));
  ASSERT_TRUE(run("pdftoppm -r 254 -png -singlefile " + quoted(target) + " " + quoted(dir_ / "raster")));
  expect_test_page_pixels(read_png(dir_ / "raster.png", 10));
}

// --- SVG --------------------------------------------------------------------------------------------

TEST_F(CairoDevice, SvgIsSizedInMillimetresAndParses) {
  PlotPage page = test_page();
  page.width_mm = 215.9;
  page.height_mm = 279.4;
  const fs::path target = dir_ / "letter.svg";
  write_cairo(target, {page}, options(CairoFormat::Svg));
  const std::string svg = slurp(target);
  EXPECT_NEAR(svg_mm_attribute(svg, "width"), 215.9, 1e-3) << svg.substr(0, 400);
  EXPECT_NEAR(svg_mm_attribute(svg, "height"), 279.4, 1e-3) << svg.substr(0, 400);
  ASSERT_TRUE(have_tool("rsvg-convert"))
      << "rsvg-convert (librsvg2-bin) is not installed: run scripts/setup.sh";
  ASSERT_TRUE(run("rsvg-convert -o " + quoted(dir_ / "letter.png") + " " + quoted(target)))
      << "rsvg-convert failed";
  const Image im = read_png(dir_ / "letter.png", 96 / 25.4);
  EXPECT_NEAR(im.width, 215.9 / 25.4 * 96, 1);
  EXPECT_NEAR(im.height, 279.4 / 25.4 * 96, 1);
}

TEST_F(CairoDevice, SvgStrokesWhereThePageSays) {
  ASSERT_TRUE(have_tool("rsvg-convert"))
      << "rsvg-convert (librsvg2-bin) is not installed: run scripts/setup.sh";
  const fs::path target = dir_ / "page.svg";
  write_cairo(target, {test_page()}, options(CairoFormat::Svg));
  const fs::path png = dir_ / "page.png";
  ASSERT_TRUE(run("rsvg-convert --dpi-x 254 --dpi-y 254 -b white -o " + quoted(png) + " " + quoted(target)));
  expect_test_page_pixels(read_png(png, 10));
}

// --- PNG --------------------------------------------------------------------------------------------

TEST_F(CairoDevice, PngPixelsWhereThePageSays) {
  const fs::path target = dir_ / "page.png";
  write_cairo(target, {test_page()}, options(CairoFormat::Png));
  expect_test_page_pixels(read_png(target, 10));
}

TEST_F(CairoDevice, PngWithoutDecorations) {
  const fs::path target = dir_ / "bare.png";
  CairoOptions o = options(CairoFormat::Png);
  o.decorations = false;
  write_cairo(target, {test_page()}, o);
  expect_test_page_pixels(read_png(target, 10), false);
}

TEST_F(CairoDevice, PngSizeFollowsDpi) {
  PlotPage page = test_page();
  page.width_mm = 254;
  page.height_mm = 127;
  CairoOptions o = options(CairoFormat::Png);
  o.dpi = 100;
  write_cairo(dir_ / "a.png", {page}, o);
  const Image a = read_png(dir_ / "a.png", 100 / 25.4);
  EXPECT_EQ(a.width, 1000);
  EXPECT_EQ(a.height, 500);
  // A4 landscape at the default 150 dpi: 1753.9 × 1240.2 rounds to 1754 × 1240.
  PlotPage a4 = test_page();
  a4.width_mm = 297;
  a4.height_mm = 210;
  o.dpi = CairoOptions{}.dpi;
  write_cairo(dir_ / "b.png", {a4}, o);
  const Image b = read_png(dir_ / "b.png", 150 / 25.4);
  EXPECT_EQ(b.width, 1754);
  EXPECT_EQ(b.height, 1240);
  const PixelSize size = png_pixel_size(a4, 150);
  EXPECT_EQ(size.width, 1754);
  EXPECT_EQ(size.height, 1240);
  // A tiny page is never zero pixels.
  page.width_mm = page.height_mm = 0.01;
  page.margin_mm = 0;
  EXPECT_EQ(png_pixel_size(page, 1).width, 1);
}

TEST_F(CairoDevice, PngTransparentBackground) {
  const fs::path target = dir_ / "clear.png";
  CairoOptions o = options(CairoFormat::Png);
  o.white_background = false;
  write_cairo(target, {test_page()}, o);
  const Image im = read_png(target, 10);
  EXPECT_EQ(im.at_mm(50, 13).a, 0) << "background";
  const Rgba ink = im.at_mm(50, 10);
  EXPECT_EQ(ink.a, 255);
  EXPECT_TRUE(ink.dark()) << ink;
}

TEST_F(CairoDevice, PenTableColoursAndWidths) {
  PlotPage page = test_page();
  page.strokes = {line({10, 25}, {90, 25}, 3), line({10, 10}, {90, 10}, 7)};
  CairoOptions o = options(CairoFormat::Png);
  o.pens.set(3, {0, 0, 0, 2.0});  // 2 mm black
  write_cairo(dir_ / "wide.png", {page}, o);
  const Image im = read_png(dir_ / "wide.png", 10);
  EXPECT_TRUE(im.at_mm(50, 24.2).dark()) << im.at_mm(50, 24.2);
  EXPECT_TRUE(im.at_mm(50, 25.7).dark()) << im.at_mm(50, 25.7);
  EXPECT_TRUE(im.at_mm(50, 26.5).white()) << im.at_mm(50, 26.5);
  // Pen 7 is the darkened carousel yellow: clearly coloured, not white, not pure yellow.
  const Rgba amber = im.at_mm(50, 10);
  EXPECT_GT(amber.r, 150) << amber;
  EXPECT_LT(amber.b, 60) << amber;
  EXPECT_LT(amber.g, 200) << amber;
  // The default width, set wider: the same pen 7 stroke now covers 1.5 mm either side.
  CairoOptions wide = options(CairoFormat::Png);
  wide.pens.set_default_width(3);
  write_cairo(dir_ / "wider.png", {page}, wide);
  const Image w = read_png(dir_ / "wider.png", 10);
  EXPECT_FALSE(w.at_mm(50, 11.2).white()) << w.at_mm(50, 11.2);
  EXPECT_TRUE(im.at_mm(50, 11.2).white()) << "the default 0.25 mm stroke does not reach there";
}

// Captions that are not UTF-8 do not fail the file; a dot (a one-point stroke) is drawn.
TEST_F(CairoDevice, OddInputsStillDraw) {
  PlotPage page = test_page();
  page.caption = "bad \xff\xfe bytes \xc3\xa9 \xed\xa0\x80 end \xc3";
  PlotStroke dot;
  dot.points = {{50, 45}};
  page.strokes.push_back(dot);
  page.strokes.push_back(PlotStroke{});  // no points: nothing
  page.border = Rect2::none();           // empty border: not drawn
  for (const CairoFormat f : {CairoFormat::Pdf, CairoFormat::Svg, CairoFormat::Png}) {
    const fs::path target = dir_ / (std::string("odd") + std::to_string(static_cast<int>(f)));
    EXPECT_NO_THROW(write_cairo(target, {page}, options(f))) << static_cast<int>(f);
    EXPECT_TRUE(fs::exists(target));
  }
  const Image im = read_png(dir_ / "odd2", 10);
  EXPECT_TRUE(im.at_mm(50, 45).dark()) << im.at_mm(50, 45);
}

// A page with no strokes is a blank page of the right size.
TEST_F(CairoDevice, EmptyPage) {
  PlotPage page;
  write_cairo(dir_ / "blank.png", {page}, options(CairoFormat::Png));
  const Image im = read_png(dir_ / "blank.png", 10);
  EXPECT_EQ(im.width, 2970);
  EXPECT_EQ(im.height, 2100);
  for (int y = 0; y < im.height; y += 37)
    for (int x = 0; x < im.width; x += 41) ASSERT_TRUE(im.pixel(x, y).white()) << x << ", " << y;
}

// --- errors -----------------------------------------------------------------------------------------

TEST_F(CairoDevice, SvgAndPngHoldOnePage) {
  for (const CairoFormat f : {CairoFormat::Svg, CairoFormat::Png})
    expect_error(dir_ / "many", {test_page(), test_page()}, options(f), "{frame}");
}

TEST_F(CairoDevice, NoPagesIsAnError) {
  for (const CairoFormat f : {CairoFormat::Pdf, CairoFormat::Svg, CairoFormat::Png})
    expect_error(dir_ / "none", {}, options(f), "no pages");
}

TEST_F(CairoDevice, TooManyPixelsNamesTheDpi) {
  CairoOptions o = options(CairoFormat::Png);
  o.dpi = 100000;
  expect_error(dir_ / "huge.png", {test_page()}, o, "dpi");
  // 100 megapixels: an A0 sheet at 300 dpi is 9933 × 14043 = 139 megapixels.
  PlotPage a0 = test_page();
  a0.width_mm = 841;
  a0.height_mm = 1189;
  o.dpi = 300;
  expect_error(dir_ / "a0.png", {a0}, o, "megapixels");
  // One side over 32767 pixels with a small area.
  PlotPage strip = test_page();
  strip.width_mm = 9000;
  strip.height_mm = 20;
  strip.margin_mm = 1;
  o.dpi = 100;
  expect_error(dir_ / "strip.png", {strip}, o, "32767");
  for (const double bad :
       {0.0, -5.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    o.dpi = bad;
    expect_error(dir_ / "bad.png", {test_page()}, o, "dpi");
  }
  // The dpi does not matter to PDF or SVG.
  CairoOptions pdf = options(CairoFormat::Pdf);
  pdf.dpi = -1;
  EXPECT_NO_THROW(write_cairo(dir_ / "fine.pdf", {test_page()}, pdf));
}

TEST_F(CairoDevice, SuggestedDpiWorks) {
  PlotPage a0 = test_page();
  a0.width_mm = 841;
  a0.height_mm = 1189;
  try {
    (void)png_pixel_size(a0, 300);
    FAIL() << "no error";
  } catch (const DeviceError& e) {
    const std::string what = e.what();
    const std::size_t at = what.rfind("at most ");
    ASSERT_NE(at, std::string::npos) << what;
    const double suggested = std::stod(what.substr(at + 8));
    EXPECT_GT(suggested, 200) << what;
    const PixelSize size = png_pixel_size(a0, suggested);
    EXPECT_LE(size.width * size.height, 100e6);
  }
}

TEST_F(CairoDevice, MissingDirectory) {
  for (const CairoFormat f : {CairoFormat::Pdf, CairoFormat::Svg, CairoFormat::Png})
    expect_error(dir_ / "missing" / "out", {test_page()}, options(f), "does not exist");
}

TEST_F(CairoDevice, BadPages) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Bad {
    double w, h, margin;
    const char* needle;
  };
  for (const Bad& b : {Bad{0, 50, 0, "paper"}, Bad{nan, 50, 5, "paper"}, Bad{20000, 50, 5, "too large"},
                       Bad{100, 50, 25, "margin"}, Bad{100, -50, 5, "paper"}}) {
    PlotPage page = test_page();
    page.width_mm = b.w;
    page.height_mm = b.h;
    page.margin_mm = b.margin;
    for (const CairoFormat f : {CairoFormat::Pdf, CairoFormat::Svg, CairoFormat::Png})
      expect_error(dir_ / "bad", {page}, options(f), b.needle);
    // In a PDF the error names the page.
    expect_error(dir_ / "bad.pdf", {test_page(), page}, options(CairoFormat::Pdf), "page 2: ");
  }
  PlotPage page = test_page();
  page.strokes[1].points[1].x = nan;
  for (const CairoFormat f : {CairoFormat::Pdf, CairoFormat::Svg, CairoFormat::Png})
    expect_error(dir_ / "nan", {page}, options(f), "stroke 2 has a non-finite point");
}

// A failed write leaves the file that was there untouched.
TEST_F(CairoDevice, FailureKeepsTheOldFile) {
  const fs::path target = dir_ / "keep.png";
  write_cairo(target, {test_page()}, options(CairoFormat::Png));
  const std::string before = slurp(target);
  CairoOptions o = options(CairoFormat::Png);
  o.dpi = 1e6;
  EXPECT_THROW(write_cairo(target, {test_page()}, o), DeviceError);
  EXPECT_EQ(slurp(target), before);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

// The target is a directory: cairo (or the rename) fails, and nothing is left beside it.
TEST_F(CairoDevice, TargetIsADirectory) {
  for (const CairoFormat f : {CairoFormat::Pdf, CairoFormat::Svg, CairoFormat::Png}) {
    const fs::path target = dir_ / "taken";
    fs::create_directories(target / "inside");
    EXPECT_THROW(write_cairo(target, {test_page()}, options(f)), DeviceError);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
    EXPECT_TRUE(fs::is_directory(target / "inside"));
  }
}

TEST(CairoFormatFor, Extensions) {
  EXPECT_EQ(cairo_format_for("a.pdf"), CairoFormat::Pdf);
  EXPECT_EQ(cairo_format_for("dir.x/a.PDF"), CairoFormat::Pdf);
  EXPECT_EQ(cairo_format_for("frame-001.svg"), CairoFormat::Svg);
  EXPECT_EQ(cairo_format_for("x.Png"), CairoFormat::Png);
  for (const char* other : {"a.hpgl", "a.json", "pdf", "a.pdf.gz", "a.", "", ".png/x"})
    EXPECT_FALSE(cairo_format_for(other)) << other;
}

}  // namespace
}  // namespace hlr
