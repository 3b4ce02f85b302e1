#pragma once
// Numbers as a GL script writes them: the shortest decimal text (std::to_chars)
// that reads back as the script parser reads it (strtod, then rounded to the
// call's own type) to the very same value. tests/util/number_text_test.cpp
// proves the round trip on every class of float and double bit pattern and
// on every subnormal float; every one of the 2^32 float patterns was checked
// once by hand (the two that need more digits are in the test).
#include <string>

namespace mpr {

void appendShortest(std::string& out, float v);
void appendShortest(std::string& out, double v);
void appendInteger(std::string& out, long long v);

inline std::string shortestText(float v) { std::string s; appendShortest(s, v); return s; }
inline std::string shortestText(double v) { std::string s; appendShortest(s, v); return s; }

// `digits` digits after the point (printf's %.*f), for reports and messages.
std::string fixedText(double v, int digits);

}  // namespace mpr
