#pragma once
// The numbers of a GL script, read as from_chars reads them (correctly
// rounded doubles) when they are short plain decimals, which is most of the
// numbers a trace holds: three to a glVertex3f line, millions to a trace.
#include <string_view>

namespace mpr {

// [-]digits[.digits][(e|E)[+|-]digits] with at most 15 significant digits
// written and a decimal exponent (the exponent less the fraction's length)
// within [-22, 22]: the digits are an integer w below 10^15 < 2^53, and w
// and 10^|q| are exact doubles, so w * 10^q or w / 10^-q, one IEEE
// operation, is the correctly rounded value from_chars gives (Clinger's fast
// path). False, `value` untouched, for anything else (a name, a '+', hex, a
// suffix, more digits): the caller's general reading decides those.
bool plainShortDecimal(std::string_view t, double& value);

// plainShortDecimal for a token whose text is followed, within the same
// buffer, by at least 16 - size readable bytes (`limit` is the buffer's end):
// the token is read as one 16-byte vector, its digits found by compares and
// combined eight at a time, with no branch per character. The same answer
// as plainShortDecimal for every token (tests/pipeline/short_decimal_test.cpp);
// a token with an exponent, or too near `limit`, is read by it.
bool shortDecimalAt(std::string_view t, const char* limit, double& value);

}  // namespace mpr
