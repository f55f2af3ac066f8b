#include "core/device/page/pen_style.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace hlr {
namespace {

void expect_colour(const PenStyle& s, double r, double g, double b) {
  EXPECT_DOUBLE_EQ(s.r, r);
  EXPECT_DOUBLE_EQ(s.g, g);
  EXPECT_DOUBLE_EQ(s.b, b);
}

void expect_colour(const std::optional<Colour>& c, double r, double g, double b) {
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(c->r, r);
  EXPECT_DOUBLE_EQ(c->g, g);
  EXPECT_DOUBLE_EQ(c->b, b);
}

TEST(PenStyle, CarouselDefaults) {
  expect_colour(default_pen_style(1), 0, 0, 0);
  expect_colour(default_pen_style(2), 1, 0, 0);
  expect_colour(default_pen_style(3), 0, 1, 0);
  expect_colour(default_pen_style(4), 0, 0, 1);
  expect_colour(default_pen_style(5), 0, 1, 1);
  expect_colour(default_pen_style(6), 1, 0, 1);
  expect_colour(default_pen_style(8), 0, 0, 0);
  // Pen 7 is yellow darkened for white paper: red over green, no blue, and not the full #ffff00.
  const PenStyle amber = default_pen_style(7);
  EXPECT_GT(amber.r, amber.g);
  EXPECT_GT(amber.g, 0.4);
  EXPECT_EQ(amber.b, 0);
  EXPECT_LT(amber.r + amber.g, 1.6);
  for (int pen = 1; pen <= 8; ++pen) {
    EXPECT_EQ(default_pen_style(pen).width_mm, kDefaultPenWidthMm) << pen;
    EXPECT_FALSE(pen_style_problem(default_pen_style(pen))) << pen;
    // Higher pens repeat the carousel.
    const PenStyle again = default_pen_style(pen + 8), third = default_pen_style(pen + 16);
    expect_colour(again, default_pen_style(pen).r, default_pen_style(pen).g, default_pen_style(pen).b);
    expect_colour(third, default_pen_style(pen).r, default_pen_style(pen).g, default_pen_style(pen).b);
  }
  EXPECT_EQ(kDefaultPenWidthMm, 0.25);
  expect_colour(default_pen_style(0), 0, 0, 0);
  expect_colour(default_pen_style(-3), 0, 0, 0);
  EXPECT_EQ(default_pen_style(2, 0.7).width_mm, 0.7);
}

TEST(PenStyle, Problems) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(pen_style_problem({1, 1, 1, 1e-6}));
  for (const double w : {0.0, -1.0, nan, inf}) {
    const auto p = pen_style_problem({0, 0, 0, w});
    ASSERT_TRUE(p) << w;
    EXPECT_NE(p->find("width"), std::string::npos) << *p;
  }
  for (const PenStyle& bad : {PenStyle{-0.1, 0, 0, 1}, PenStyle{0, 1.01, 0, 1}, PenStyle{0, 0, nan, 1}}) {
    const auto p = pen_style_problem(bad);
    ASSERT_TRUE(p);
    EXPECT_NE(p->find("colour"), std::string::npos) << *p;
  }
}

TEST(PenTable, FallsBackToTheCarousel) {
  PenTable t;
  EXPECT_EQ(t.default_width_mm(), kDefaultPenWidthMm);
  for (int pen = 1; pen <= 20; ++pen) {
    const PenStyle s = t.style(pen), d = default_pen_style(pen);
    expect_colour(s, d.r, d.g, d.b);
    EXPECT_EQ(s.width_mm, d.width_mm);
    EXPECT_FALSE(t.is_set(pen));
  }
  t.set(3, {0.1, 0.2, 0.3, 0.5});
  EXPECT_TRUE(t.is_set(3));
  expect_colour(t.style(3), 0.1, 0.2, 0.3);
  EXPECT_EQ(t.style(3).width_mm, 0.5);
  expect_colour(t.style(11), 0, 1, 0);  // pen 11 is still the carousel's green
  // Colour and width separately, each keeping the other.
  t.set_colour(2, {0, 0.5, 0});
  expect_colour(t.style(2), 0, 0.5, 0);
  EXPECT_EQ(t.style(2).width_mm, kDefaultPenWidthMm);
  t.set_width(2, 0.35);
  expect_colour(t.style(2), 0, 0.5, 0);
  EXPECT_EQ(t.style(2).width_mm, 0.35);
  t.set_width(12, 1);
  expect_colour(t.style(12), 0, 0, 1);
  EXPECT_EQ(t.style(12).width_mm, 1);
}

