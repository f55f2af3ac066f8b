#include "core/device/plotters/hpgl_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/device/formats/hpgl_device.hpp"
#include "core/device/page/atomic_file.hpp"
#include "core/device/page/page_layout.hpp"

namespace hlr {
namespace {

const HpglProfile& builtin(const std::string& name) {
  for (const HpglProfile& p : builtin_hpgl_profiles())
    if (p.name == name) return p;
  throw std::runtime_error("no built-in profile " + name);
}

const HpglPaperRange& range(const HpglProfile& p, const std::string& paper) {
  for (const HpglPaperRange& r : p.ranges)
    if (r.paper == paper) return r;
  throw std::runtime_error(p.name + " has no " + paper);
}

std::string thrown(const HpglProfile& p) {
  try {
    check_hpgl_profile(p);
  } catch (const DeviceError& e) {
    return e.what();
  }
  return "";
}

TEST(HpglProfile, BuiltinNamesAndLookup) {
  std::vector<std::string> names;
  for (const HpglProfile& p : builtin_hpgl_profiles()) names.push_back(p.name);
  EXPECT_EQ(names, (std::vector<std::string>{"hp7475a", "hp7440a", "hp7550", "roland-dxy", "generic"}));
  EXPECT_EQ(hpgl_profile_list(), "hp7475a, hp7440a, hp7550, roland-dxy, generic");
  ASSERT_TRUE(hpgl_profile_by_name("HP7475A"));
  EXPECT_EQ(hpgl_profile_by_name("HP7475A")->name, "hp7475a");
  EXPECT_EQ(hpgl_profile_by_name("Roland-DXY")->name, "roland-dxy");
  EXPECT_FALSE(hpgl_profile_by_name("hp7475"));
  EXPECT_FALSE(hpgl_profile_by_name(""));
}

// The settings the issue asks for, per device.
TEST(HpglProfile, BuiltinSettings) {
  const HpglProfile& a = builtin("hp7475a");
  EXPECT_DOUBLE_EQ(a.unit_mm, 0.02488);
  EXPECT_EQ(a.pen_count, 6);
  EXPECT_DOUBLE_EQ(a.speeds.pen_down_mm_per_s, 381);
  EXPECT_DOUBLE_EQ(a.speeds.lift_s, 0.1);
  EXPECT_EQ(builtin("hp7440a").pen_count, 8);
  EXPECT_DOUBLE_EQ(builtin("hp7440a").unit_mm, 0.02488);
  EXPECT_EQ(builtin("hp7550").pen_count, 8);
  EXPECT_DOUBLE_EQ(builtin("hp7550").unit_mm, 0.02488);
  EXPECT_EQ(builtin("roland-dxy").pen_count, 8);
  EXPECT_DOUBLE_EQ(builtin("roland-dxy").unit_mm, 0.025);
  EXPECT_DOUBLE_EQ(builtin("generic").unit_mm, 0.025);
  for (const HpglProfile& p : builtin_hpgl_profiles()) {
    SCOPED_TRACE(p.name);
    EXPECT_EQ(thrown(p), "");
    EXPECT_TRUE(p.relative);
    EXPECT_EQ(p.max_pairs_per_pd, 32);
    EXPECT_EQ(p.newline, p.name == "generic");  // generic output goes to lp and cheap cutters
    EXPECT_FALSE(p.velocity_cm_s);              // IN leaves the plotter at its own fastest speed
    EXPECT_TRUE(p.y_axis_up);
    EXPECT_FALSE(p.info.empty());
    EXPECT_GT(p.speeds.pen_down_mm_per_s, 0);
  }
}

// HP's documented hard-clip ranges for the 7475A (also vpype's table).
TEST(HpglProfile, Hp7475aDocumentedRanges) {
  const HpglProfile& p = builtin("hp7475a");
  ASSERT_EQ(p.ranges.size(), 4u);
  const auto check = [&](const std::string& paper, long xmax, long ymax) {
    const HpglPaperRange& r = range(p, paper);
    EXPECT_EQ(r.x_min, 0);
    EXPECT_EQ(r.y_min, 0);
    EXPECT_EQ(r.x_max, xmax) << paper;
    EXPECT_EQ(r.y_max, ymax) << paper;
  };
  check("A4", 11040, 7721);
  check("A3", 16158, 11040);
  check("Letter", 10365, 7962);
  check("Tabloid", 16640, 10365);
}

// Sized ranges name real papers at their landscape size, and the reachable area lies on the sheet.
TEST(HpglProfile, RangesLieOnTheirSheets) {
  for (const HpglProfile& p : builtin_hpgl_profiles()) {
    for (const HpglPaperRange& r : p.ranges) {
      SCOPED_TRACE(p.name + " " + r.paper);
      if (r.any_size()) {
        EXPECT_EQ(p.name, "generic");
        EXPECT_EQ(r.x_min, 0);
        EXPECT_EQ(r.y_min, 0);
        EXPECT_EQ(r.x_max, 32767);
        EXPECT_EQ(r.y_max, 32767);
        continue;
      }
      const std::optional<Paper> paper = paper_by_name(r.paper, true);
      ASSERT_TRUE(paper);
      EXPECT_NEAR(r.width_mm, paper->width_mm, 0.05);
      EXPECT_NEAR(r.height_mm, paper->height_mm, 0.05);
      EXPECT_GE(r.origin_x_mm + r.x_min * p.unit_mm, 0);
      EXPECT_GE(r.origin_y_mm + r.y_min * p.unit_mm, 0);
      EXPECT_LE(r.origin_x_mm + r.x_max * p.unit_mm, r.width_mm + 1e-9);
      EXPECT_LE(r.origin_y_mm + r.y_max * p.unit_mm, r.height_mm + 1e-9);
    }
  }
}

// The margins each sheet needs (the reachable area is not centred on HP sheets); none beyond 20 mm, and
// the generic profile needs none.
TEST(HpglProfile, MinimumMargins) {
  for (const HpglProfile& p : builtin_hpgl_profiles()) {
    for (const HpglPaperRange& r : p.ranges) {
      if (r.any_size()) continue;
      const double m = hpgl_min_margin_mm(p, r.width_mm, r.height_mm);
      EXPECT_GT(m, 0) << p.name << " " << r.paper;
      EXPECT_LE(m, 20.01) << p.name << " " << r.paper;
      EXPECT_DOUBLE_EQ(hpgl_min_margin_mm(p, r.height_mm, r.width_mm), m) << "portrait " << p.name;
    }
  }
  // 7475A A4: the pen stops 13.9 mm short of the top edge (vpype's origin 4 mm above the bottom edge).
  EXPECT_NEAR(hpgl_min_margin_mm(builtin("hp7475a"), 297, 210), 210 - 4 - 7721 * 0.02488, 0.03);
  EXPECT_NEAR(hpgl_min_margin_mm(builtin("hp7475a"), 420, 297), 15, 0.03);
  EXPECT_EQ(hpgl_min_margin_mm(builtin("generic"), 297, 210), 0);
  EXPECT_EQ(hpgl_min_margin_mm(builtin("generic"), 100, 100), 0);
  EXPECT_THROW(hpgl_min_margin_mm(builtin("hp7475a"), 200, 100), DeviceError);
}

TEST(HpglProfile, PaperList) {
  EXPECT_EQ(hpgl_paper_list(builtin("hp7475a")),
            "A4 (297 × 210 mm), A3 (420 × 297 mm), Letter (279.4 × 215.9 mm), Tabloid (431.8 × 279.4 mm)");
  EXPECT_EQ(hpgl_paper_list(builtin("generic")), "any size");
}

TEST(HpglProfile, CheckRefusesBrokenProfiles) {
  const HpglProfile good = builtin("hp7475a");
  const auto broken = [&](auto change) {
    HpglProfile p = good;
    change(p);
    return thrown(p);
  };
  EXPECT_NE(broken([](HpglProfile& p) { p.unit_mm = 0; }).find("unit"), std::string::npos);
  EXPECT_NE(broken([](HpglProfile& p) { p.unit_mm = NAN; }).find("unit"), std::string::npos);
  EXPECT_NE(broken([](HpglProfile& p) { p.ranges.clear(); }).find("no paper range"), std::string::npos);
  EXPECT_NE(broken([](HpglProfile& p) { p.ranges[0].x_max = 40000; }).find("-32768…32767"),
            std::string::npos);
  EXPECT_NE(broken([](HpglProfile& p) { p.ranges[0].y_min = -40000; }).find("-32768…32767"),
            std::string::npos);
  EXPECT_NE(broken([](HpglProfile& p) { p.ranges[1].x_max = 0; }).find("range is empty"), std::string::npos);
  EXPECT_NE(broken([](HpglProfile& p) { p.ranges[0].width_mm = -1; }).find("sheet size"), std::string::npos);
  EXPECT_NE(broken([](HpglProfile& p) { p.ranges[0].height_mm = 0; }).find("sheet size"), std::string::npos);
  EXPECT_NE(broken([](HpglProfile& p) { p.ranges[0].origin_x_mm = INFINITY; }).find("origin"),
            std::string::npos);
  EXPECT_NE(broken([](HpglProfile& p) { p.pen_count = 0; }).find("pen"), std::string::npos);
  EXPECT_NE(broken([](HpglProfile& p) { p.velocity_cm_s = -3; }).find("velocity"), std::string::npos);
  EXPECT_NE(broken([](HpglProfile& p) { p.max_pairs_per_pd = 0; }).find("pair"), std::string::npos);
  EXPECT_NE(broken([](HpglProfile& p) { p.unit_mm = -1; }).find("plotter 'hp7475a'"), std::string::npos);
  EXPECT_EQ(broken([](HpglProfile& p) { p.velocity_cm_s = 10; }), "");
}

}  // namespace
}  // namespace hlr
