#pragma once
// The per-fragment operations as loops over a span (FragmentSpan): each
// stage's state switch (compare function, stencil operation, blend factor)
// is taken once per span, outside its loop, and the loop body is plain
// integer arithmetic on arrays the compiler can do several lanes at a time.
// The tests and stencil operations call compare and stencilOpValue
// themselves with the state a constant; the blend factors and products, on
// the bytes of colour words, compute what blendFactorValue and blend
// (blend.hpp) do for one fragment. fragment_pipeline.cpp strings them
// together in GL order.
#include <bit>
#include <cstdint>
#include <type_traits>

#include "framebuffer/blend.hpp"
#include "framebuffer/compare_func.hpp"
#include "framebuffer/stencil.hpp"

namespace mpr::span {

// Calls body(std::integral_constant<E, e>{}) for the e that `value` is, one
// of `values`: the state's switch taken once, the body compiled for each
// value with it a constant (so the scalar functions' own switches fold). A
// value outside the list gets body with it at run time.
template <auto... values, typename E, typename Body>
[[gnu::always_inline]] inline void withConstant(E value, Body&& body) {
  if (!((value == values ? (body(std::integral_constant<E, values>{}), true) : false) || ...))
    body([value] { return value; });
}

// pass[k] = compare(f, incoming(k), stored(k)) for k < n.
template <typename Incoming, typename Stored>
[[gnu::always_inline]] inline void compare(CompareFunc f, int n, Incoming incoming, Stored stored,
                                           std::uint32_t* pass) {
  using enum CompareFunc;
  withConstant<Never, Less, Equal, Lequal, Greater, Notequal, Gequal, Always>(f, [&](auto func) {
    for (int k = 0; k < n; ++k) pass[k] = mpr::compare(func(), incoming(k), stored(k));
  });
}

// out[k] = stencilOpValue(op, stored[k], ref, max) for k < n.
[[gnu::always_inline]] inline void stencilOpValues(StencilOp op, int n, const std::uint32_t* stored,
                                                   std::uint32_t ref, std::uint32_t max, std::uint32_t* out) {
  using enum StencilOp;
  withConstant<Keep, Zero, Replace, Incr, Decr, Invert, IncrWrap, DecrWrap>(op, [&](auto o) {
    for (int k = 0; k < n; ++k) out[k] = stencilOpValue(o(), stored[k], ref, max);
  });
}

// Byte c of a colour (Rgba8 channel c) within its 32-bit word in memory.
constexpr int channelShift(int c) { return std::endian::native == std::endian::little ? 8 * c : 8 * (3 - c); }

// Colours are blended as the bytes of their words in memory order: byte
// 4k + c of an array of words is channel c of lane k (Rgba8's order), so
// no loop reorders channels, and a factor that is an alpha is that byte
// copied to the word's four.
[[gnu::always_inline]] inline std::uint32_t alphaInEveryByte(std::uint32_t word) {
  return ((word >> channelShift(3)) & 0xFFu) * 0x01010101u;
}

// out[k] = the four bytes blendFactorValue(f, s_k, d_k, c) for c = 0..3, k < n.
// 255 - x of a byte is its complement.
[[gnu::always_inline]] inline void blendFactorWords(BlendFactor f, int n, const std::uint32_t* s,
                                                    const std::uint32_t* d, std::uint32_t* out) {
  switch (f) {
    case BlendFactor::Zero: for (int k = 0; k < n; ++k) out[k] = 0; return;
    case BlendFactor::One: for (int k = 0; k < n; ++k) out[k] = 0xFFFFFFFFu; return;
    case BlendFactor::SrcColor: for (int k = 0; k < n; ++k) out[k] = s[k]; return;
    case BlendFactor::OneMinusSrcColor: for (int k = 0; k < n; ++k) out[k] = ~s[k]; return;
    case BlendFactor::DstColor: for (int k = 0; k < n; ++k) out[k] = d[k]; return;
    case BlendFactor::OneMinusDstColor: for (int k = 0; k < n; ++k) out[k] = ~d[k]; return;
    case BlendFactor::SrcAlpha: for (int k = 0; k < n; ++k) out[k] = alphaInEveryByte(s[k]); return;
    case BlendFactor::OneMinusSrcAlpha: for (int k = 0; k < n; ++k) out[k] = ~alphaInEveryByte(s[k]); return;
    case BlendFactor::DstAlpha: for (int k = 0; k < n; ++k) out[k] = alphaInEveryByte(d[k]); return;
    case BlendFactor::OneMinusDstAlpha: for (int k = 0; k < n; ++k) out[k] = ~alphaInEveryByte(d[k]); return;
    case BlendFactor::SrcAlphaSaturate:
      // (f, f, f, 1) with f = min(As, 1 - Ad).
      for (int k = 0; k < n; ++k) {
        const std::uint32_t sa = (s[k] >> channelShift(3)) & 0xFFu, inv = 255u - ((d[k] >> channelShift(3)) & 0xFFu);
        out[k] = (sa < inv ? sa : inv) * 0x01010101u | 0xFFu << channelShift(3);
      }
      return;
  }
  for (int k = 0; k < n; ++k) out[k] = 0;
}

// out = blend(b, s, d) for n words (blend.hpp), byte by byte in sixteen
// bits, which hold every intermediate exactly (mulUnorm8's t + (t >> 8) + 128
// is at most 65407). n is at most N; out may be s or d.
template <int N>
[[gnu::always_inline]] inline void blendWords(const BlendState& b, int n, const std::uint32_t* s,
                                              const std::uint32_t* d, std::uint32_t* out) {
  alignas(64) std::uint32_t fs[N], fd[N], result[N];
  const int bytes = 4 * n;
  const auto* sb = reinterpret_cast<const std::uint8_t*>(s);
  const auto* db = reinterpret_cast<const std::uint8_t*>(d);
  auto* rb = reinterpret_cast<std::uint8_t*>(result);
  if (b.src == BlendFactor::One && b.dst == BlendFactor::One) {
    // mulUnorm8(x, 255) is x: the sum, saturated.
    for (int i = 0; i < bytes; ++i) {
      const std::uint16_t v = static_cast<std::uint16_t>(sb[i] + db[i]);
      rb[i] = static_cast<std::uint8_t>(v > 255 ? 255 : v);
    }
  } else {
    blendFactorWords(b.src, n, s, d, fs);
    blendFactorWords(b.dst, n, s, d, fd);
    const auto* fsb = reinterpret_cast<const std::uint8_t*>(fs);
    const auto* fdb = reinterpret_cast<const std::uint8_t*>(fd);
    // mulUnorm8 in sixteen bits.
    const auto mul = [](std::uint16_t a, std::uint16_t f) {
      const std::uint16_t t = static_cast<std::uint16_t>(a * f);
      return static_cast<std::uint16_t>(static_cast<std::uint16_t>(t + (t >> 8) + 128) >> 8);
    };
    for (int i = 0; i < bytes; ++i) {
      const std::uint16_t v = static_cast<std::uint16_t>(mul(sb[i], fsb[i]) + mul(db[i], fdb[i]));
      rb[i] = static_cast<std::uint8_t>(v > 255 ? 255 : v);
    }
  }
  for (int k = 0; k < n; ++k) out[k] = result[k];
}

}  // namespace mpr::span
