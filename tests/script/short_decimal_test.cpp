// shortDecimalAt (a token read as one 16-byte vector) against
// plainShortDecimal (a character at a time), and both against from_chars:
// on random tokens of the shapes a script holds (a sign, up to 17 digits, a
// point anywhere, an exponent) and of shapes neither may take (a '+', a
// second point, a suffix, a name), each followed in its buffer by digits,
// points and spaces that must not be read as part of it, the same answer,
// the same double to the bit, and that double from_chars' for the token.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>

#include "script/short_decimal.hpp"

namespace mpr {
namespace {

std::uint64_t bitsOf(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

std::string randomToken(std::mt19937& rng) {
  auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  std::string t;
  if (pick(2)) t += '-';
  const int digits = pick(18);
  const int point = pick(3) ? pick(digits + 1) : -1;
  for (int i = 0; i < digits; ++i) {
    if (i == point) t += '.';
    t += static_cast<char>('0' + pick(10));
  }
  if (point == digits) t += '.';
  if (pick(6) == 0) {
    t += pick(2) ? 'e' : 'E';
    const int sign = pick(3);
    if (sign == 1) t += '-';
    if (sign == 2) t += '+';
    for (int i = pick(4); i > 0; --i) t += static_cast<char>('0' + pick(10));
  }
  if (pick(20) == 0) {
    static const char* const kOdd[] = {"+", ".", "f", "x", "-", "GL_", "e"};
    const std::string odd = kOdd[pick(7)];
    t.insert(static_cast<std::size_t>(pick(static_cast<int>(t.size()) + 1)), odd);
  }
  return t;
}

// The token at the start of a buffer, `after` bytes of what may follow a
// token in a script after it; the limit is the buffer's end.
void expectSameReading(const std::string& token, const std::string& after) {
  const std::string buffer = token + after;
  const std::string_view t(buffer.data(), token.size());
  double slow = 12345.0, fast = 12345.0;
  const bool slowRead = plainShortDecimal(t, slow);
  const bool fastRead = shortDecimalAt(t, buffer.data() + buffer.size(), fast);
  ASSERT_EQ(fastRead, slowRead) << "'" << token << "' followed by '" << after << "'";
  if (!slowRead) {
    ASSERT_EQ(bitsOf(fast), bitsOf(12345.0)) << "'" << token << "': a refused token leaves the value";
    return;
  }
  ASSERT_EQ(bitsOf(fast), bitsOf(slow)) << "'" << token << "'";
  double exact = 0.0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), exact, std::chars_format::general);
  ASSERT_TRUE(ec == std::errc() && end == t.data() + t.size()) << "'" << token << "' is read but from_chars refuses it";
  ASSERT_EQ(bitsOf(fast), bitsOf(exact)) << "'" << token << "'";
}

TEST(ShortDecimal, RandomTokensReadAsOneByOneAndAsFromChars) {
  std::mt19937 rng(20261205);
  for (int i = 0; i < 200000; ++i) {
    const std::string token = randomToken(rng);
    std::string after;
    for (int k = static_cast<int>(rng() % 24u); k > 0; --k) after += "0123456789. -e\n"[rng() % 15u];
    expectSameReading(token, after);
  }
}

TEST(ShortDecimal, ShapesAtTheirEdges) {
  const char* const kRead[] = {"0", "-0", "7", ".5", "5.", "-.5", "0.1", "-1.0369235", "0.98092043",
                               "123456789012345", "12345678.9012345", "0.00000000000001", "1e22", "1e-7"};
  for (const char* s : kRead) {
    double v = 0.0;
    const std::string padded = std::string(s) + std::string(16, ' ');
    EXPECT_TRUE(shortDecimalAt(std::string_view(padded.data(), std::strlen(s)), padded.data() + padded.size(), v)) << s;
    EXPECT_EQ(bitsOf(v), bitsOf(std::strtod(s, nullptr))) << s;
  }
  const char* const kLeft[] = {"", "-", ".", "-.", "+1", "1..2", "1-", "1234567890123456", "0.000000000000001",
                               "1f", "0x10", "GL_ONE", "1e", "1e23", "1e1000", "inf", "nan", "--1"};
  for (const char* s : kLeft) {
    double v = 3.0;
    const std::string padded = std::string(s) + std::string(16, '1');
    EXPECT_FALSE(shortDecimalAt(std::string_view(padded.data(), std::strlen(s)), padded.data() + padded.size(), v)) << s;
    EXPECT_EQ(v, 3.0) << s;
  }
  double negativeZero = 1.0;
  const std::string alone = "-0";  // too near its buffer's end: read one by one
  ASSERT_TRUE(shortDecimalAt(alone, alone.data() + alone.size(), negativeZero));
  EXPECT_TRUE(std::signbit(negativeZero));
}

// A token at the very end of its buffer, with fewer than 16 bytes to read,
// is read without a byte past the buffer (AddressSanitizer watches this).
TEST(ShortDecimal, TokenAtTheBuffersEnd) {
  std::mt19937 rng(7);
  for (int i = 0; i < 20000; ++i) {
    const std::string token = randomToken(rng);
    const std::string after(rng() % 16u, '9');
    expectSameReading(token, after);
  }
}

}  // namespace
}  // namespace mpr
