#pragma once
// The per-fragment operations as loops over a span (FragmentSpan): each
// stage's state switch (compare function, stencil operation, blend factor)
// is taken once per span, outside its loop, and the loop body is plain
// integer arithmetic on arrays the compiler can do several lanes at a time.
// Each function computes, lane by lane, exactly what compare,
// applyStencilOp and blend (compare_func.hpp, stencil.hpp, blend.hpp) do for
// one fragment; fragment_pipeline.cpp strings them together in GL order.
#include <cstdint>

#include "framebuffer/blend.hpp"
#include "framebuffer/compare_func.hpp"
#include "framebuffer/stencil.hpp"

namespace mpr::span {

// pass[k] = compare(f, incoming(k), stored(k)) for k < n.
template <typename Incoming, typename Stored>
[[gnu::always_inline]] inline void compare(CompareFunc f, int n, Incoming incoming, Stored stored,
                                           std::uint32_t* pass) {
  switch (f) {
    case CompareFunc::Never: for (int k = 0; k < n; ++k) pass[k] = 0; return;
    case CompareFunc::Less: for (int k = 0; k < n; ++k) pass[k] = incoming(k) < stored(k); return;
    case CompareFunc::Equal: for (int k = 0; k < n; ++k) pass[k] = incoming(k) == stored(k); return;
    case CompareFunc::Lequal: for (int k = 0; k < n; ++k) pass[k] = incoming(k) <= stored(k); return;
    case CompareFunc::Greater: for (int k = 0; k < n; ++k) pass[k] = incoming(k) > stored(k); return;
    case CompareFunc::Notequal: for (int k = 0; k < n; ++k) pass[k] = incoming(k) != stored(k); return;
    case CompareFunc::Gequal: for (int k = 0; k < n; ++k) pass[k] = incoming(k) >= stored(k); return;
    case CompareFunc::Always: for (int k = 0; k < n; ++k) pass[k] = 1; return;
  }
  for (int k = 0; k < n; ++k) pass[k] = 0;
}

// out[k] = stencilOpValue(op, stored[k], ref, max) for k < n.
[[gnu::always_inline]] inline void stencilOpValues(StencilOp op, int n, const std::uint32_t* stored,
                                                   std::uint32_t ref, std::uint32_t max, std::uint32_t* out) {
  switch (op) {
    case StencilOp::Keep: for (int k = 0; k < n; ++k) out[k] = stored[k]; return;
    case StencilOp::Zero: for (int k = 0; k < n; ++k) out[k] = 0; return;
    case StencilOp::Replace: for (int k = 0; k < n; ++k) out[k] = ref & max; return;
    case StencilOp::Incr: for (int k = 0; k < n; ++k) out[k] = stored[k] < max ? stored[k] + 1 : max; return;
    case StencilOp::Decr: for (int k = 0; k < n; ++k) out[k] = stored[k] > 0 ? stored[k] - 1 : 0; return;
    case StencilOp::Invert: for (int k = 0; k < n; ++k) out[k] = ~stored[k] & max; return;
    case StencilOp::IncrWrap: for (int k = 0; k < n; ++k) out[k] = (stored[k] + 1) & max; return;
    case StencilOp::DecrWrap: for (int k = 0; k < n; ++k) out[k] = (stored[k] - 1) & max; return;
  }
  for (int k = 0; k < n; ++k) out[k] = stored[k];
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
