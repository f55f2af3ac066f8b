#include "core/device/page/page_layout.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/device/page/atomic_file.hpp"

namespace hlr {
namespace {

constexpr PageSpec kA4Landscape{{297, 210}, 12};

VisibleSegment piece(Point2 a, Point2 b) {
  VisibleSegment s;
  s.s0 = a;
  s.s1 = b;
  return s;
}

void expect_point(Point2 got, Point2 want, double tolerance = 1e-12) {
  EXPECT_NEAR(got.x, want.x, tolerance);
  EXPECT_NEAR(got.y, want.y, tolerance);
}

// Frame [−1, 1]² on 297 × 210 mm less 12 mm margins: room 273 × 186, so the height limits the scale to
// 186 / 2 = 93 mm per unit; the centre (0, 0) lands on the page centre (148.5, 105) and y flips.
TEST(PageLayout, FrameOnA4LandscapeByHand) {
  const PageLayout l = fit_to_page(Rect2{-1, -1, 1, 1}, {}, kA4Landscape);
  EXPECT_EQ(l.page_width_mm, 297);
  EXPECT_EQ(l.page_height_mm, 210);
  EXPECT_DOUBLE_EQ(l.scale, 93);
  expect_point(l.origin(), {148.5, 105});
  expect_point(l.to_page_mm({0, 0}), {148.5, 105});
  expect_point(l.to_page_mm({-1, 1}), {55.5, 12});    // picture top-left → page top margin
  expect_point(l.to_page_mm({1, -1}), {241.5, 198});  // picture bottom-right → page bottom margin
  expect_point(l.to_page_mm({1, 1}), {241.5, 12});
  expect_point(l.to_page_mm({-1, -1}), {55.5, 198});
  expect_point(l.to_page_mm({0.5, 0.25}), {195, 81.75});
  expect_point(l.to_page_mm({-0.2, -0.6}), {129.9, 160.8});
}

TEST(PageLayout, FrameWinsOverSegments) {
  const std::vector<VisibleSegment> segments{piece({-50, -50}, {50, 50})};
  const PageLayout l = fit_to_page(Rect2{-1, -1, 1, 1}, segments, kA4Landscape);
  EXPECT_DOUBLE_EQ(l.scale, 93);
}

// Without a frame the pieces' bounds [2, 6] × [1, 2] are fitted: the width limits (273 / 4 = 68.25).
TEST(PageLayout, SegmentBoundsWithoutFrame) {
  const std::vector<VisibleSegment> segments{piece({2, 1}, {3, 2}), piece({6, 1.5}, {4, 1.2})};
  const PageLayout l = fit_to_page(std::nullopt, segments, kA4Landscape);
  EXPECT_DOUBLE_EQ(l.scale, 68.25);
  expect_point(l.to_page_mm({4, 1.5}), {148.5, 105});
  expect_point(l.to_page_mm({2, 1}), {12, 139.125});
  expect_point(l.to_page_mm({6, 2}), {285, 70.875});
  const Rect2 e = drawing_extent(std::nullopt, segments);
  EXPECT_EQ(e.xmin, 2);
  EXPECT_EQ(e.xmax, 6);
  EXPECT_EQ(e.ymin, 1);
  EXPECT_EQ(e.ymax, 2);
}

TEST(PageLayout, NonFiniteEndPointsDoNotWidenTheExtent) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const std::vector<VisibleSegment> segments{piece({-1, -1}, {1, 1}), piece({nan, 0}, {inf, -inf})};
  const PageLayout l = fit_to_page(std::nullopt, segments, kA4Landscape);
  EXPECT_DOUBLE_EQ(l.scale, 93);
}

TEST(PageLayout, PortraitCentresOnTheTallPage) {
  const PageLayout l = fit_to_page(Rect2{-1, -1, 1, 1}, {}, PageSpec{*paper_by_name("A4"), 12});
  EXPECT_DOUBLE_EQ(l.scale, 93);  // the width 186 now limits
  expect_point(l.to_page_mm({0, 0}), {105, 148.5});
  expect_point(l.to_page_mm({-1, 1}), {12, 55.5});
}

TEST(PageLayout, ZeroMarginUsesTheWholePage) {
  const PageLayout l = fit_to_page(Rect2{0, 0, 297, 210}, {}, PageSpec{{297, 210}, 0});
  EXPECT_DOUBLE_EQ(l.scale, 1);
  expect_point(l.to_page_mm({0, 0}), {0, 210});
  expect_point(l.to_page_mm({297, 210}), {297, 0});
}

TEST(PageLayout, DegenerateExtents) {
  // Nothing to draw: scale 1 about the picture origin at the page centre.
  const PageLayout empty = fit_to_page(std::nullopt, {}, kA4Landscape);
  EXPECT_EQ(empty.scale, 1);
  expect_point(empty.to_page_mm({0, 0}), {148.5, 105});
  // A single point: centred, scale 1.
  const PageLayout dot = fit_to_page(std::nullopt, {piece({3, 4}, {3, 4})}, kA4Landscape);
  EXPECT_EQ(dot.scale, 1);
  expect_point(dot.to_page_mm({3, 4}), {148.5, 105});
  // A horizontal line: only its length limits the scale.
  const PageLayout flat = fit_to_page(std::nullopt, {piece({-1, 7}, {1, 7})}, kA4Landscape);
  EXPECT_DOUBLE_EQ(flat.scale, 136.5);
  expect_point(flat.to_page_mm({-1, 7}), {12, 105});
  expect_point(flat.to_page_mm({1, 7}), {285, 105});
  // A vertical line likewise.
  const PageLayout tall = fit_to_page(std::nullopt, {piece({5, 0}, {5, 3})}, kA4Landscape);
  EXPECT_DOUBLE_EQ(tall.scale, 62);
}

// Far from the picture origin the mapping keeps its precision (it works about the centre).
TEST(PageLayout, FarFromOriginStaysPrecise) {
  const PageLayout l = fit_to_page(Rect2{1e9 - 1, 1e9 - 1, 1e9 + 1, 1e9 + 1}, {}, kA4Landscape);
  expect_point(l.to_page_mm({1e9 - 1, 1e9 + 1}), {55.5, 12}, 1e-6);
}

TEST(PageLayout, BadSpecsAreDeviceErrors) {
  const Rect2 r{-1, -1, 1, 1};
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const PageSpec& bad : {PageSpec{{297, 210}, -1}, PageSpec{{297, 210}, 105}, PageSpec{{297, 210}, 200},
                              PageSpec{{0, 210}, 0}, PageSpec{{297, -210}, 0}, PageSpec{{nan, 210}, 12},
                              PageSpec{{297, inf}, 12}, PageSpec{{297, 210}, nan}}) {
    EXPECT_THROW(fit_rect_to_page(r, bad), DeviceError) << bad.paper.width_mm << " " << bad.margin_mm;
    EXPECT_THROW(check_page_spec(bad), DeviceError);
  }
  try {
    check_page_spec(PageSpec{{297, 210}, 105});
    ADD_FAILURE() << "no error";
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("margin"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(check_page_spec(PageSpec{{297, 210}, 104.9}));
}

// A fixed scale centres the extent instead of fitting it: [2, 6] × [1, 2] at 10 mm per unit.
TEST(PageLayout, ExplicitScaleCentresWithoutFitting) {
  PageSpec spec = kA4Landscape;
  spec.mm_per_unit = 10;
  const std::vector<VisibleSegment> segments{piece({2, 1}, {6, 2})};
  const PageLayout l = fit_to_page(std::nullopt, segments, spec);
  EXPECT_EQ(l.scale, 10);
  expect_point(l.to_page_mm({4, 1.5}), {148.5, 105});
  expect_point(l.to_page_mm({2, 1}), {128.5, 110});
  expect_point(l.to_page_mm({6, 2}), {168.5, 100});
  // The frame still wins and is centred; its size does not matter.
  const PageLayout framed = fit_to_page(Rect2{-1, -1, 1, 1}, segments, spec);
  EXPECT_EQ(framed.scale, 10);
  expect_point(framed.to_page_mm({1, 1}), {158.5, 95});
  // Too large for the page: kept, running off the sheet.
  spec.mm_per_unit = 1000;
  const PageLayout big = fit_rect_to_page(Rect2{-1, -1, 1, 1}, spec);
  EXPECT_EQ(big.scale, 1000);
  expect_point(big.to_page_mm({-1, 1}), {-851.5, -895});
  // Nothing to draw: the picture origin at the centre, at the given scale.
  spec.mm_per_unit = 2.5;
  const PageLayout empty = fit_to_page(std::nullopt, {}, spec);
  EXPECT_EQ(empty.scale, 2.5);
  expect_point(empty.to_page_mm({0, 0}), {148.5, 105});
  expect_point(empty.to_page_mm({2, 2}), {153.5, 100});
  // A point lands at the centre.
  const PageLayout dot = fit_to_page(std::nullopt, {piece({3, 4}, {3, 4})}, spec);
  EXPECT_EQ(dot.scale, 2.5);
  expect_point(dot.to_page_mm({3, 4}), {148.5, 105});
}

TEST(PageLayout, BadExplicitScaleIsADeviceError) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const double bad : {0.0, -1.0, -0.0, nan, inf, -inf}) {
    PageSpec spec = kA4Landscape;
    spec.mm_per_unit = bad;
    try {
      fit_rect_to_page(Rect2{-1, -1, 1, 1}, spec);
      ADD_FAILURE() << "no error for " << bad;
    } catch (const DeviceError& e) {
      EXPECT_NE(std::string(e.what()).find("scale"), std::string::npos) << e.what();
    }
  }
  PageSpec tiny = kA4Landscape;
  tiny.mm_per_unit = 1e-9;
  EXPECT_NO_THROW(check_page_spec(tiny));
}

