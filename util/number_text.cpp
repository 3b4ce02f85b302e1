#include "util/number_text.hpp"

#include <charconv>

namespace mpr {
namespace {

template <class T>
void append(std::string& out, T v) {
  char buf[64];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

}  // namespace

void appendShortest(std::string& out, float v) { append(out, v); }
void appendShortest(std::string& out, double v) { append(out, v); }
void appendInteger(std::string& out, long long v) { append(out, v); }

}  // namespace mpr
