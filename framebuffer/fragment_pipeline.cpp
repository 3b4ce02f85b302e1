#include "framebuffer/fragment_pipeline.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "framebuffer/fragment_span_stages.hpp"
#include "util/cpu_dispatch.hpp"

namespace mpr {
namespace {

enum class ColorWrites { None, All, Some };

// processFragment (fragment_ops.cpp) with its state switches decided at
// compile time, on the pixel's three buffer cells.
template <bool kAlpha, bool kStencil, bool kDepth, bool kBlend, ColorWrites kColor>
[[gnu::always_inline]] inline FragmentFate specialisedAt(const FragmentState& s, std::uint32_t stencilMax,
                                                         std::uint8_t* st, std::uint32_t* z, Rgba8* dst,
                                                         std::uint32_t depth, Rgba8 color, float alpha) {
  if constexpr (kAlpha)
    if (!alphaTestPasses(s.alpha, alpha)) return FragmentFate::AlphaFailed;
  if constexpr (kStencil) {
    if (!stencilTest(s.stencil, *st)) {
      *st = static_cast<std::uint8_t>(applyStencilOp(s.stencil.sfail, *st, s.stencil, stencilMax));
      return FragmentFate::StencilFailed;
    }
  }
  if constexpr (kDepth) {
    if (!compare(s.depth.func, depth, *z)) {
      if constexpr (kStencil)
        *st = static_cast<std::uint8_t>(applyStencilOp(s.stencil.dpfail, *st, s.stencil, stencilMax));
      return FragmentFate::DepthFailed;
    }
    if (s.depth.writeMask) *z = depth;
  }
  if constexpr (kStencil)
    *st = static_cast<std::uint8_t>(applyStencilOp(s.stencil.dppass, *st, s.stencil, stencilMax));

  if constexpr (kColor != ColorWrites::None) {
    Rgba8 src = color;
    if constexpr (kBlend) src = blend(s.blend, color, *dst);
    if constexpr (kColor == ColorWrites::All) {
      *dst = src;
    } else {
      for (int c = 0; c < 4; ++c)
        if (s.colorMask[c]) (*dst)[c] = src[c];
    }
  }
  return FragmentFate::Written;
}

template <bool kAlpha, bool kStencil, bool kDepth, bool kBlend, ColorWrites kColor>
FragmentFate specialised(const FragmentState& s, Framebuffer& fb, const Fragment& f) {
  return specialisedAt<kAlpha, kStencil, kDepth, kBlend, kColor>(
      s, fb.profile().stencilMax(), &fb.stencil(f.x, f.y), &fb.depth(f.x, f.y), &fb.color(f.x, f.y), f.depth, f.color,
      f.alpha);
}

// The same over a span, stage by stage as GL orders them (span::*, one
// state switch per stage and span): which fragments pass each test is
// decided for the whole span, then stencil, depth and colour are written
// where the fragment-by-fragment run would write them. The pixels of a span
// are distinct, so no fragment sees another's writes either way.
// kLanes: 0 for any span, or a span of at most kLanes fragments run over
// exactly kLanes lanes (loops of a constant count: most spans of a trace
// are a few pixels, and a loop's set-up cost more than its body).
template <bool kAlpha, bool kStencil, bool kDepth, bool kBlend, ColorWrites kColor, int kLanes>
[[gnu::always_inline]] inline std::uint32_t spanBody(const FragmentState& s, Framebuffer& fb, const FragmentSpan& span) {
  constexpr int N = kLanes > 0 ? kLanes : FragmentSpan::kCapacity;
  const int n = span.count;
  // The tests and operations run over whole vectors of lanes (paddedLanes):
  // the span's lanes past n are defined (FragmentSpan), the buffers' cells
  // are read into arrays whose lanes past n are zeroed (not all of it: a
  // memset of the whole array is a `rep stos`, slower than the loops it
  // saves), and only the n pixels are counted and written.
  const int lanes = kLanes > 0 ? kLanes : paddedLanes(n);
  std::uint8_t* const st = &fb.stencil(span.x, span.y);
  std::uint32_t* const z = &fb.depth(span.x, span.y);
  Rgba8* const dst = &fb.color(span.x, span.y);

  alignas(64) std::uint32_t alive[N];  // past the alpha test
  if constexpr (kAlpha) {
    alignas(64) std::uint32_t a8[N];
    for (int k = 0; k < lanes; ++k) a8[k] = floatToUnorm8(span.alpha[k]);
    const std::uint32_t ref = floatToUnorm8(s.alpha.ref);
    span::compare(s.alpha.func, lanes, [&](int k) { return a8[k]; }, [&](int) { return ref; }, alive);
  } else {
    for (int k = 0; k < lanes; ++k) alive[k] = 1;
  }

  alignas(64) std::uint32_t stored[N], stencilPass[N];
  if constexpr (kStencil) {
    for (int k = 0; k < n; ++k) stored[k] = st[k];
    for (int k = n; k < lanes; ++k) stored[k] = 0;
    const std::uint32_t mask = s.stencil.valueMask, ref = s.stencil.ref & mask;
    span::compare(s.stencil.func, lanes, [&](int) { return ref; }, [&](int k) { return stored[k] & mask; }, stencilPass);
  } else {
    for (int k = 0; k < lanes; ++k) stencilPass[k] = 1;
  }

  alignas(64) std::uint32_t depthPass[N];
  if constexpr (kDepth) {
    alignas(64) std::uint32_t zStored[N];
    for (int k = 0; k < n; ++k) zStored[k] = z[k];
    for (int k = n; k < lanes; ++k) zStored[k] = 0;
    span::compare(s.depth.func, lanes, [&](int k) { return span.depth[k]; }, [&](int k) { return zStored[k]; }, depthPass);
  } else {
    for (int k = 0; k < lanes; ++k) depthPass[k] = 1;
  }

  alignas(64) std::uint32_t written[N];
  std::uint32_t count = 0;
  for (int k = 0; k < lanes; ++k) {
    written[k] = alive[k] & stencilPass[k] & depthPass[k] & static_cast<std::uint32_t>(k < n);
    count += written[k];
  }

  if constexpr (kStencil) {
    // sfail where the stencil test failed, dpfail where the depth test did,
    // dppass where both passed; a fragment the alpha test killed leaves it.
    const std::uint32_t max = fb.profile().stencilMax(), m = s.stencil.writeMask & max, ref = s.stencil.ref;
    alignas(64) std::uint32_t onFail[N], onDepthFail[N], onPass[N], next[N];
    span::stencilOpValues(s.stencil.sfail, lanes, stored, ref, max, onFail);
    span::stencilOpValues(s.stencil.dpfail, lanes, stored, ref, max, onDepthFail);
    span::stencilOpValues(s.stencil.dppass, lanes, stored, ref, max, onPass);
    for (int k = 0; k < lanes; ++k) {
      const std::uint32_t v = !alive[k] ? stored[k] : !stencilPass[k] ? onFail[k] : !depthPass[k] ? onDepthFail[k] : onPass[k];
      next[k] = (stored[k] & ~m) | (v & m);
    }
    for (int k = 0; k < n; ++k) st[k] = static_cast<std::uint8_t>(next[k]);
  }
  if constexpr (kDepth) {
    if (s.depth.writeMask)
      for (int k = 0; k < n; ++k) z[k] = written[k] ? span.depth[k] : z[k];
  }

  if constexpr (kColor != ColorWrites::None) {
    // Copied word by word in loops (built with -fno-tree-loop-distribute-patterns,
    // so they stay loops): a memcpy of n words is a library call per span.
    alignas(64) std::uint32_t src32[N], dst32[N];
    for (int k = 0; k < lanes; ++k) std::memcpy(&src32[k], &span.color[k], sizeof(Rgba8));
    for (int k = 0; k < n; ++k) std::memcpy(&dst32[k], &dst[k], sizeof(Rgba8));
    for (int k = n; k < lanes; ++k) dst32[k] = 0;
    if constexpr (kBlend) span::blendWords<N>(s.blend, lanes, src32, dst32, src32);
    std::uint32_t keep = 0;  // the bits of each word the colour mask writes
    for (int c = 0; c < 4; ++c)
      if (kColor == ColorWrites::All || s.colorMask[c]) keep |= 0xFFu << span::channelShift(c);
    for (int k = 0; k < lanes; ++k) dst32[k] = written[k] ? (dst32[k] & ~keep) | (src32[k] & keep) : dst32[k];
    for (int k = 0; k < n; ++k) std::memcpy(&dst[k], &dst32[k], sizeof(Rgba8));
  }
  return count;
}

template <bool kAlpha, bool kStencil, bool kDepth, bool kBlend, ColorWrites kColor>
MPR_CPU_CLONES std::uint32_t specialisedSpan(const FragmentState& s, Framebuffer& fb, const FragmentSpan& span) {
  if (span.count <= 8) return spanBody<kAlpha, kStencil, kDepth, kBlend, kColor, 8>(s, fb, span);
  return spanBody<kAlpha, kStencil, kDepth, kBlend, kColor, 0>(s, fb, span);
}

// Whether the stencil test passes for any of the `count` bytes at st, the
// test as span::compare takes it (ref OP stored & mask).
bool anyStencilPasses(const StencilState& s, const std::uint8_t* st, int count, int x, int width) {
  const std::uint32_t mask = s.valueMask, ref = s.ref & mask;
#if defined(__SSE2__)
  // Sixteen bytes at a time: the tests as unsigned byte compares (a >= b is
  // max(a, b) == a). The loads stay in the span's row, which its thread
  // owns: a span shorter than sixteen is read with the bytes before it (or
  // after it, at the row's left edge) and those lanes masked off; a longer
  // one ends with the sixteen bytes before its end, overlapping.
  // (A stored byte's bits above 8 are zero: the mask's there change nothing.)
  if (ref <= 0xFF && width >= 16) {
    const __m128i m = _mm_set1_epi8(static_cast<char>(mask & 0xFF)), r = _mm_set1_epi8(static_cast<char>(ref));
    const auto passes = [&](__m128i v) {
      v = _mm_and_si128(v, m);
      const auto ge = [](__m128i a, __m128i b) { return _mm_cmpeq_epi8(_mm_max_epu8(a, b), a); };
      switch (s.func) {
        case CompareFunc::Never: return 0;
        case CompareFunc::Less: return ~_mm_movemask_epi8(ge(r, v)) & 0xFFFF;
        case CompareFunc::Equal: return _mm_movemask_epi8(_mm_cmpeq_epi8(r, v));
        case CompareFunc::Lequal: return _mm_movemask_epi8(ge(v, r));
        case CompareFunc::Greater: return ~_mm_movemask_epi8(ge(v, r)) & 0xFFFF;
        case CompareFunc::Notequal: return ~_mm_movemask_epi8(_mm_cmpeq_epi8(r, v)) & 0xFFFF;
        case CompareFunc::Gequal: return _mm_movemask_epi8(ge(r, v));
        case CompareFunc::Always: return 0xFFFF;
      }
      return 0xFFFF;  // (not reached: the state holds one of the eight)
    };
    const auto load = [](const std::uint8_t* p) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p)); };
    if (count < 16) {
      const int before = std::min(x, 16 - count);  // bytes of the row read before the span
      const int lanes = ((1 << count) - 1) << before;
      return (passes(load(st - before)) & lanes) != 0;
    }
    int k = 0;
    for (; k + 16 <= count; k += 16)
      if (passes(load(st + k))) return true;
    return k < count && passes(load(st + count - 16)) != 0;
  }