TEST(PageLayout, PaperSidesUpToTenMetres) {
  EXPECT_NO_THROW(check_page_spec(PageSpec{{kMaxPaperSideMm, kMaxPaperSideMm}, 0}));
  EXPECT_NO_THROW(check_page_spec(PageSpec{{10000, 5}, 0}));
  for (const Paper& bad : {Paper{10000.001, 200}, Paper{200, 1e9}, Paper{1e300, 1e300}}) {
    try {
      check_page_spec(PageSpec{bad, 0});
      ADD_FAILURE() << "no error for " << bad.width_mm << " x " << bad.height_mm;
    } catch (const DeviceError& e) {
      EXPECT_NE(std::string(e.what()).find("too large"), std::string::npos) << e.what();
    }
  }
}

struct NamedSize {
  const char* name;
  double width_mm, height_mm;  // portrait
};

TEST(PaperByName, EveryNamedSizeBothWays) {
  const NamedSize sizes[] = {{"A0", 841, 1189},        {"A1", 594, 841},         {"A2", 420, 594},
                             {"A3", 297, 420},         {"A4", 210, 297},         {"A5", 148, 210},
                             {"A6", 105, 148},         {"Letter", 215.9, 279.4}, {"Legal", 215.9, 355.6},
                             {"Tabloid", 279.4, 431.8}};
  ASSERT_EQ(paper_names().size(), std::size(sizes));
  for (std::size_t i = 0; i < std::size(sizes); ++i) {
    const NamedSize& n = sizes[i];
    EXPECT_EQ(paper_names()[i], n.name);
    const auto portrait = paper_by_name(n.name);
    ASSERT_TRUE(portrait) << n.name;
    EXPECT_DOUBLE_EQ(portrait->width_mm, n.width_mm) << n.name;
    EXPECT_DOUBLE_EQ(portrait->height_mm, n.height_mm) << n.name;
    const auto explicit_portrait = paper_by_name(n.name, false);
    ASSERT_TRUE(explicit_portrait);
    EXPECT_EQ(explicit_portrait->width_mm, portrait->width_mm);
    const auto landscape = paper_by_name(n.name, true);
    ASSERT_TRUE(landscape) << n.name;
    EXPECT_DOUBLE_EQ(landscape->width_mm, n.height_mm) << n.name;
    EXPECT_DOUBLE_EQ(landscape->height_mm, n.width_mm) << n.name;
  }
}

