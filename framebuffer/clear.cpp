#include "framebuffer/clear.hpp"

namespace mpr {

void clearBuffers(Framebuffer& fb, const PixelRect& region, const ClearBuffers& which,
                  const ClearValues& values, const ClearMasks& masks) {
  const PixelRect r = region.intersect(fb.bounds());
  if (r.empty()) return;
  const std::uint32_t smask = masks.stencil & fb.profile().stencilMax();
  const int accumChannels = fb.profile().accumHasAlpha ? 4 : 3;
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) {
      if (which.color) {
        Rgba8& c = fb.color(x, y);
        for (int i = 0; i < 4; ++i)
          if (masks.color[i]) c[i] = values.color[i];
      }
      if (which.depth && masks.depth) fb.depth(x, y) = values.depth;
      if (which.stencil) {
        std::uint8_t& s = fb.stencil(x, y);
        s = static_cast<std::uint8_t>((s & ~smask) | (values.stencil & smask));
      }
      if (which.accum) {
        std::int16_t* a = fb.accum(x, y);
        for (int i = 0; i < accumChannels; ++i) a[i] = values.accum[i];
      }
    }
  }
}

}  // namespace mpr