#else
  (void)x;
  (void)width;
#endif
  bool any = false;
  for (int k = 0; k < count; ++k) any = any || compare(s.func, ref, static_cast<std::uint32_t>(st[k]) & mask);
  return any;
}

// The stencil-fail operation on `count` bytes at st (a call of its own: its
// arrays would otherwise give every rejection test a frame of them).
[[gnu::noinline]] void applyStencilFail(const StencilState& s, std::uint32_t max, std::uint8_t* st, int count) {
  constexpr int N = FragmentSpan::kCapacity;
  const std::uint32_t m = s.writeMask & max;
  alignas(64) std::uint32_t stored[N], onFail[N];
  for (int k = 0; k < count; ++k) stored[k] = st[k];
  span::stencilOpValues(s.sfail, count, stored, s.ref, max, onFail);
  for (int k = 0; k < count; ++k) st[k] = static_cast<std::uint8_t>((stored[k] & ~m) | (onFail[k] & m));
}

// spanBody's stencil stage alone, for fragments not yet shaded: in the
// passes of a mirror's or a shadow's level most of a scene's triangles fall
// where the stencil holds another level, and their shading is wasted.
bool stencilRejectsAll(const FragmentState& s, Framebuffer& fb, int x, int y, int count) {
  std::uint8_t* const st = &fb.stencil(x, y);
  if (anyStencilPasses(s.stencil, st, count, x, fb.width())) return false;
  const std::uint32_t max = fb.profile().stencilMax();
  if (s.stencil.sfail != StencilOp::Keep && (s.stencil.writeMask & max) != 0) applyStencilFail(s.stencil, max, st, count);
  return true;
}

