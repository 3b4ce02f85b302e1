#include "framebuffer/fragment_ops.hpp"

#include <cmath>

namespace mpr {

FragmentFate processFragment(const FragmentState& s, Framebuffer& fb, const Fragment& f) {
  if (s.alpha.enabled && !alphaTestPasses(s.alpha, f.alpha)) return FragmentFate::AlphaFailed;

  const std::uint32_t max = fb.profile().stencilMax();
  std::uint8_t& st = fb.stencil(f.x, f.y);
  if (s.stencil.enabled && !stencilTest(s.stencil, st)) {
    st = static_cast<std::uint8_t>(applyStencilOp(s.stencil.sfail, st, s.stencil, max));
    return FragmentFate::StencilFailed;
  }

  std::uint32_t& z = fb.depth(f.x, f.y);
  // With the depth test disabled the depth buffer is neither tested nor written
  // (GL 1.1 section 4.1.5), and the stencil takes the depth-pass operation.
  if (s.depth.enabled) {
    if (!compare(s.depth.func, f.depth, z)) {
      if (s.stencil.enabled)
        st = static_cast<std::uint8_t>(applyStencilOp(s.stencil.dpfail, st, s.stencil, max));
      return FragmentFate::DepthFailed;
    }
    if (s.depth.writeMask) z = f.depth;
  }
  if (s.stencil.enabled)
    st = static_cast<std::uint8_t>(applyStencilOp(s.stencil.dppass, st, s.stencil, max));

  Rgba8& dst = fb.color(f.x, f.y);
  const Rgba8 src = s.blend.enabled ? blend(s.blend, f.color, dst) : f.color;
  for (int c = 0; c < 4; ++c)
    if (s.colorMask[c]) dst[c] = src[c];
  return FragmentFate::Written;
}

}  // namespace mpr
