#include "script/recent_decimals.hpp"

#include "script/short_decimal.hpp"

#include <cstring>

#include "util/check.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mpr {

bool RecentDecimals::read(std::string_view t, const char* limit, double& value) {
#if defined(__SSE2__)
  const std::size_t n = t.size();
  if (n == 0 || n > 16 || limit - t.data() < 16) return shortDecimalAt(t, limit, value);
  // The token's 16 bytes with those past its end zeroed: n bytes of 0xFF
  // then zeros, read from the middle of a row of 16 of each.
  static constexpr unsigned char kMask[32] = {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
                                              0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
  const __m128i bytes = _mm_and_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(t.data())),
                                      _mm_loadu_si128(reinterpret_cast<const __m128i*>(kMask + 16 - n)));
  const auto low = static_cast<std::uint64_t>(_mm_cvtsi128_si64(bytes));
  const auto high = static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_unpackhi_epi64(bytes, bytes)));
  const std::uint64_t hash = (low ^ (high * 0xC2B2AE3D27D4EB4Full) ^ n) * 0x9E3779B97F4A7C15ull;
  if (!entries_) entries_ = std::make_unique<Entry[]>(std::size_t{1} << kSlotBits);
  Entry& e = entries_[hash >> (64 - kSlotBits)];
  if (e.size == n && e.low == low && e.high == high) {
    value = e.value;
    if constexpr (kCheckCaches) {
      double fresh = 0.0;
      MPR_CHECK(shortDecimalAt(t, limit, fresh));
      MPR_CHECK(std::memcmp(&fresh, &value, sizeof(double)) == 0);
    }
    return true;
  }
  if (!shortDecimalAt(t, limit, value)) return false;
  e = {low, high, value, static_cast<std::uint32_t>(n)};
  return true;
#else
  return shortDecimalAt(t, limit, value);
#endif
}

}  // namespace mpr
