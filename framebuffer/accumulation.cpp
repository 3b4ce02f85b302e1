#include "framebuffer/accumulation.hpp"

#include <array>

#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "framebuffer/fragment_ops.hpp"

namespace mpr {
namespace {

// C's (GLshort)(float) on x86-64: cvttss2si to a 32-bit integer (0x80000000 for
// out-of-range and NaN), then the low 16 bits. Mesa relies on this conversion.
std::int32_t truncToInt32(float f) {
  if (!(f > -2147483648.0f && f < 2147483648.0f)) return INT32_MIN;
  return static_cast<std::int32_t>(f);
}

std::int16_t wrap16(std::int64_t v) { return static_cast<std::int16_t>(static_cast<std::uint16_t>(v & 0xFFFF)); }

std::int16_t saturate16(std::int64_t v) {
  return static_cast<std::int16_t>(v < -32768 ? -32768 : (v > 32767 ? 32767 : v));
}

// A word produced by a product: truncated as Mesa does, then wrapped or clamped.
std::int16_t productWord(float f, bool wraps) {
  if (wraps) return wrap16(truncToInt32(f));
  if (std::isnan(f)) return 0;
  const float t = std::trunc(f);
  return saturate16(t < -40000.0f ? -40000 : (t > 40000.0f ? 40000 : static_cast<std::int64_t>(t)));
}

std::int16_t sumWord(std::int32_t a, std::int32_t b, bool wraps) {
  return wraps ? wrap16(std::int64_t{a} + b) : saturate16(std::int64_t{a} + b);
}

// Mesa's _mesa_float_to_unorm(x, 8): clamp, scale, round half to even.
std::uint8_t unitToUnorm8(float x) {
  if (!(x >= 0.0f)) return 0;
  if (x > 1.0f) return 255;
  return static_cast<std::uint8_t>(roundNonNegative(x * 255.0f));
}

// GL_ACCUM and GL_LOAD over the rows of r, the state's switches (which
// operation, wrapping or saturating sums, three or four words) taken once
// rather than per channel: a plain loop along each row's words.
template <bool kLoad, bool kWraps, int kChannels>
void accumulateBytes(Framebuffer& fb, const PixelRect& r, const std::array<std::int16_t, 256>& word) {
  const int width = r.x1 - r.x0;
  for (int y = r.y0; y < r.y1; ++y) {
    std::int16_t* a = fb.accum(r.x0, y);
    const Rgba8* col = &fb.color(r.x0, y);
    for (int i = 0; i < width; ++i)
      for (int c = 0; c < kChannels; ++c) {
        const std::int16_t w = word[col[i][c]];
        a[4 * i + c] = kLoad ? w : sumWord(a[4 * i + c], w, kWraps);
      }
  }
}

#if defined(__SSE2__)
// The same for a finite scale, eight words (two pixels) at a time: each
// colour byte's product computed as the table's entry is, in the same IEEE
// single-precision steps, (byte * toUnit) * scale, instead of looked up
// word by word. cvttps2dq is truncToInt32 itself (0x80000000 out of
// range); wrapping keeps its low 16 bits, saturating clamps the product to
// +-40000 first and packs with signed saturation, as productWord does (no
// NaN arises: the bytes and the scale are finite; an infinite product
// clamps or truncates as productWord's). The sums are paddw (wrapping) and
// paddsw (saturating), sumWord's. Indigo's alpha word is kept.
template <bool kWraps>
__m128i productWords(__m128i bytes, __m128 toUnit, __m128 scale) {
  const __m128i zero = _mm_setzero_si128();
  const __m128i words = _mm_unpacklo_epi8(bytes, zero);
  __m128 lo = _mm_mul_ps(_mm_mul_ps(_mm_cvtepi32_ps(_mm_unpacklo_epi16(words, zero)), toUnit), scale);
  __m128 hi = _mm_mul_ps(_mm_mul_ps(_mm_cvtepi32_ps(_mm_unpackhi_epi16(words, zero)), toUnit), scale);
  if (!kWraps) {
    const __m128 top = _mm_set1_ps(40000.0f), bottom = _mm_set1_ps(-40000.0f);
    lo = _mm_min_ps(_mm_max_ps(lo, bottom), top);
    hi = _mm_min_ps(_mm_max_ps(hi, bottom), top);
  }
  __m128i ilo = _mm_cvttps_epi32(lo), ihi = _mm_cvttps_epi32(hi);
  if (kWraps) {  // the low 16 bits, sign-extended, so that the pack below is exact
    ilo = _mm_srai_epi32(_mm_slli_epi32(ilo, 16), 16);
    ihi = _mm_srai_epi32(_mm_slli_epi32(ihi, 16), 16);
  }
  return _mm_packs_epi32(ilo, ihi);
}

template <bool kLoad, bool kWraps, int kChannels>
__m128i accumulatedWords(__m128i old, __m128i product) {
  __m128i result = kLoad ? product : (kWraps ? _mm_add_epi16(old, product) : _mm_adds_epi16(old, product));
  if (kChannels == 3) {
    const __m128i rgb = _mm_set_epi16(0, -1, -1, -1, 0, -1, -1, -1);
    result = _mm_or_si128(_mm_and_si128(rgb, result), _mm_andnot_si128(rgb, old));
  }
  return result;
}

template <bool kLoad, bool kWraps, int kChannels>
void accumulateComputed(Framebuffer& fb, const PixelRect& r, float unit, float scaleValue) {
  const __m128 toUnit = _mm_set1_ps(unit), scale = _mm_set1_ps(scaleValue);
  const int width = r.x1 - r.x0;
  for (int y = r.y0; y < r.y1; ++y) {
    std::int16_t* a = fb.accum(r.x0, y);
    const std::uint8_t* col = fb.color(r.x0, y).data();
    int i = 0;
    for (; i + 2 <= width; i += 2) {
      const __m128i bytes = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(col + 4 * i));
      const __m128i product = productWords<kWraps>(bytes, toUnit, scale);
      __m128i* at = reinterpret_cast<__m128i*>(a + 4 * i);
      _mm_storeu_si128(at, accumulatedWords<kLoad, kWraps, kChannels>(_mm_loadu_si128(at), product));
    }
    if (i < width) {  // the last pixel of an odd row
      std::int32_t bytes;
      std::memcpy(&bytes, col + 4 * i, 4);
      const __m128i product = productWords<kWraps>(_mm_cvtsi32_si128(bytes), toUnit, scale);
      __m128i* at = reinterpret_cast<__m128i*>(a + 4 * i);
      _mm_storel_epi64(at, accumulatedWords<kLoad, kWraps, kChannels>(_mm_loadl_epi64(at), product));
    }
  }
}

template <bool kLoad>
void accumulateComputed(Framebuffer& fb, const PixelRect& r, float unit, float scale, bool wraps, int channels) {
  if (wraps) {
    if (channels == 4) accumulateComputed<kLoad, true, 4>(fb, r, unit, scale);
    else accumulateComputed<kLoad, true, 3>(fb, r, unit, scale);
  } else {
    if (channels == 4) accumulateComputed<kLoad, false, 4>(fb, r, unit, scale);
    else accumulateComputed<kLoad, false, 3>(fb, r, unit, scale);
  }
}
#endif

template <bool kLoad>
void accumulateBytes(Framebuffer& fb, const PixelRect& r, const std::array<std::int16_t, 256>& word, bool wraps,
                     int channels) {
  if (wraps) {
    if (channels == 4) accumulateBytes<kLoad, true, 4>(fb, r, word);
    else accumulateBytes<kLoad, true, 3>(fb, r, word);
  } else {
    if (channels == 4) accumulateBytes<kLoad, false, 4>(fb, r, word);
    else accumulateBytes<kLoad, false, 3>(fb, r, word);
  }
}

}  // namespace

