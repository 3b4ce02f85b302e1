#include "util/number_text.hpp"

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstdio>

namespace mpr {
namespace {

template <class T>
std::to_chars_result shortest(char* buf, std::size_t size, T v) {
  return std::to_chars(buf, buf + size, v);
}

}  // namespace

void appendShortest(std::string& out, float v) {
  char buf[64];
  std::to_chars_result r = shortest(buf, sizeof buf, v);
  // The script parser reads a number as a double (strtod) and rounds it to
  // the call's float. The shortest text of a float reads back to that float
  // directly, but through a double it can round twice: of the 4 278 190 080
  // finite floats exactly two, ±7.038531e-26, come back one ulp off. Those
  // are written as their double instead, which reads back exactly.
  double d = 0.0;
  std::from_chars(buf, r.ptr, d);
  if (std::bit_cast<std::uint32_t>(static_cast<float>(d)) != std::bit_cast<std::uint32_t>(v))
    r = shortest(buf, sizeof buf, static_cast<double>(v));
  out.append(buf, r.ptr);
}

void appendShortest(std::string& out, double v) {
  char buf[64];
  const std::to_chars_result r = shortest(buf, sizeof buf, v);
  out.append(buf, r.ptr);
}

void appendInteger(std::string& out, long long v) {
  char buf[32];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

std::string fixedText(double v, int digits) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", digits, v);
  return b;
}

}  // namespace mpr
