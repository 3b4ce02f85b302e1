#pragma once
// The byte and text formats of the stepper page's data files, which its
// script (web/stepper.js) decodes: zlib streams (the browser's
// DecompressionStream("deflate") reads them), base64, LEB128 varints and
// JavaScript string literals.
#include <cstdint>
#include <string>
#include <string_view>

namespace mpr::cli {

// RFC 1950 zlib stream at `level` (1 fast .. 9 small); the same bytes on every run.
std::string zlibCompress(std::string_view bytes, int level = 6);
std::string base64(std::string_view bytes);
// A double-quoted JavaScript (and JSON) string literal; "</" is escaped so
// the text can never close a <script> element.
std::string jsString(std::string_view text);

// Unsigned LEB128.
inline void putVarint(std::string& out, std::uint64_t v) {
  while (v >= 0x80) {
    out.push_back(static_cast<char>((v & 0x7f) | 0x80));
    v >>= 7;
  }
  out.push_back(static_cast<char>(v));
}
// Signed values as unsigned varints: 0, -1, 1, -2, ... -> 0, 1, 2, 3, ...
inline void putSigned(std::string& out, std::int64_t v) {
  putVarint(out, (static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63));
}

}  // namespace mpr::cli
