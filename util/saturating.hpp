#pragma once
// Counting in a type that saturates: predicted pass counts grow as n^depth
// (1994 eq. 5) and wrap a uint64 long before a render could finish, so a
// sum or product that would overflow stays at the maximum instead, and the
// maximum reads "at least this many".
#include <cstdint>
#include <limits>
#include <string>

namespace mpr {

inline constexpr std::uint64_t kSaturated = std::numeric_limits<std::uint64_t>::max();

inline std::uint64_t saturatingAdd(std::uint64_t a, std::uint64_t b) {
  std::uint64_t r = 0;
  return __builtin_add_overflow(a, b, &r) ? kSaturated : r;
}

inline std::uint64_t saturatingMul(std::uint64_t a, std::uint64_t b) {
  std::uint64_t r = 0;
  return __builtin_mul_overflow(a, b, &r) ? kSaturated : r;
}

// The count as text; a saturated one as "more than 18446744073709551614".
inline std::string countText(std::uint64_t v) {
  return v == kSaturated ? "more than " + std::to_string(kSaturated - 1) : std::to_string(v);
}

}  // namespace mpr