template <bool kAlpha, bool kStencil, bool kDepth, bool kBlend, ColorWrites kColor>
constexpr FragmentPipeline kPipeline{specialised<kAlpha, kStencil, kDepth, kBlend, kColor>,
                                     specialisedSpan<kAlpha, kStencil, kDepth, kBlend, kColor>,
                                     kStencil && !kAlpha ? stencilRejectsAll : nullptr};

template <bool kAlpha, bool kStencil, bool kDepth, bool kBlend>
FragmentPipeline byColor(ColorWrites c) {
  switch (c) {
    case ColorWrites::None: return kPipeline<kAlpha, kStencil, kDepth, kBlend, ColorWrites::None>;
    case ColorWrites::All: return kPipeline<kAlpha, kStencil, kDepth, kBlend, ColorWrites::All>;
    case ColorWrites::Some: break;
  }
  return kPipeline<kAlpha, kStencil, kDepth, kBlend, ColorWrites::Some>;
}

template <bool kAlpha, bool kStencil, bool kDepth>
FragmentPipeline byBlend(const FragmentState& s, ColorWrites c) {
  return s.blend.enabled ? byColor<kAlpha, kStencil, kDepth, true>(c) : byColor<kAlpha, kStencil, kDepth, false>(c);
}

template <bool kAlpha, bool kStencil>
FragmentPipeline byDepth(const FragmentState& s, ColorWrites c) {
  return s.depth.enabled ? byBlend<kAlpha, kStencil, true>(s, c) : byBlend<kAlpha, kStencil, false>(s, c);
}

template <bool kAlpha>
FragmentPipeline byStencil(const FragmentState& s, ColorWrites c) {
  return s.stencil.enabled ? byDepth<kAlpha, true>(s, c) : byDepth<kAlpha, false>(s, c);
}

}  // namespace

FragmentPipeline chooseFragmentPipeline(const FragmentState& s) {
  const int written = s.colorMask[0] + s.colorMask[1] + s.colorMask[2] + s.colorMask[3];
  const ColorWrites c = written == 0 ? ColorWrites::None : written == 4 ? ColorWrites::All : ColorWrites::Some;
  return s.alpha.enabled ? byStencil<true>(s, c) : byStencil<false>(s, c);
}

}  // namespace mpr
