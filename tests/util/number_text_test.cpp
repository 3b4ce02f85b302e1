// The trace's numbers read back to the very values the render executed: the
// shortest text (std::to_chars) parsed as the script parser parses it
// (strtod, then rounded to the call's type), for every class of bit pattern.
#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <random>
#include <vector>

#include "util/number_text.hpp"

namespace mpr {
namespace {

bool floatRoundTrips(float v) {
  const std::string t = shortestText(v);
  const float back = static_cast<float>(std::strtod(t.c_str(), nullptr));
  return std::bit_cast<std::uint32_t>(back) == std::bit_cast<std::uint32_t>(v);
}

bool doubleRoundTrips(double v) {
  const std::string t = shortestText(v);
  return std::bit_cast<std::uint64_t>(std::strtod(t.c_str(), nullptr)) == std::bit_cast<std::uint64_t>(v);
}

// Patterns of every class: each exponent (subnormals at 0) with its smallest
// and largest mantissas and random ones between, both signs.
std::vector<float> floatPatterns() {
  std::vector<float> out;
  std::mt19937 rng(13);
  for (std::uint32_t sign = 0; sign < 2; ++sign)
    for (std::uint32_t exp = 0; exp < 255; ++exp) {
      auto add = [&](std::uint32_t mant) { out.push_back(std::bit_cast<float>(sign << 31 | exp << 23 | mant)); };
      for (std::uint32_t m = 0; m < 64; ++m) add(m), add(0x7FFFFF - m);
      for (int i = 0; i < 2000; ++i) add(rng() & 0x7FFFFF);
    }
  return out;
}

TEST(NumberText, EveryFloatClassRoundTrips) {
  for (float v : floatPatterns()) ASSERT_TRUE(floatRoundTrips(v)) << shortestText(v);
}

TEST(NumberText, EverySubnormalFloatRoundTrips) {
  for (std::uint32_t mant = 0; mant <= 0x7FFFFF; ++mant)
    ASSERT_TRUE(floatRoundTrips(std::bit_cast<float>(mant))) << mant;
}

// The only finite floats whose shortest text rounds twice through a double
// (found by checking all 2^32 patterns): written with more digits.
TEST(NumberText, TheDoubleRoundingCasesRoundTrip) {
  for (float v : {7.038531e-26f, -7.038531e-26f}) {
    const std::string shortestFloat = [&] {
      char buf[64];
      return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
    }();
    EXPECT_EQ(shortestFloat, v > 0 ? "7.038531e-26" : "-7.038531e-26");
    EXPECT_NE(static_cast<float>(std::strtod(shortestFloat.c_str(), nullptr)), v);  // why the case exists
    EXPECT_TRUE(floatRoundTrips(v)) << shortestText(v);
  }
}

TEST(NumberText, FloatExtremesAndPowersOfTen) {
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> v = {0.0f, -0.0f, FLT_MIN, -FLT_MIN, FLT_MAX, -FLT_MAX, FLT_TRUE_MIN, -FLT_TRUE_MIN,
                          std::nextafter(FLT_MIN, 0.0f), std::nextafter(FLT_MAX, 0.0f), 1.0f, -1.0f, 0.1f, 1e-7f};
  for (int k = -45; k <= 38; ++k) {
    const float p = static_cast<float>(std::pow(10.0, k));
    float a = p, b = p;
    for (int i = 0; i < 50; ++i) {
      v.push_back(a), v.push_back(b);
      a = std::nextafter(a, inf), b = std::nextafter(b, 0.0f);
    }
  }
  for (float x : v) EXPECT_TRUE(floatRoundTrips(x)) << shortestText(x);
}

TEST(NumberText, EveryDoubleClassRoundTrips) {
  std::mt19937_64 rng(13);
  const double inf = std::numeric_limits<double>::infinity();
  for (std::uint64_t sign = 0; sign < 2; ++sign)
    for (std::uint64_t exp = 0; exp < 2047; ++exp) {
      auto check = [&](std::uint64_t mant) {
        const double d = std::bit_cast<double>(sign << 63 | exp << 52 | mant);
        ASSERT_TRUE(doubleRoundTrips(d)) << shortestText(d);
      };
      const std::uint64_t top = (std::uint64_t{1} << 52) - 1;
      for (std::uint64_t m = 0; m < 8; ++m) check(m), check(top - m);
      for (int i = 0; i < 100; ++i) check(rng() & top);
    }
  for (double x : {DBL_MIN, DBL_MAX, DBL_TRUE_MIN, -DBL_MAX, 0.1, 1.0 / 3.0}) EXPECT_TRUE(doubleRoundTrips(x));
  for (int k = -323; k <= 308; ++k) {
    double a = std::pow(10.0, k), b = a;
    for (int i = 0; i < 20; ++i) {
      EXPECT_TRUE(doubleRoundTrips(a) && doubleRoundTrips(b)) << k;
      a = std::nextafter(a, inf), b = std::nextafter(b, 0.0);
    }
  }
}

TEST(NumberText, IntegersAreExact) {
  std::string s;
  appendInteger(s, -2147483648LL);
  EXPECT_EQ(s, "-2147483648");
}

}  // namespace
}  // namespace mpr
