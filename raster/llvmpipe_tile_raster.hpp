#pragma once
// llvmpipe's binning and tile rasteriser, step by step, for the triangles
// whose plane steps wrap in 32 bits (LlvmpipeDepth::Triangle::wrapsSteps).
//
// An edge through the clip-space origin leaves draw's clipper a vertex at
// (0,0,0,0), whose window position is NaN: calc_fixed_position makes it
// INT32_MIN, and do_triangle_ccw (lp_setup_tri.c, SSE path, Mesa 22.3) then
// takes each edge's dcdx = y[i] - y[i+1] and dcdy = x[i] - x[i+1] in 32
// bits, wrapping; its c = dcdx x[i] - dcdy y[i] from those wrapped steps
// widened to 64 bits (plus one on the edges owning ties); the steps shifted
// by FIXED_ORDER in 32 bits (wrapping again); the trivial-reject offset eo
// from the pre-shift signs and the shifted steps. The box, over 128 pixels,
// goes to the 64-bit rasteriser (lp_rast_tri_tmp.h with RASTER_64): tiles
// of 64 binned by lp_setup_bin_triangle on 64-bit c + eo and c + ei - 1
// (or the one tile, all planes, where the box crosses no tile edge), then
// 16x16 and 4x4 blocks and pixels on 32-bit values of c >> 8 and the
// steps >> 8, a block inside every plane it is tested against being filled
// whole. None of it is the exact half-plane test LlvmpipeDepth::Triangle
// covers() makes (which is llvmpipe's wherever no step wraps), so such a
// triangle's pixels are those this walk reaches.
#include <array>
#include <cstdint>

#include "raster/llvmpipe_depth.hpp"

namespace mpr {

class LlvmpipeTileRaster {
 public:
  // The triangle as set up (positions in 1/256 pixel, y down), and the
  // region llvmpipe draws into (draw_regions: the framebuffer, within the
  // scissor box when that is enabled), inclusive, in y-down rows.
  LlvmpipeTileRaster(const LlvmpipeDepth::Triangle& t, int regionX0, int regionY0, int regionX1, int regionY1);

  // False where the walk is not the one llvmpipe takes for this triangle
  // (a box small enough for the 32-bit rasteriser): covers() says nothing then.
  bool emulated() const { return emulated_; }

  // Whether llvmpipe shades the pixel (x, yDown) of the region.
  bool covers(int x, int yDown) const;

 private:
  struct Plane {  // lp_rast_plane
    std::int64_t c;
    std::int32_t dcdx, dcdy;
    std::uint32_t eo;
  };
  // Whether lp_rast_triangle, run on the tile with the planes of planeMask,
  // shades the pixel (x, yDown): its 16x16 blocks, do_block_16's 4x4
  // blocks, do_block_4's pixels.
  bool coversInTile(unsigned planeMask, int tileX, int tileY, int x, int yDown) const;

  bool emulated_ = false;
  bool binned_ = false;   // the box meets the region
  bool oneTile_ = false;  // the box crosses no tile edge: one command, every plane
  int tileX0_ = 0, tileY0_ = 0, tileX1_ = 0, tileY1_ = 0;  // the binned tiles (trimmed box)
  int planes_ = 0;
  std::array<Plane, 7> plane_{};
};

}  // namespace mpr