std::int16_t accumClearWord(float v) {
  // Mesa's FLOAT_TO_SHORT: ((int)(65535 * x) - 1) / 2, integer division.
  const std::int32_t t = static_cast<std::int32_t>(65535.0f * v);
  return static_cast<std::int16_t>((t - 1) / 2);
}

void accumulate(Framebuffer& fb, const PixelRect& region, AccumOp op, float value,
                const std::array<bool, 4>& colorMask) {
  const PixelRect r = region.intersect(fb.bounds());
  if (r.empty()) return;
  const bool wraps = fb.profile().accumArithmetic == AccumulationArithmetic::MesaWrap;
  const int channels = fb.profile().accumHasAlpha ? 4 : 3;

  // Mesa skips the identity operations entirely; the result is the same.
  switch (op) {
    case AccumOp::Add: {
      if (value == 0.0f) return;
      const std::int16_t incr = productWord(value * 32767.0f, wraps);
      for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) {
          std::int16_t* a = fb.accum(x, y);
          for (int c = 0; c < channels; ++c) a[c] = sumWord(a[c], incr, wraps);
        }
      return;
    }
    case AccumOp::Mult: {
      if (value == 1.0f) return;
      for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) {
          std::int16_t* a = fb.accum(x, y);
          for (int c = 0; c < channels; ++c) a[c] = productWord(static_cast<float>(a[c]) * value, wraps);
        }
      return;
    }
    case AccumOp::Accum:
    case AccumOp::Load: {
      if (op == AccumOp::Accum && value == 0.0f) return;
      const float scale = value * 32767.0f;
      const float toUnit = 1.0f / 255.0f;
#if defined(__SSE2__)
      if (std::isfinite(scale)) {
        if (op == AccumOp::Load) accumulateComputed<true>(fb, r, toUnit, scale, wraps, channels);
        else accumulateComputed<false>(fb, r, toUnit, scale, wraps, channels);
        return;
      }
#endif
      // The product depends on the colour byte alone: its 256 words once,
      // then a lookup per channel.
      std::array<std::int16_t, 256> word;
      for (int v = 0; v < 256; ++v) word[v] = productWord(static_cast<float>(v) * toUnit * scale, wraps);
      if (op == AccumOp::Load) accumulateBytes<true>(fb, r, word, wraps, channels);
      else accumulateBytes<false>(fb, r, word, wraps, channels);
      return;
    }
    case AccumOp::Return: {
      const float scale = value / 32767.0f;
      for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) {
          const std::int16_t* a = fb.accum(x, y);
          Rgba8& col = fb.color(x, y);
          for (int c = 0; c < 4; ++c) {
            // An RGB-only buffer has no alpha word to return: destination
            // alpha is left as it is (indigo).
            if (!colorMask[c] || c >= channels) continue;
            col[c] = unitToUnorm8(static_cast<float>(a[c]) * scale);
          }
        }
      return;
    }
  }
}

}  // namespace mpr
