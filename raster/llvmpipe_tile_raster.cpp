// llvmpipe's binning and tile rasteriser for wrapped plane steps (see
// llvmpipe_tile_raster.hpp).
#include "raster/llvmpipe_tile_raster.hpp"

#include <algorithm>
#include <bit>

#include "raster/fixed_point.hpp"

namespace mpr {
namespace {

// 32-bit arithmetic as the SSE instructions (and the C on x86-64) do it:
// two's complement, wrapping (64-bit: raster/fixed_point.hpp's wrapping*).
inline std::int32_t add32(std::int32_t a, std::int32_t b) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) + static_cast<std::uint32_t>(b));
}
inline std::int32_t sub32(std::int32_t a, std::int32_t b) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) - static_cast<std::uint32_t>(b));
}
inline std::int32_t shl32(std::int32_t a, int n) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) << n);
}
inline std::int32_t lo32(std::int64_t v) { return static_cast<std::int32_t>(static_cast<std::uint32_t>(v)); }

// lp_rast_tri.c build_mask_linear_sse: bit 4 row + column set where
// c + column dcdx + row dcdy (32 bits, wrapping; the saturating packs keep
// the sign) is negative.
unsigned signMask(std::int32_t c, std::int32_t dcdx, std::int32_t dcdy) {
  unsigned mask = 0;
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column) {
      const std::uint32_t v = static_cast<std::uint32_t>(c) + static_cast<std::uint32_t>(column) * static_cast<std::uint32_t>(dcdx) +
                              static_cast<std::uint32_t>(row) * static_cast<std::uint32_t>(dcdy);
      if (static_cast<std::int32_t>(v) < 0) mask |= 1u << (row * 4 + column);
    }
  return mask;
}

// floor_pot: the largest power of two not above n (0 for 0).
std::uint32_t floorPot(std::uint32_t n) { return n == 0 ? 0 : std::uint32_t{1} << (31 - std::countl_zero(n)); }

constexpr int kTileSize = 64;

}  // namespace

LlvmpipeTileRaster::LlvmpipeTileRaster(const LlvmpipeDepth::Triangle& t, int regionX0, int regionY0, int regionX1,
                                       int regionY1) {
  std::array<std::int32_t, 3> x, y;
  for (int i = 0; i < 3; ++i) {
    x[i] = static_cast<std::int32_t>(t.fixedX[i]);
    y[i] = static_cast<std::int32_t>(t.fixedY[i]);
  }
  // do_triangle_ccw's bounding box (bottom_edge_rule: OSMesa's rows are
  // top-down, so adj is 1), on the 32-bit positions.
  int bx0 = std::min({x[0], x[1], x[2]}) >> 8;
  int bx1 = sub32(std::max({x[0], x[1], x[2]}), 1) >> 8;
  int by0 = add32(std::min({y[0], y[1], y[2]}), 1) >> 8;
  int by1 = std::max({y[0], y[1], y[2]}) >> 8;
  if (regionX1 < bx0 || bx1 < regionX0 || regionY1 < by0 || by1 < regionY0) {
    emulated_ = true;  // culled: no pixel
    return;
  }
  const std::int32_t maxSizeOriginal = sub32(bx1, bx0 & ~3) | sub32(by1, by0 & ~3);
  if (maxSizeOriginal <= 128) return;  // MAX_FIXED_LENGTH32: the 32-bit rasteriser, not this walk
  emulated_ = true;
  binned_ = true;
  bx0 = std::max(bx0, 0);
  by0 = std::max(by0, 0);

  // The three edges (SSE path): wrapped steps, c from them in 64 bits.
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const std::int32_t dcdx = sub32(y[i], y[j]), dcdy = sub32(x[i], x[j]);
    Plane& p = plane_[static_cast<std::size_t>(i)];
    p.c = wrappingSub(wrappingMul(dcdx, x[i]), wrappingMul(dcdy, y[i]));
    if (dcdx < 0 || (dcdx == 0 && dcdy < 0)) p.c = wrappingAdd(p.c, 1);
    p.dcdx = shl32(dcdx, 8);
    p.dcdy = shl32(dcdy, 8);
    p.eo = static_cast<std::uint32_t>(dcdy >= 0 ? p.dcdy : 0) - static_cast<std::uint32_t>(dcdx < 0 ? p.dcdx : 0);
  }
  planes_ = 3;
  // scissor_planes_needed against draw_regions, lp_setup_add_scissor_planes.
  if (bx0 < regionX0)
    plane_[static_cast<std::size_t>(planes_++)] = {-(static_cast<std::int64_t>(regionX0 - 1) * 256), -256, 0, 256};
  if (bx1 > regionX1)
    plane_[static_cast<std::size_t>(planes_++)] = {static_cast<std::int64_t>(regionX1) * 256 + 127, 256, 0, 0};
  if (by0 < regionY0)
    plane_[static_cast<std::size_t>(planes_++)] = {-(static_cast<std::int64_t>(regionY0 - 1) * 256), 0, 256, 256};
  if (by1 > regionY1)
    plane_[static_cast<std::size_t>(planes_++)] = {static_cast<std::int64_t>(regionY1) * 256 + 127, 0, -256, 0};

  // lp_setup_bin_triangle: a box crossing no tile edge is one command on
  // its tile with every plane; else each tile of the trimmed box is tested.
  const int dx = static_cast<int>(floorPot(static_cast<std::uint32_t>((bx0 ^ bx1) | (by0 ^ by1))));
  oneTile_ = dx < kTileSize;
  if (oneTile_) {
    tileX0_ = tileX1_ = bx0 / kTileSize;
    tileY0_ = tileY1_ = by0 / kTileSize;
  } else {
    tileX0_ = std::max(bx0, regionX0) / kTileSize;
    tileX1_ = std::min(bx1, regionX1) / kTileSize;
    tileY0_ = std::max(by0, regionY0) / kTileSize;
    tileY1_ = std::min(by1, regionY1) / kTileSize;
  }
}

