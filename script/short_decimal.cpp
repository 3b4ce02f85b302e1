#include "script/short_decimal.hpp"

#include <bit>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mpr {
namespace {

constexpr double kPowers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                              1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr std::uint64_t kIntegerPowers[] = {1,         10,         100,         1000,         10000,
                                            100000,    1000000,    10000000,    100000000,    1000000000,
                                            10000000000ULL, 100000000000ULL, 1000000000000ULL,
                                            10000000000000ULL, 100000000000000ULL, 1000000000000000ULL};

// w * 10^q, or w / 10^-q: one correctly rounded operation on exact doubles.
double scaled(std::uint64_t w, int q) {
  return q >= 0 ? static_cast<double>(w) * kPowers[q] : static_cast<double>(w) / kPowers[-q];
}

#if defined(__SSE2__)
// The value of the `count` (at most 8) digits at the start of `digits`
// (byte k the k-th digit's value, 0..9; bytes past them anything): the
// digits moved to the word's top bytes, zeros below (leading zeros), then
// pairs, quads and the eight combined by three multiplies (the well-known
// eight-digit reduction of fast_float and simdjson).
std::uint64_t digitsValue(const unsigned char* digits, int count) {
  if (count == 0) return 0;
  std::uint64_t v;
  std::memcpy(&v, digits, 8);
  v <<= 8 * (8 - count);
  v = v * 10 + (v >> 8);
  constexpr std::uint64_t kMask = 0x000000FF000000FF;
  constexpr std::uint64_t kMul1 = 100 + (1000000ULL << 32);
  constexpr std::uint64_t kMul2 = 1 + (10000ULL << 32);
  return (((v & kMask) * kMul1) + (((v >> 16) & kMask) * kMul2)) >> 32;
}

// Up to 15 digits: eight, then the rest.
std::uint64_t runValue(const unsigned char* digits, int count) {
  if (count <= 8) return digitsValue(digits, count);
  return digitsValue(digits, 8) * kIntegerPowers[count - 8] + digitsValue(digits + 8, count - 8);
}
#endif

}  // namespace

bool plainShortDecimal(std::string_view t, double& value) {
  std::size_t i = 0;
  const bool negative = !t.empty() && t[0] == '-';
  if (negative) i = 1;
  std::uint64_t w = 0;
  int digits = 0, fraction = 0;
  bool point = false;
  for (; i < t.size(); ++i) {
    const char c = t[i];
    if (c >= '0' && c <= '9') {
      if (++digits > 15) return false;
      w = w * 10 + static_cast<std::uint64_t>(c - '0');
      fraction += point;
    } else if (c == '.' && !point) {
      point = true;
    } else {
      break;
    }
  }
  if (digits == 0) return false;
  int exponent = 0;
  if (i < t.size()) {
    if (t[i] != 'e' && t[i] != 'E') return false;
    ++i;
    const bool negativeExponent = i < t.size() && t[i] == '-';
    if (i < t.size() && (t[i] == '-' || t[i] == '+')) ++i;
    if (i == t.size() || t.size() - i > 3) return false;  // no digits, or past the fast path anyway
    for (; i < t.size(); ++i) {
      if (t[i] < '0' || t[i] > '9') return false;
      exponent = exponent * 10 + (t[i] - '0');
    }
    if (negativeExponent) exponent = -exponent;
  }
  const int q = exponent - fraction;
  if (q < -22 || q > 22) return false;
  const double v = scaled(w, q);
  value = negative ? -v : v;
  return true;
}

bool shortDecimalAt(std::string_view t, const char* limit, double& value) {
#if defined(__SSE2__)
  const std::size_t n = t.size();
  if (n == 0 || n > 16 || limit - t.data() < 16) return plainShortDecimal(t, value);
  const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(t.data()));
  const __m128i values = _mm_sub_epi8(bytes, _mm_set1_epi8('0'));
  // A byte is a digit where its value, unsigned, is at most 9.
  const __m128i isDigit = _mm_cmpeq_epi8(_mm_min_epu8(values, _mm_set1_epi8(9)), values);
  const unsigned inToken = static_cast<unsigned>((std::uint32_t{1} << n) - 1);
  const unsigned digitBits = static_cast<unsigned>(_mm_movemask_epi8(isDigit)) & inToken;
  const unsigned pointBits = static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(bytes, _mm_set1_epi8('.')))) & inToken;
  const bool negative = t[0] == '-';
  // Anything but [-], digits and one point (an exponent, a '+', a name, a
  // second point) is plainShortDecimal's to read or refuse.
  if ((digitBits | pointBits | unsigned{negative}) != inToken || (pointBits & (pointBits - 1)) != 0)
    return plainShortDecimal(t, value);
  // Every byte but the sign and the point is a digit (counted without a
  // popcount, which baseline x86-64 lacks: a library call per number).
  const bool point = pointBits != 0;
  const int first = negative ? 1 : 0;
  const int digits = static_cast<int>(n) - first - int{point};
  if (digits == 0 || digits > 15) return false;
  // The digits after the point (none without one).
  const int fraction = point ? static_cast<int>(n) - 1 - std::countr_zero(pointBits) : 0;
  const int wholeDigits = digits - fraction;
  // Digit values with room for a run of eight read past the token's end.
  alignas(16) unsigned char d[32] = {};
  _mm_store_si128(reinterpret_cast<__m128i*>(d), values);
  const std::uint64_t whole = runValue(d + first, wholeDigits);
  const std::uint64_t part = runValue(d + first + wholeDigits + int{point}, fraction);
  const std::uint64_t w = whole * kIntegerPowers[fraction] + part;
  const double v = scaled(w, -fraction);
  value = negative ? -v : v;
  return true;
#else
  (void)limit;
  return plainShortDecimal(t, value);
#endif
}

}  // namespace mpr
