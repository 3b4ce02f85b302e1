// VectorPool hands back what was given, emptied with its storage kept, and
// keeps no more than its bound.
#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "util/vector_pool.hpp"

namespace mpr {
namespace {

TEST(VectorPool, TakeGivesBackAGivenVectorEmptyWithItsStorage) {
  VectorPool<int> pool(2);
  EXPECT_EQ(pool.take().capacity(), 0u);  // nothing given yet: a new vector
  std::vector<int> v(1000, 7);
  const int* storage = v.data();
  pool.give(std::move(v));
  std::vector<int> back = pool.take();
  EXPECT_TRUE(back.empty());
  EXPECT_EQ(back.data(), storage);
  EXPECT_GE(back.capacity(), 1000u);
  EXPECT_EQ(pool.take().capacity(), 0u);  // taken once only
}

TEST(VectorPool, KeepsAtMostItsBound) {
  VectorPool<int> pool(2);
  for (int i = 0; i < 3; ++i) pool.give(std::vector<int>(10 + i));
  EXPECT_GT(pool.take().capacity(), 0u);
  EXPECT_GT(pool.take().capacity(), 0u);
  EXPECT_EQ(pool.take().capacity(), 0u);  // the third was freed, not kept
}

TEST(VectorPool, GivenOnOneThreadTakenOnAnother) {
  VectorPool<int> pool(4);
  std::thread giver([&] {
    for (int i = 0; i < 4; ++i) pool.give(std::vector<int>(100));
  });
  giver.join();
  int kept = 0;
  for (int i = 0; i < 5; ++i) kept += pool.take().capacity() >= 100;
  EXPECT_EQ(kept, 4);
}

}  // namespace
}  // namespace mpr
