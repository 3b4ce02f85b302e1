#pragma once
// glClear (GL 1.1 section 4.2.3): every enabled buffer inside the scissor box
// (the whole window when scissoring is off) takes its clear value through its
// write mask. The accumulation buffer has no write mask.
#include <array>
#include <cstdint>

#include "framebuffer/framebuffer.hpp"

namespace mpr {

struct ClearValues {
  Rgba8 color{0, 0, 0, 0};
  std::uint32_t depth = 0;      // stored integer
  std::uint32_t stencil = 0;    // already masked to the stencil width
  std::array<std::int16_t, 4> accum{0, 0, 0, 0};  // stored words
};

struct ClearMasks {
  std::array<bool, 4> color{true, true, true, true};
  bool depth = true;
  std::uint32_t stencil = ~0u;
};

struct ClearBuffers {
  bool color = false, depth = false, stencil = false, accum = false;
};

void clearBuffers(Framebuffer& fb, const PixelRect& region, const ClearBuffers& which,
                  const ClearValues& values, const ClearMasks& masks);

}  // namespace mpr
