#pragma once
// Text from a user's file made safe for a terminal: a script or scene may
// hold control characters (escape sequences among them), which an error
// message must not echo raw. They are written as \xNN; tabs and all other
// bytes (UTF-8 included) pass unchanged.
#include <string>
#include <string_view>

namespace mpr {

inline std::string printableText(std::string_view s) {
  static const char* hex = "0123456789abcdef";
  std::string o;
  o.reserve(s.size());
  for (const char ch : s) {
    const auto u = static_cast<unsigned char>(ch);
    if ((u < 0x20 && ch != '\t') || u == 0x7f) {
      o += "\\x";
      o += hex[u >> 4];
      o += hex[u & 15];
    } else {
      o += ch;
    }
  }
  return o;
}

}  // namespace mpr
