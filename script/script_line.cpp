#include "script/script_line.hpp"

#include <bit>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mpr {
namespace {

// Where the token from i ends: the first ' ', '\t' or '#' at or after i, or
// the line's end.
std::size_t tokenEnd(std::string_view line, std::size_t i) {
  while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '#') ++i;
  return i;
}

#if defined(__SSE2__)
// Bit k set where byte k of the 64 in `chunks` is c.
std::uint64_t bytesEqual(const __m128i (&chunks)[4], char c) {
  const __m128i wanted = _mm_set1_epi8(c);
  std::uint64_t mask = 0;
  for (int k = 0; k < 4; ++k)
    mask |= static_cast<std::uint64_t>(static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_cmpeq_epi8(chunks[k], wanted))))
            << (16 * k);
  return mask;
}
#endif

}  // namespace

ScriptLine scriptLineOneByOne(std::string_view text, std::size_t pos, std::vector<ScriptToken>& tokens) {
  std::size_t eol = text.find('\n', pos);
  if (eol == std::string_view::npos) eol = text.size();
  std::string_view line = text.substr(pos, eol - pos);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  tokens.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i >= line.size() || line[i] == '#') break;
    const std::size_t start = i;
    i = tokenEnd(line, i);
    tokens.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
  }
  return {line, eol + 1, eol == text.size()};
}

ScriptLine nextScriptLine(std::string_view text, std::size_t pos, std::vector<ScriptToken>& tokens) {
#if defined(__SSE2__)
  // The bytes of the line and of the tokens as bits of 64-bit words: the
  // line's end is the lowest '\n', a comment cuts at the lowest '#', and a
  // token is a run of bits that are neither space nor tab. One pass of
  // compares instead of a branch per character (the character loops were
  // most of reading a trace).
  if (text.size() - pos >= 64) {
    __m128i chunks[4];
    for (int k = 0; k < 4; ++k)
      chunks[k] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(text.data() + pos + 16 * static_cast<std::size_t>(k)));
    const std::uint64_t newlines = bytesEqual(chunks, '\n');
    if (newlines != 0) {
      const int eol = std::countr_zero(newlines);
      int length = eol;
      if (length > 0 && text[pos + static_cast<std::size_t>(length) - 1] == '\r') --length;
      const std::string_view line = text.substr(pos, static_cast<std::size_t>(length));
      // Bits below the first '#' within the line (length < 64).
      const std::uint64_t inLine = (std::uint64_t{1} << length) - 1;
      const std::uint64_t hashes = bytesEqual(chunks, '#') & inLine;
      const std::uint64_t live = hashes ? (hashes & -hashes) - 1 : inLine;
      const std::uint64_t blanks = bytesEqual(chunks, ' ') | bytesEqual(chunks, '\t');
      const std::uint64_t inToken = ~blanks & live;
      std::uint64_t starts = inToken & ~(inToken << 1);
      std::uint64_t ends = inToken & ~(inToken >> 1);  // each token's last byte
      tokens.clear();
      while (starts != 0) {
        const int first = std::countr_zero(starts), final = std::countr_zero(ends);
        tokens.push_back({line.substr(static_cast<std::size_t>(first), static_cast<std::size_t>(final - first + 1)), first + 1});
        starts &= starts - 1;
        ends &= ends - 1;
      }
      const std::size_t end = pos + static_cast<std::size_t>(eol);
      return {line, end + 1, false};
    }
  }
#endif
  return scriptLineOneByOne(text, pos, tokens);
}

}  // namespace mpr
