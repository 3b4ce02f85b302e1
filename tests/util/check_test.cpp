// Invariant checks print the expression, both operands and the place.
#include <gtest/gtest.h>

#include "util/check.hpp"

namespace mpr {
namespace {

TEST(CheckDeathTest, PrintsBothOperands) {
  const int stencilBits = 8;
  EXPECT_DEATH(MPR_CHECK_EQ(stencilBits, 4), "check_test.cpp:[0-9]+: internal check failed: stencilBits == 4 with 8 and 4");
  EXPECT_DEATH(MPR_CHECK(stencilBits < 0), "internal check failed: stencilBits < 0");
}

TEST(Check, PassingChecksDoNothing) {
  MPR_CHECK_LT(1, 2);
  MPR_CHECK(true);
  MPR_DCHECK_EQ(3, 3);
}

}  // namespace
}  // namespace mpr