bool LlvmpipeTileRaster::covers(int x, int yDown) const {
  if (!binned_ || x < 0 || yDown < 0) return false;
  const int tileX = x / kTileSize, tileY = yDown / kTileSize;
  if (tileX < tileX0_ || tileX > tileX1_ || tileY < tileY0_ || tileY > tileY1_) return false;
  const unsigned allPlanes = (1u << planes_) - 1;
  if (oneTile_) return coversInTile(allPlanes, tileX, tileY, x, yDown);
  // The row of tiles from the left, as binned: out, partial (the planes
  // not trivially accepted), or whole; out after one in ends the row.
  bool in = false;
  for (int tx = tileX0_; tx <= tileX; ++tx) {
    bool out = false;
    unsigned partial = 0;
    for (int i = 0; i < planes_; ++i) {
      const Plane& p = plane_[static_cast<std::size_t>(i)];
      const std::int64_t c = wrappingSub(wrappingAdd(p.c, wrappingMul(wrappingMul(p.dcdy, tileY), kTileSize)), wrappingMul(wrappingMul(p.dcdx, tx), kTileSize));
      const std::int64_t eo = static_cast<std::int64_t>(p.eo) * kTileSize;
      const std::int64_t ei = wrappingMul(static_cast<std::int64_t>(sub32(p.dcdy, p.dcdx)) - static_cast<std::int64_t>(p.eo), kTileSize);
      out = out || wrappingAdd(c, eo) < 0;
      if (wrappingSub(wrappingAdd(c, ei), 1) < 0) partial |= 1u << i;
    }
    if (out) {
      if (in) return false;  // exiting the triangle: the row is done
      if (tx == tileX) return false;
      continue;
    }
    in = true;
    if (tx == tileX) return partial == 0 || coversInTile(partial, tileX, tileY, x, yDown);
  }
  return false;
}

bool LlvmpipeTileRaster::coversInTile(unsigned planeMask, int tileX, int tileY, int x, int yDown) const {
  std::array<const Plane*, 7> planes{};
  std::array<std::int64_t, 7> c{};
  int n = 0;
  int bx = tileX * kTileSize, by = tileY * kTileSize;
  for (int i = 0; i < planes_; ++i)
    if (planeMask & (1u << i)) {
      const Plane& p = plane_[static_cast<std::size_t>(i)];
      planes[static_cast<std::size_t>(n)] = &p;
      c[static_cast<std::size_t>(n)] = wrappingSub(wrappingAdd(p.c, wrappingMul(p.dcdy, by)), wrappingMul(p.dcdx, bx));
      ++n;
    }
  // lp_rast_triangle (16x16 blocks of the tile), then do_block_16 (4x4
  // blocks): the masks of c >> 8 and the steps >> 8 in 32 bits; a block
  // outside no plane's reject and inside every plane's accept is filled.
  for (int shift = 4; shift >= 2; shift -= 2) {
    const int size = 1 << shift;
    unsigned outMask = 0, partMask = 0;
    for (int j = 0; j < n; ++j) {
      const Plane& p = *planes[static_cast<std::size_t>(j)];
      const std::int64_t cj = c[static_cast<std::size_t>(j)];
      const std::int32_t dcdx = sub32(0, p.dcdx) >> 8, dcdy = p.dcdy >> 8;
      const std::int32_t cox = static_cast<std::int32_t>(p.eo >> 8);
      const std::int32_t ei = shl32(sub32(add32(dcdy, dcdx), cox), shift);
      const std::int32_t coxS = shl32(cox, shift);
      const std::int32_t co = add32(lo32(cj >> 8), coxS);
      const std::int32_t cdiff = add32(sub32(ei, coxS), sub32(lo32(wrappingSub(cj, 1) >> 8), lo32(cj >> 8)));
      outMask |= signMask(co, shl32(dcdx, shift), shl32(dcdy, shift));
      partMask |= signMask(add32(co, cdiff), shl32(dcdx, shift), shl32(dcdy, shift));
    }
    if ((outMask & 0xffff) == 0xffff) return false;
    const int ix = (x - bx) / size, iy = (yDown - by) / size;
    const unsigned bit = 1u << (iy * 4 + ix);
    if (!(partMask & bit)) return true;   // inside every accept: filled whole
    if (outMask & bit) return false;      // outside a reject
    bx += ix * size;
    by += iy * size;
    for (int j = 0; j < n; ++j) {
      const Plane& p = *planes[static_cast<std::size_t>(j)];
      c[static_cast<std::size_t>(j)] =
          wrappingAdd(wrappingSub(c[static_cast<std::size_t>(j)], wrappingMul(p.dcdx, ix * size)), wrappingMul(p.dcdy, iy * size));
    }
  }
  // do_block_4: each pixel on (c - 1) >> 8 in 32 bits.
  unsigned mask = 0xffff;
  for (int j = 0; j < n; ++j) {
    const Plane& p = *planes[static_cast<std::size_t>(j)];
    mask &= ~signMask(lo32(wrappingSub(c[static_cast<std::size_t>(j)], 1) >> 8), sub32(0, p.dcdx) >> 8, p.dcdy >> 8);
  }
  return (mask & (1u << ((yDown - by) * 4 + (x - bx)))) != 0;
}

}  // namespace mpr
