#include "script/recent_lines.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mpr {

#if defined(__SSE2__)
const RecentLines::Entry* RecentLines::find(std::string_view text, std::size_t pos) {
  pending_.size = 0;
  if (text.size() - pos < 64) return nullptr;
  const char* p = text.data() + pos;
  __m128i chunks[4];
  std::uint64_t newlines = 0;
  const __m128i newline = _mm_set1_epi8('\n');
  for (int k = 0; k < 4; ++k) {
    chunks[k] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + 16 * k));
    newlines |= static_cast<std::uint64_t>(static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_cmpeq_epi8(chunks[k], newline))))
                << (16 * k);
  }
  if (newlines == 0) return nullptr;  // longer than kMaxBytes
  const int n = std::countr_zero(newlines);
  if (n == 0) return nullptr;  // an empty line
  // The bytes from the '\n' on zeroed: n bytes of 0xFF then zeros, read
  // from a row of 64 of each.
  static constexpr unsigned char kMask[128] = {
      0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
      0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
      0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
      0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
  // Each 8 bytes times its own odd constant, the products summed: eight
  // multiplies side by side rather than one chain of them.
  static constexpr std::uint64_t kOdd[8] = {0x9E3779B97F4A7C15ull, 0xC2B2AE3D27D4EB4Full, 0x165667B19E3779F9ull,
                                            0xD6E8FEB86659FD93ull, 0xFF51AFD7ED558CCDull, 0xC4CEB9FE1A85EC53ull,
                                            0x85EBCA77C2B2AE63ull, 0x27D4EB2F165667C5ull};
  std::uint64_t hash = static_cast<std::uint64_t>(n);
  for (int k = 0; k < 4; ++k) {
    chunks[k] = _mm_and_si128(chunks[k], _mm_loadu_si128(reinterpret_cast<const __m128i*>(kMask + 64 - n + 16 * k)));
    const auto low = static_cast<std::uint64_t>(_mm_cvtsi128_si64(chunks[k]));
    const auto high = static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_unpackhi_epi64(chunks[k], chunks[k])));
    hash += low * kOdd[2 * k] + high * kOdd[2 * k + 1];
  }
  hash ^= hash >> 31;
  if (!entries_) entries_ = std::make_unique<Entry[]>(std::size_t{1} << kSlotBits);
  Entry& e = entries_[hash >> (64 - kSlotBits)];
  if (e.size == static_cast<std::uint32_t>(n)) {
    int same = 0xFFFF;
    for (int k = 0; k < 4; ++k)
      same &= _mm_movemask_epi8(_mm_cmpeq_epi8(chunks[k], _mm_load_si128(reinterpret_cast<const __m128i*>(e.bytes + 16 * k))));
    if (same == 0xFFFF) return &e;
  }
  for (int k = 0; k < 4; ++k) _mm_store_si128(reinterpret_cast<__m128i*>(pending_.bytes + 16 * k), chunks[k]);
  pending_.size = static_cast<std::uint32_t>(n);
  pendingSlot_ = &e;
  return nullptr;
}
#else
const RecentLines::Entry* RecentLines::find(std::string_view, std::size_t) { return nullptr; }
#endif

void RecentLines::keep(GLCall call, std::span<const ScriptArg> args) {
  if (pending_.size == 0 || args.size() > kMaxArgs) return;
  Entry& e = *pendingSlot_;
  std::memcpy(e.bytes, pending_.bytes, sizeof e.bytes);
  e.size = pending_.size;
  e.call = call;
  e.argCount = static_cast<std::uint8_t>(args.size());
  std::copy(args.begin(), args.end(), e.args);
  pending_.size = 0;
}

}  // namespace mpr
