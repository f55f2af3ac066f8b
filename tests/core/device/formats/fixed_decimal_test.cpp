#include "core/device/formats/fixed_decimal.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace hlr {
namespace {

std::string fixed(double v, int decimals) {
  std::string s;
  append_fixed(s, v, decimals);
  return s;
}

// The reference, in exact rationals: every double is one. v · 10^decimals rounded to the nearest integer,
// ties to even, written with the point put back, trailing zeros and a bare point dropped, no "-0".
std::string exact_fixed(double v, int decimals) {
  mpz_class scale = 1;
  for (int k = 0; k < decimals; ++k) scale *= 10;
  const mpq_class scaled = mpq_class(v) * scale;
  mpz_class below;
  mpz_fdiv_q(below.get_mpz_t(), scaled.get_num_mpz_t(), scaled.get_den_mpz_t());
  const mpq_class above_below = scaled - below;  // in [0, 1)
  const int half = cmp(above_below, mpq_class(1, 2));
  mpz_class rounded = below;
  if (half > 0 || (half == 0 && mpz_odd_p(below.get_mpz_t()) != 0)) rounded += 1;
  const bool negative = rounded < 0;
  std::string digits = mpz_class(abs(rounded)).get_str();
  if (static_cast<int>(digits.size()) <= decimals)
    digits.insert(0, static_cast<std::size_t>(decimals + 1) - digits.size(), '0');
  std::string text = digits.substr(0, digits.size() - static_cast<std::size_t>(decimals));
  std::string fraction = digits.substr(digits.size() - static_cast<std::size_t>(decimals));
  while (!fraction.empty() && fraction.back() == '0') fraction.pop_back();
  if (!fraction.empty()) text += "." + fraction;
  return negative ? "-" + text : text;
}

TEST(FixedDecimal, WritesCoordinatesAsTyped) {
  EXPECT_EQ(fixed(12.5, 3), "12.5");
  EXPECT_EQ(fixed(0.125, 3), "0.125");
  EXPECT_EQ(fixed(-3, 3), "-3");
  EXPECT_EQ(fixed(0, 3), "0");
  EXPECT_EQ(fixed(-0.0, 3), "0");
  EXPECT_EQ(fixed(-0.0004, 3), "0");  // rounds to zero: no sign
  EXPECT_EQ(fixed(-0.0006, 3), "-0.001");
  EXPECT_EQ(fixed(595.2756, 4), "595.2756");
  EXPECT_EQ(fixed(2.83464567, 8), "2.83464567");
  EXPECT_EQ(fixed(1e20, 3), "100000000000000000000");  // beyond the short way
}

TEST(FixedDecimal, ExactTiesGoToEven) {
  // Sixteenths have four decimals: each lies halfway between two numbers of three.
  EXPECT_EQ(fixed(0.0625, 3), "0.062");
  EXPECT_EQ(fixed(0.1875, 3), "0.188");
  EXPECT_EQ(fixed(-0.0625, 3), "-0.062");
  EXPECT_EQ(fixed(2.5, 0), "2");
  EXPECT_EQ(fixed(3.5, 0), "4");
  EXPECT_EQ(fixed(-2.5, 0), "-2");
}

TEST(FixedDecimal, AgreesWithExactRoundingOnRandomAndNearTieValues) {
  std::mt19937_64 rng(20261207);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-12, 18), decimals(0, 9);
  std::uniform_int_distribution<std::int64_t> whole(-2'000'000, 2'000'000);
  int checked = 0;
  for (int i = 0; i < 100'000; ++i) {
    const int d = decimals(rng);
    // Plain values over many magnitudes, and doubles at and next to n + ½ units of the last decimal.
    const double plain = std::ldexp(unit(rng), exponent(rng));
    const double tie = (static_cast<double>(whole(rng)) + 0.5) / std::pow(10.0, d);
    for (const double v : {plain, tie, std::nextafter(tie, 0.0), std::nextafter(tie, 1e300)}) {
      ASSERT_EQ(fixed(v, d), exact_fixed(v, d)) << "v = " << v << ", decimals " << d;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 400'000);
}

TEST(FixedDecimal, LargeAndSpecialValuesTakeTheLongWay) {
  for (const double v : {1e15, -1e15, 123456789012345.678, 1e300, std::numeric_limits<double>::denorm_min()})
    EXPECT_EQ(fixed(v, 3), exact_fixed(v, 3)) << v;
  EXPECT_EQ(fixed(std::numeric_limits<double>::infinity(), 3), "inf");
  EXPECT_EQ(fixed(std::nan(""), 3), "nan");
}

}  // namespace
}  // namespace hlr
