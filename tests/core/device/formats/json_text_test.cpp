#include "core/device/formats/json_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "core/device/formats/json_device.hpp"

namespace hlr {
namespace {

std::string number_text(double v) {
  std::string s;
  append_json_number(s, v);
  return s;
}

TEST(JsonText, NumbersAreShortestAndStayFloating) {
  EXPECT_EQ(number_text(2), "2.0");
  EXPECT_EQ(number_text(-0.5), "-0.5");
  EXPECT_EQ(number_text(0.1), "0.1");
  EXPECT_EQ(number_text(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(number_text(1e20), "1e+20");
  EXPECT_EQ(number_text(1e-7), "1e-07");
  EXPECT_EQ(number_text(0), "0.0");
  EXPECT_EQ(number_text(123456789), "123456789.0");
}

// Every double read back by an independent parser (nlohmann's) is the one written, and the text is no
// longer than the 17 significant digits that always suffice.
TEST(JsonText, NumbersReadBackExactly) {
  std::mt19937_64 random(20261203);
  std::uniform_int_distribution<std::uint64_t> bits;
  for (int i = 0; i < 200000; ++i) {
    double v;
    const std::uint64_t b = bits(random);
    static_assert(sizeof v == sizeof b);
    std::memcpy(&v, &b, sizeof v);
    if (!std::isfinite(v)) continue;
    const std::string text = number_text(v);
    EXPECT_EQ(nlohmann::json::parse(text).get<double>(), v) << text;
    EXPECT_LE(text.size(), 25U) << text;
  }
  for (const double v : {std::numeric_limits<double>::max(), std::numeric_limits<double>::denorm_min(),
                         -std::numeric_limits<double>::min(), 5e-324, 1.0 / 3.0})
    EXPECT_EQ(nlohmann::json::parse(number_text(v)).get<double>(), v) << number_text(v);
}

TEST(JsonText, StringsAreEscaped) {
  std::string text = "a\"b\\c\n\t\r\b\f\x01\x1f";
  text += '\0';
  text += "é€😀";
  std::string out;
  ASSERT_TRUE(append_json_string(out, text));
  EXPECT_EQ(out, "\"a\\\"b\\\\c\\n\\t\\r\\b\\f\\u0001\\u001f\\u0000é€😀\"");
  EXPECT_EQ(nlohmann::json::parse(out).get<std::string>(), text);
}

TEST(JsonText, IllFormedUtf8IsRefused) {
  for (const char* bad : {"\xff", "a\xc3", "\xc0\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80", "\xe2\x82"}) {
    std::string out;
    EXPECT_FALSE(append_json_string(out, bad)) << bad;
  }
}

TEST(JsonParts, ListsAndAll) {
  const auto all = parse_json_parts("all");
  ASSERT_TRUE(all);
  EXPECT_TRUE(all->camera && all->layout && all->segments && all->strokes && all->stats);
  const auto two = parse_json_parts("stats,strokes");
  ASSERT_TRUE(two);
  EXPECT_TRUE(two->strokes && two->stats);
  EXPECT_FALSE(two->camera || two->layout || two->segments);
  for (const char* bad : {"", "strokes,", ",stats", "stroke", "all,stats", "STATS", "strokes stats"})
    EXPECT_FALSE(parse_json_parts(bad)) << bad;
}

}  // namespace
}  // namespace hlr
