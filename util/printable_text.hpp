#pragma once
// Text from a user's file made safe for a terminal: a script or scene may
// hold control characters (escape sequences among them), which an error
// message must not echo raw. They are written as \xNN; tabs and all other
// bytes (UTF-8 included) pass unchanged. A message quoting a huge token (a
// 1 GiB unknown call name) is cut to its first and last few hundred bytes,
// so the place and the reason around the quote are kept.
#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

namespace mpr {

inline constexpr std::size_t kMaxPrintableBytes = 1024;

inline std::string printableText(std::string_view s) {
  static const char* hex = "0123456789abcdef";
  std::string o;
  o.reserve(std::min(s.size(), kMaxPrintableBytes + 64));
  const auto append = [&](std::string_view part) {
    for (const char ch : part) {
      const auto u = static_cast<unsigned char>(ch);
      if ((u < 0x20 && ch != '\t') || u == 0x7f) {
        o += "\\x";
        o += hex[u >> 4];
        o += hex[u & 15];
      } else {
        o += ch;
      }
    }
  };
  if (s.size() <= kMaxPrintableBytes) {
    append(s);
    return o;
  }
  // Cuts moved back to the start of a UTF-8 sequence, never inside one.
  const auto boundary = [&](std::size_t i) {
    while (i > 0 && (static_cast<unsigned char>(s[i]) & 0xc0) == 0x80) --i;
    return i;
  };
  const std::size_t head = boundary(600), tail = boundary(s.size() - 300);
  append(s.substr(0, head));
  o += " ... (" + std::to_string(tail - head) + " bytes left out) ... ";
  append(s.substr(tail));
  return o;
}

}  // namespace mpr
