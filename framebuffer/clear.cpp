#include "framebuffer/clear.hpp"

#include <algorithm>

namespace mpr {

void clearBuffers(Framebuffer& fb, const PixelRect& region, const ClearBuffers& which,
                  const ClearValues& values, const ClearMasks& masks) {
  const PixelRect r = region.intersect(fb.bounds());
  if (r.empty()) return;
  const std::uint32_t smask = masks.stencil & fb.profile().stencilMax();
  const int accumChannels = fb.profile().accumHasAlpha ? 4 : 3;
  const bool allColor = masks.color[0] && masks.color[1] && masks.color[2] && masks.color[3];
  const std::size_t width = static_cast<std::size_t>(r.x1 - r.x0);
  // Row by row, buffer by buffer: an unmasked buffer's row is one fill.
  for (int y = r.y0; y < r.y1; ++y) {
    if (which.color) {
      Rgba8* c = &fb.color(r.x0, y);
      if (allColor) {
        std::fill_n(c, width, values.color);
      } else {
        for (std::size_t x = 0; x < width; ++x)
          for (int i = 0; i < 4; ++i)
            if (masks.color[i]) c[x][i] = values.color[i];
      }
    }
    if (which.depth && masks.depth) std::fill_n(&fb.depth(r.x0, y), width, values.depth);
    if (which.stencil) {
      std::uint8_t* s = &fb.stencil(r.x0, y);
      for (std::size_t x = 0; x < width; ++x) s[x] = static_cast<std::uint8_t>((s[x] & ~smask) | (values.stencil & smask));
    }
    if (which.accum) {
      std::int16_t* a = fb.accum(r.x0, y);
      for (std::size_t x = 0; x < width; ++x)
        for (int i = 0; i < accumChannels; ++i) a[4 * x + i] = values.accum[i];
    }
  }
}

}  // namespace mpr
