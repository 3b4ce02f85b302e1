// Invariant checks print the expression, both operands and the place;
// a passing one evaluates each operand once and formats nothing.
#include <gtest/gtest.h>

#include <ostream>

#include "util/check.hpp"

namespace mpr {
namespace {

TEST(CheckDeathTest, PrintsBothOperands) {
  const int stencilBits = 8;
  EXPECT_DEATH(MPR_CHECK_EQ(stencilBits, 4), "check_test.cpp:[0-9]+: internal check failed: stencilBits == 4 with 8 and 4");
  EXPECT_DEATH(MPR_CHECK(stencilBits < 0), "internal check failed: stencilBits < 0");
}

// An operand that counts how often it is evaluated and printed.
struct Counted {
  int value;
  int* printed;
  bool operator<(const Counted& o) const { return value < o.value; }
  bool operator==(const Counted& o) const { return value == o.value; }
};
std::ostream& operator<<(std::ostream& out, const Counted& c) {
  ++*c.printed;
  return out << c.value;
}

// A passing check costs its comparison only: each operand is evaluated
// once (a check may hold an expression with effects, or an expensive one),
// nothing is formatted, and control goes on past it.
TEST(Check, APassingCheckEvaluatesEachOperandOnceAndFormatsNothing) {
  int evaluated = 0, printed = 0;
  const auto next = [&](int v) {
    ++evaluated;
    return Counted{v, &printed};
  };
  MPR_CHECK_LT(next(1), next(2));
  EXPECT_EQ(evaluated, 2);
  MPR_CHECK_EQ(next(3), next(3));
  EXPECT_EQ(evaluated, 4);
  MPR_CHECK(++evaluated == 5);
  EXPECT_EQ(evaluated, 5);
  EXPECT_EQ(printed, 0);
}

// A failing one prints each operand once, as evaluated once: the message
// shows the values the comparison saw.
TEST(CheckDeathTest, AFailingCheckPrintsTheValuesItCompared) {
  int calls = 0;
  const auto next = [&] { return ++calls; };
  EXPECT_DEATH(MPR_CHECK_EQ(next(), next()), "next\\(\\) == next\\(\\) with 1 and 2");
}

// MPR_DCHECK* are debug-build checks: in a build with NDEBUG their operands
// are not evaluated at all (they cost nothing in a hot path), without it
// they are checks like MPR_CHECK*.
TEST(Check, DebugChecksEvaluateTheirOperandsOnlyInDebugBuilds) {
  int evaluated = 0;
  MPR_DCHECK(++evaluated == 1);
  MPR_DCHECK_EQ(++evaluated, 2);
  MPR_DCHECK_LT(++evaluated, 4);
#ifdef NDEBUG
  EXPECT_EQ(evaluated, 0);
#else
  EXPECT_EQ(evaluated, 3);
#endif
}

}  // namespace
}  // namespace mpr