TEST(PenTable, DefaultWidth) {
  PenTable t(0.5);
  EXPECT_EQ(t.style(1).width_mm, 0.5);
  t.set_width(4, 0.1);
  t.set_default_width(0.7);
  EXPECT_EQ(t.style(1).width_mm, 0.7);
  EXPECT_EQ(t.style(9).width_mm, 0.7);
  EXPECT_EQ(t.style(4).width_mm, 0.1) << "a pen set keeps its width";
}

TEST(PenTable, RejectsBadInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(PenTable{0.0}, std::invalid_argument);
  EXPECT_THROW(PenTable{-1.0}, std::invalid_argument);
  EXPECT_THROW(PenTable{nan}, std::invalid_argument);
  PenTable t;
  EXPECT_THROW(t.set_default_width(0), std::invalid_argument);
  EXPECT_EQ(t.default_width_mm(), kDefaultPenWidthMm);
  EXPECT_THROW(t.set(0, {}), std::invalid_argument);
  EXPECT_THROW(t.set(-1, {}), std::invalid_argument);
  EXPECT_THROW(t.set(1, {0, 0, 0, 0}), std::invalid_argument);
  EXPECT_THROW(t.set(1, {2, 0, 0, 1}), std::invalid_argument);
  EXPECT_THROW(t.set_width(1, nan), std::invalid_argument);
  EXPECT_THROW(t.set_colour(1, {0, -1, 0}), std::invalid_argument);
  EXPECT_FALSE(t.is_set(1)) << "a rejected style is not stored";
  try {
    t.set(5, {0, 0, 0, -2});
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("pen 5"), std::string::npos) << e.what();
  }
}

TEST(ParseColour, Hex) {
  expect_colour(parse_colour("#ff8000"), 1, 128 / 255.0, 0);
  expect_colour(parse_colour("#FF8000"), 1, 128 / 255.0, 0);
  expect_colour(parse_colour("#000000"), 0, 0, 0);
  expect_colour(parse_colour("#aBcDeF"), 0xab / 255.0, 0xcd / 255.0, 0xef / 255.0);
  expect_colour(parse_colour("#f80"), 1, 0x88 / 255.0, 0);  // #rgb doubles each digit
  expect_colour(parse_colour("#FFF"), 1, 1, 1);
  expect_colour(parse_colour("#123"), 0x11 / 255.0, 0x22 / 255.0, 0x33 / 255.0);
}

TEST(ParseColour, Names) {
  expect_colour(parse_colour("black"), 0, 0, 0);
  expect_colour(parse_colour("white"), 1, 1, 1);
  expect_colour(parse_colour("red"), 1, 0, 0);
  expect_colour(parse_colour("Green"), 0, 128 / 255.0, 0);
  expect_colour(parse_colour("BLUE"), 0, 0, 1);
  expect_colour(parse_colour("cyan"), 0, 1, 1);
  expect_colour(parse_colour("magenta"), 1, 0, 1);
  expect_colour(parse_colour("yellow"), 1, 1, 0);
  expect_colour(parse_colour("orange"), 1, 165 / 255.0, 0);
  expect_colour(parse_colour("grey"), 128 / 255.0, 128 / 255.0, 128 / 255.0);
  expect_colour(parse_colour("Gray"), 128 / 255.0, 128 / 255.0, 128 / 255.0);
  expect_colour(parse_colour("brown"), 165 / 255.0, 42 / 255.0, 42 / 255.0);
  expect_colour(parse_colour("purple"), 128 / 255.0, 0, 128 / 255.0);
}

TEST(ParseColour, Rejects) {
  for (const char* bad : {"",     "#",          "#1",     "#12",   "#1234", "#12345", "#1234567",
                          "#ggg", "#12345g",    "ff0000", "##fff", " red",  "red ",   "reds",
                          "re",   "rgb(1,2,3)", "#f f",   "lime",  "navy",  "#-12",   "0x123"}) {
    EXPECT_FALSE(parse_colour(bad)) << '"' << bad << '"';
  }
  EXPECT_FALSE(parse_colour(std::string_view("red\0", 4)));
  EXPECT_FALSE(parse_colour(std::string_view("#fff\0", 5)));
}

}  // namespace
}  // namespace hlr
