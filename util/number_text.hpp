#pragma once
// Numbers as a GL script writes them: the shortest decimal text that reads
// back (strtod, then rounded to the call's own type) as the very same value,
// by std::to_chars. tests/util/number_text_test.cpp proves the round trip on
// every class of float and double bit pattern.
#include <string>

namespace mpr {

void appendShortest(std::string& out, float v);
void appendShortest(std::string& out, double v);
void appendInteger(std::string& out, long long v);

inline std::string shortestText(float v) { std::string s; appendShortest(s, v); return s; }
inline std::string shortestText(double v) { std::string s; appendShortest(s, v); return s; }

}  // namespace mpr
