#include "framebuffer/fragment_pipeline.hpp"

namespace mpr {
namespace {

enum class ColorWrites { None, All, Some };

// processFragment (fragment_ops.cpp) with its state switches decided at compile time.
template <bool kAlpha, bool kStencil, bool kDepth, bool kBlend, ColorWrites kColor>
FragmentFate specialised(const FragmentState& s, Framebuffer& fb, const Fragment& f) {
  if constexpr (kAlpha)
    if (!alphaTestPasses(s.alpha, f.alpha)) return FragmentFate::AlphaFailed;

  [[maybe_unused]] const std::uint32_t max = fb.profile().stencilMax();
  [[maybe_unused]] std::uint8_t* st = nullptr;
  if constexpr (kStencil) {
    st = &fb.stencil(f.x, f.y);
    if (!stencilTest(s.stencil, *st)) {
      *st = static_cast<std::uint8_t>(applyStencilOp(s.stencil.sfail, *st, s.stencil, max));
      return FragmentFate::StencilFailed;
    }
  }
  if constexpr (kDepth) {
    std::uint32_t& z = fb.depth(f.x, f.y);
    if (!compare(s.depth.func, f.depth, z)) {
      if constexpr (kStencil) *st = static_cast<std::uint8_t>(applyStencilOp(s.stencil.dpfail, *st, s.stencil, max));
      return FragmentFate::DepthFailed;
    }
    if (s.depth.writeMask) z = f.depth;
  }
  if constexpr (kStencil) *st = static_cast<std::uint8_t>(applyStencilOp(s.stencil.dppass, *st, s.stencil, max));

  if constexpr (kColor != ColorWrites::None) {
    Rgba8& dst = fb.color(f.x, f.y);
    Rgba8 src = f.color;
    if constexpr (kBlend) src = blend(s.blend, f.color, dst);
    if constexpr (kColor == ColorWrites::All) {
      dst = src;
    } else {
      for (int c = 0; c < 4; ++c)
        if (s.colorMask[c]) dst[c] = src[c];
    }
  }
  return FragmentFate::Written;
}

template <bool kAlpha, bool kStencil, bool kDepth, bool kBlend>
FragmentFunction byColor(ColorWrites c) {
  switch (c) {
    case ColorWrites::None: return specialised<kAlpha, kStencil, kDepth, kBlend, ColorWrites::None>;
    case ColorWrites::All: return specialised<kAlpha, kStencil, kDepth, kBlend, ColorWrites::All>;
    case ColorWrites::Some: break;
  }
  return specialised<kAlpha, kStencil, kDepth, kBlend, ColorWrites::Some>;
}

template <bool kAlpha, bool kStencil, bool kDepth>
FragmentFunction byBlend(const FragmentState& s, ColorWrites c) {
  return s.blend.enabled ? byColor<kAlpha, kStencil, kDepth, true>(c) : byColor<kAlpha, kStencil, kDepth, false>(c);
}

template <bool kAlpha, bool kStencil>
FragmentFunction byDepth(const FragmentState& s, ColorWrites c) {
  return s.depth.enabled ? byBlend<kAlpha, kStencil, true>(s, c) : byBlend<kAlpha, kStencil, false>(s, c);
}

template <bool kAlpha>
FragmentFunction byStencil(const FragmentState& s, ColorWrites c) {
  return s.stencil.enabled ? byDepth<kAlpha, true>(s, c) : byDepth<kAlpha, false>(s, c);
}

}  // namespace

FragmentFunction chooseFragmentFunction(const FragmentState& s) {
  const int written = s.colorMask[0] + s.colorMask[1] + s.colorMask[2] + s.colorMask[3];
  const ColorWrites c = written == 0 ? ColorWrites::None : written == 4 ? ColorWrites::All : ColorWrites::Some;
  return s.alpha.enabled ? byStencil<true>(s, c) : byStencil<false>(s, c);
}

}  // namespace mpr
