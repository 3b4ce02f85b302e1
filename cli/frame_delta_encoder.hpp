#pragma once
// The buffers at the end of each pass, for the stepper page, as changes
// against the previous pass: a 640x480 frame is 5 MB of buffers, but a pass
// changes a part of them. Per buffer (colour, depth, stencil, accumulation)
// the delta is a list of runs of changed pixels in window order (row y = 0
// first), each run the element-wise wrapping differences new - old: additive
// light passes then give smooth small numbers, which zlib packs well.
//
// Layout, per buffer in that order: varint runCount, then per run varint
// skip (unchanged pixels before it), varint length, and length pixels of
// little-endian differences (colour 4 x u8, depth u32, stencil u8,
// accumulation 4 x i16). Short unchanged gaps are folded into runs.
#include <cstdint>
#include <string>
#include <vector>

#include "framebuffer/framebuffer.hpp"

namespace mpr::cli {

class FrameDeltaEncoder {
 public:
  // The first delta is against buffers that hold zero everywhere.
  FrameDeltaEncoder(int width, int height);

  // The changes from the buffers given last time to `fb`'s (uncompressed).
  std::string encode(const Framebuffer& fb);

 private:
  std::vector<Rgba8> colour_;
  std::vector<std::uint32_t> depth_;
  std::vector<std::uint8_t> stencil_;
  std::vector<std::int16_t> accum_;
};

}  // namespace mpr::cli
