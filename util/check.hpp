#pragma once
// Invariant checks (pbrt-v4's check.h): a programmer's mistake, never a
// user's. A failed check prints the expression, both operands and the place,
// and aborts. MPR_CHECK* are always on; MPR_DCHECK* only in builds without
// NDEBUG. User errors (a scene or script mistake) are located exceptions
// instead (SceneError, ScriptError: FILE:LINE:COLUMN: message).
#include <sstream>
#include <string>

namespace mpr::detail {

[[noreturn]] void checkFailed(const char* file, int line, const char* expression, const std::string& operands);

template <class A, class B>
std::string checkOperands(const A& a, const B& b) {
  std::ostringstream o;
  o << "with " << a << " and " << b;
  return o.str();
}

}  // namespace mpr::detail

#define MPR_CHECK(cond) \
  ((cond) ? static_cast<void>(0) : ::mpr::detail::checkFailed(__FILE__, __LINE__, #cond, std::string()))

#define MPR_CHECK_OP_(a, op, b)                                                                        \
  do {                                                                                                 \
    const auto& mprCheckA_ = (a);                                                                      \
    const auto& mprCheckB_ = (b);                                                                      \
    if (!(mprCheckA_ op mprCheckB_))                                                                   \
      ::mpr::detail::checkFailed(__FILE__, __LINE__, #a " " #op " " #b,                                \
                                 ::mpr::detail::checkOperands(mprCheckA_, mprCheckB_));                \
  } while (false)

#define MPR_CHECK_EQ(a, b) MPR_CHECK_OP_(a, ==, b)
#define MPR_CHECK_NE(a, b) MPR_CHECK_OP_(a, !=, b)
#define MPR_CHECK_LT(a, b) MPR_CHECK_OP_(a, <, b)
#define MPR_CHECK_LE(a, b) MPR_CHECK_OP_(a, <=, b)
#define MPR_CHECK_GT(a, b) MPR_CHECK_OP_(a, >, b)
#define MPR_CHECK_GE(a, b) MPR_CHECK_OP_(a, >=, b)

#ifdef NDEBUG
#define MPR_DCHECK(cond) static_cast<void>(0)
#define MPR_DCHECK_EQ(a, b) static_cast<void>(0)
#define MPR_DCHECK_LT(a, b) static_cast<void>(0)
#else
#define MPR_DCHECK(cond) MPR_CHECK(cond)
#define MPR_DCHECK_EQ(a, b) MPR_CHECK_EQ(a, b)
#define MPR_DCHECK_LT(a, b) MPR_CHECK_LT(a, b)
#endif

namespace mpr {
// The cache-check build (-DMPR_CHECK_CACHES=ON, the sanitizer build's mode):
// every hit of a cache that stands in for a pure function (RecentLines,
// RecentDecimals, RecentResults) computes the uncached result as well and
// checks that the bytes agree. A cache is only a speed-up when that holds.
#if defined(MPR_CHECK_CACHES)
inline constexpr bool kCheckCaches = true;
#else
inline constexpr bool kCheckCaches = false;
#endif
}  // namespace mpr
