// RecentResults gives back the value computed for a key only for the same
// bytes, since the last clear(); any other key, or a cleared table,
// computes again.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

#include "util/check.hpp"
#include "util/recent_results.hpp"

namespace mpr {
namespace {

struct Key {
  float x, y;
};

TEST(RecentResults, ARepeatedKeyIsComputedOnceUntilCleared) {
  // The cache-check build computes at every hit too, to compare: there the
  // counts cannot tell a hit from a miss (the Release suite runs this test).
  if (kCheckCaches) GTEST_SKIP() << "built with MPR_CHECK_CACHES";
  RecentResults<Key, int, 16> table;
  int computed = 0;
  const auto square = [&](const Key& k) {
    ++computed;
    return static_cast<int>(k.x * k.x + k.y);
  };
  EXPECT_EQ(table.get({3.0f, 1.0f}, square), 10);
  EXPECT_EQ(table.get({3.0f, 1.0f}, square), 10);
  EXPECT_EQ(computed, 1);
  EXPECT_EQ(table.get({2.0f, 1.0f}, square), 5);
  EXPECT_EQ(computed, 2);
  table.clear();  // the function may have changed: nothing is found
  EXPECT_EQ(table.get({3.0f, 1.0f}, square), 10);
  EXPECT_EQ(computed, 3);
}

TEST(RecentResults, KeysAreTheirBytesNotTheirValues) {
  // The cache-check build computes at every hit too, to compare: there the
  // counts cannot tell a hit from a miss (the Release suite runs this test).
  if (kCheckCaches) GTEST_SKIP() << "built with MPR_CHECK_CACHES";
  RecentResults<Key, std::array<unsigned char, 4>, 16> table;
  int computed = 0;
  const auto signOfX = [&](const Key& k) {
    ++computed;
    return std::array<unsigned char, 4>{static_cast<unsigned char>(std::signbit(k.x)), 0, 0, 0};
  };
  // 0.0 and -0.0 compare equal but are different keys with different results.
  EXPECT_EQ(table.get({0.0f, 0.0f}, signOfX)[0], 0);
  EXPECT_EQ(table.get({-0.0f, 0.0f}, signOfX)[0], 1);
  EXPECT_EQ(computed, 2);
  // A NaN key (never equal to itself as a float) is found by its bytes.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  table.get({nan, 0.0f}, signOfX);
  table.get({nan, 0.0f}, signOfX);
  EXPECT_EQ(computed, 3);
}

TEST(RecentResults, AKeyThatLostItsSlotIsComputedAgain) {
  // Two slots: of three keys at least two share one, and the table keeps
  // the later; asking for every key again still gives each its own value.
  RecentResults<Key, float, 2> table;
  int computed = 0;
  const auto sum = [&](const Key& k) {
    ++computed;
    return k.x + k.y;
  };
  for (int round = 0; round < 2; ++round)
    for (float x : {1.0f, 2.0f, 3.0f}) EXPECT_EQ(table.get({x, 0.5f}, sum), x + 0.5f);
  EXPECT_GT(computed, 3);
  EXPECT_LE(computed, 6);
}

}  // namespace
}  // namespace mpr
