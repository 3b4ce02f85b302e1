#pragma once
// The per-fragment operations as loops over a span (FragmentSpan): each
// stage's state switch (compare function, stencil operation, blend factor)
// is taken once per span, outside its loop, and the loop body is plain
// integer arithmetic on arrays the compiler can do several lanes at a time.
// The tests and stencil operations call compare and stencilOpValue
// themselves with the state a constant; the blend factors, on channel
// arrays, compute lane by lane what blendFactorValue and blend
// (blend.hpp) do for one fragment. fragment_pipeline.cpp strings them
// together in GL order.
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

// Colours as four channel arrays (SoA), each value 0..255. Sixteen bits a
// lane hold every intermediate of blending exactly (mulUnorm8's t + (t >> 8)
// + 128 is at most 65407), twice the lanes of 32.
template <int N>
struct Channels {
  alignas(64) std::uint16_t c[4][N];
};

// out[k] = blendFactorValue(f, s_k, d_k, channel) for k < n.
template <int N>
[[gnu::always_inline]] inline void blendFactors(BlendFactor f, int channel, int n, const Channels<N>& s,
                                                const Channels<N>& d, std::uint16_t* out) {
  const std::uint16_t* sc = s.c[channel];
  const std::uint16_t* dc = d.c[channel];
  const std::uint16_t* sa = s.c[3];
  const std::uint16_t* da = d.c[3];
  switch (f) {
    case BlendFactor::Zero: for (int k = 0; k < n; ++k) out[k] = 0; return;
    case BlendFactor::One: for (int k = 0; k < n; ++k) out[k] = 255; return;
    case BlendFactor::SrcColor: for (int k = 0; k < n; ++k) out[k] = sc[k]; return;
    case BlendFactor::OneMinusSrcColor: for (int k = 0; k < n; ++k) out[k] = static_cast<std::uint16_t>(255 - sc[k]); return;
    case BlendFactor::DstColor: for (int k = 0; k < n; ++k) out[k] = dc[k]; return;
    case BlendFactor::OneMinusDstColor: for (int k = 0; k < n; ++k) out[k] = static_cast<std::uint16_t>(255 - dc[k]); return;
    case BlendFactor::SrcAlpha: for (int k = 0; k < n; ++k) out[k] = sa[k]; return;
    case BlendFactor::OneMinusSrcAlpha: for (int k = 0; k < n; ++k) out[k] = static_cast<std::uint16_t>(255 - sa[k]); return;
    case BlendFactor::DstAlpha: for (int k = 0; k < n; ++k) out[k] = da[k]; return;
    case BlendFactor::OneMinusDstAlpha: for (int k = 0; k < n; ++k) out[k] = static_cast<std::uint16_t>(255 - da[k]); return;
    case BlendFactor::SrcAlphaSaturate:
      if (channel == 3) {
        for (int k = 0; k < n; ++k) out[k] = 255;
      } else {
        for (int k = 0; k < n; ++k) {
          const std::uint16_t inv = static_cast<std::uint16_t>(255 - da[k]);
          out[k] = sa[k] < inv ? sa[k] : inv;
        }
      }
      return;
  }
  for (int k = 0; k < n; ++k) out[k] = 0;
}

// out = blend(b, s, d) lane by lane (blend.hpp).
template <int N>
[[gnu::always_inline]] inline void blendChannels(const BlendState& b, int n, const Channels<N>& s,
                                                 const Channels<N>& d, Channels<N>& out) {
  alignas(64) std::uint16_t fs[N], fd[N];
  // mulUnorm8 in sixteen bits.
  const auto mul = [](std::uint16_t a, std::uint16_t b) {
    const std::uint16_t t = static_cast<std::uint16_t>(a * b);
    return static_cast<std::uint16_t>(static_cast<std::uint16_t>(t + (t >> 8) + 128) >> 8);
  };
  for (int c = 0; c < 4; ++c) {
    blendFactors(b.src, c, n, s, d, fs);
    blendFactors(b.dst, c, n, s, d, fd);
    for (int k = 0; k < n; ++k) {
      const std::uint16_t v = static_cast<std::uint16_t>(mul(s.c[c][k], fs[k]) + mul(d.c[c][k], fd[k]));
      out.c[c][k] = v > 255 ? 255 : v;
    }
  }
}

}  // namespace mpr::span
