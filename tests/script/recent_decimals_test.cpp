// RecentDecimals gives shortDecimalAt's answer, to the bit, whether a token
// is read for the first time or found in its table: on a stream of tokens
// drawn from a small set (so most come back, and with 2 048 slots many
// share one), each followed in its buffer by other bytes, and on tokens that
// differ from one another only in their length or in one byte.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "script/recent_decimals.hpp"
#include "script/short_decimal.hpp"

namespace mpr {
namespace {

std::uint64_t bitsOf(double v) { return std::bit_cast<std::uint64_t>(v); }

// `token` read at the start of a buffer followed by `after`: RecentDecimals
// and shortDecimalAt agree on the answer and the double.
void expectSameAsShortDecimal(RecentDecimals& recent, const std::string& token, const std::string& after) {
  const std::string buffer = token + after;
  const std::string_view t(buffer.data(), token.size());
  const char* limit = buffer.data() + buffer.size();
  double expected = 777.0, got = 777.0;
  const bool expectedRead = shortDecimalAt(t, limit, expected);
  const bool gotRead = recent.read(t, limit, got);
  ASSERT_EQ(gotRead, expectedRead) << "'" << token << "' then '" << after << "'";
  if (expectedRead) EXPECT_EQ(bitsOf(got), bitsOf(expected)) << "'" << token << "'";
  else EXPECT_EQ(bitsOf(got), bitsOf(777.0)) << "'" << token << "' refused, value untouched";
}

TEST(RecentDecimals, RepeatedTokensGiveShortDecimalsDoubles) {
  std::mt19937 rng(1414);
  auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  // Five thousand distinct-ish tokens: more than the table's slots.
  std::vector<std::string> tokens;
  for (int i = 0; i < 5000; ++i) {
    std::string t = pick(2) ? "-" : "";
    const int digits = 1 + pick(15);
    const int point = pick(4) ? pick(digits + 1) : -1;
    for (int d = 0; d < digits; ++d) {
      if (d == point) t += '.';
      t += static_cast<char>('0' + pick(10));
    }
    if (pick(30) == 0) t += "e-3";  // read by plainShortDecimal
    if (pick(40) == 0) t += "x";    // refused
    tokens.push_back(t);
  }
  static const char* const kAfter[] = {" 1.5 2.25\n", "\n", "0000000000000000", "", " -7\nglVertex3f 1 2 3\n"};
  RecentDecimals recent;
  for (int i = 0; i < 200000; ++i) {
    // Mostly a recent token (the way a trace repeats its numbers).
    const std::size_t at = pick(8) ? static_cast<std::size_t>(pick(64)) : static_cast<std::size_t>(pick(5000));
    expectSameAsShortDecimal(recent, tokens[at], kAfter[pick(5)]);
    if (HasFailure()) return;
  }
}

TEST(RecentDecimals, TokensThatDifferInLengthOrOneByteAreNotConfused) {
  RecentDecimals recent;
  const char* const kTokens[] = {"1",    "10",   "1.",   "1.0",  "1.00", "-1",         "-1.0",        "0.1",
                                 "0.10", "0.01", "1.5",  "1.50", "15",   "1234567.5",  "1234567.50",  "1234567.51",
                                 "0",    "-0",   "0.0",  "-0.0", "7",    "9999999999", "99999999999", "0.3333333333333333"};
  for (int round = 0; round < 3; ++round)
    for (const char* t : kTokens)
      for (const char* after : {"", "0", "5 6", "\n"}) expectSameAsShortDecimal(recent, t, after);
  // A token with a byte the table would zero (a NUL in the text) is not the
  // shorter token.
  expectSameAsShortDecimal(recent, std::string("1\0", 2), " 2");
  expectSameAsShortDecimal(recent, "1", " 2");
}

}  // namespace
}  // namespace mpr