TEST(PaperByName, IgnoresCase) {
  for (const char* name : {"A4", "a4"}) {
    const auto p = paper_by_name(name, true);
    ASSERT_TRUE(p) << name;
    EXPECT_EQ(p->width_mm, 297);
    EXPECT_EQ(p->height_mm, 210);
  }
  for (const char* name : {"letter", "LETTER", "Letter", "lEtTeR"}) {
    const auto p = paper_by_name(name);
    ASSERT_TRUE(p) << name;
    EXPECT_DOUBLE_EQ(p->width_mm, 215.9);
  }
  EXPECT_TRUE(paper_by_name("legal"));
  EXPECT_TRUE(paper_by_name("TABLOID"));
  EXPECT_TRUE(paper_by_name("a0"));
}

TEST(PaperByName, UnknownNames) {
  for (const char* name : {"", "A", "A7", "A10", "B4", "a4 ", " a4", "A4landscape", "letters", "ledger", "4A",
                           "Let", "A4\n", "ａ4"}) {
    EXPECT_FALSE(paper_by_name(name)) << '"' << name << '"';
    EXPECT_FALSE(paper_by_name(name, true)) << '"' << name << '"';
  }
  EXPECT_FALSE(paper_by_name(std::string_view("A4\0", 3)));
}

TEST(PaperByName, DefaultPaperIsA4Landscape) {
  const Paper p;
  const auto a4 = paper_by_name("A4", true);
  EXPECT_EQ(p.width_mm, a4->width_mm);
  EXPECT_EQ(p.height_mm, a4->height_mm);
}

TEST(ParsePaper, NamesFollowPaperByName) {
  for (const std::string_view name : paper_names()) {
    for (const bool landscape : {false, true}) {
      const auto parsed = parse_paper(name, landscape), named = paper_by_name(name, landscape);
      ASSERT_TRUE(parsed) << name;
      EXPECT_EQ(parsed->width_mm, named->width_mm) << name;
      EXPECT_EQ(parsed->height_mm, named->height_mm) << name;
    }
  }
  const auto a3 = parse_paper("a3", true);
  ASSERT_TRUE(a3);
  EXPECT_EQ(a3->width_mm, 420);
  EXPECT_EQ(a3->height_mm, 297);
}

// Custom sizes turn like named ones: width ≥ height in landscape, width ≤ height in portrait.
TEST(ParsePaper, CustomSizesInMillimetres) {
  struct Case {
    const char* text;
    bool landscape;
    double width_mm, height_mm;
  };
  const Case cases[] = {
      {"300x200", true, 300, 200},    {"300x200", false, 200, 300},
      {"200x300", true, 300, 200},    {"200x300", false, 200, 300},
      {"300x200mm", true, 300, 200},  {"300X200MM", true, 300, 200},
      {"300x200Mm", false, 200, 300}, {"215.9x279.4", false, 215.9, 279.4},
      {"250x250", true, 250, 250},    {"250x250", false, 250, 250},
      {"0.5x7", true, 7, 0.5},        {"007x0010.250mm", false, 7, 10.25},
  };
  for (const Case& c : cases) {
    const auto p = parse_paper(c.text, c.landscape);
    ASSERT_TRUE(p) << c.text;
    EXPECT_DOUBLE_EQ(p->width_mm, c.width_mm) << c.text << " landscape " << c.landscape;
    EXPECT_DOUBLE_EQ(p->height_mm, c.height_mm) << c.text << " landscape " << c.landscape;
  }
}

TEST(ParsePaper, MalformedSizes) {
  for (const char* text :
       {"",          "x",        "300",       "300x",     "x200",       "300x200x100", "300 x 200",
        " 300x200",  "300x200 ", "300x200cm", "300x200m", "300x200mmm", "300*200",     "300×200",
        "-300x200",  "+300x200", "300x-200",  "3e2x200",  "300.x200",   "300x.5",      ".5x200",
        "300,5x200", "infx200",  "nanxnan",   "0x1e3",    "300x200in",  "A4x",         "A4 landscape"}) {
    EXPECT_FALSE(parse_paper(text, true)) << '"' << text << '"';
    EXPECT_FALSE(parse_paper(text, false)) << '"' << text << '"';
  }
  EXPECT_FALSE(parse_paper(std::string_view("300x200\0", 8), true));
}

// The parser checks spelling only; sizes are checked with the rest of the page.
TEST(ParsePaper, SizesAreCheckedByCheckPageSpec) {
  const auto zero = parse_paper("0x200", true);
  ASSERT_TRUE(zero);
  EXPECT_THROW(check_page_spec(PageSpec{*zero, 0}), DeviceError);
  const auto huge = parse_paper("20000x200", true);
  ASSERT_TRUE(huge);
  EXPECT_THROW(check_page_spec(PageSpec{*huge, 0}), DeviceError);
  const auto limit = parse_paper("10000x10000mm", false);
  ASSERT_TRUE(limit);
  EXPECT_NO_THROW(check_page_spec(PageSpec{*limit, 12}));
  // More digits than a double holds: infinity, a size error rather than a spelling one.
  const auto endless = parse_paper(std::string(400, '9') + "x200", true);
  ASSERT_TRUE(endless);
  EXPECT_THROW(check_page_spec(PageSpec{*endless, 0}), DeviceError);
}

}  // namespace
}  // namespace hlr
