// rasterizeTriangle solves each row's span from the edge functions instead of
// testing every pixel of the bounding box. Against that per-pixel test
// (written here as the rasterizer had it), on random triangles of every
// shape and size, slivers, ties on pixel centres, both windings and clip
// rectangles cutting through them: the same pixels in the same order, with
// the same integer weights.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <tuple>
#include <vector>

#include "raster/triangle_rasterizer.hpp"

namespace mpr {
namespace {

using Hit = std::tuple<int, int, std::int64_t, std::int64_t, std::int64_t>;

// Every pixel of the clipped bounding box, tested: (E_i - bias_i) >= 0 for all i.
std::vector<Hit> perPixel(const std::array<SnappedVertex, 3>& vIn, const PixelBounds& clip) {
  std::vector<Hit> out;
  std::array<SnappedVertex, 3> v = vIn;
  std::int64_t area = signedArea2(v[0], v[1], v[2]);
  if (area == 0) return out;
  const bool swapped = area < 0;
  if (swapped) std::swap(v[1], v[2]);
  const std::int64_t minX = std::min({v[0].x, v[1].x, v[2].x}), maxX = std::max({v[0].x, v[1].x, v[2].x});
  const std::int64_t minY = std::min({v[0].y, v[1].y, v[2].y}), maxY = std::max({v[0].y, v[1].y, v[2].y});
  const std::int64_t px0 = std::max<std::int64_t>(clip.x0, ceilDivSubpixel(minX));
  const std::int64_t px1 = std::min<std::int64_t>(clip.x1 - 1, floorDivSubpixel(maxX));
  const std::int64_t py0 = std::max<std::int64_t>(clip.y0, ceilDivSubpixel(minY));
  const std::int64_t py1 = std::min<std::int64_t>(clip.y1 - 1, floorDivSubpixel(maxY));
  for (std::int64_t py = py0; py <= py1; ++py)
    for (std::int64_t px = px0; px <= px1; ++px) {
      std::int64_t w[3];
      bool in = true;
      for (int i = 0; i < 3; ++i) {
        const SnappedVertex& a = v[(i + 1) % 3];
        const SnappedVertex& b = v[(i + 2) % 3];
        const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
        w[i] = dx * (py * kSubpixelOne - a.y) - dy * (px * kSubpixelOne - a.x);
        in = in && w[i] - (ownsTies(dx, dy) ? 0 : 1) >= 0;
      }
      if (!in) continue;
      if (swapped) out.emplace_back(static_cast<int>(px), static_cast<int>(py), w[0], w[2], w[1]);
      else out.emplace_back(static_cast<int>(px), static_cast<int>(py), w[0], w[1], w[2]);
    }
  return out;
}

std::vector<Hit> spans(const std::array<SnappedVertex, 3>& v, const PixelBounds& clip) {
  std::vector<Hit> out;
  rasterizeTriangle(v, clip, [&](int x, int y, std::int64_t w0, std::int64_t w1, std::int64_t w2) {
    out.emplace_back(x, y, w0, w1, w2);
  });
  return out;
}

TEST(SpanRasterizer, SameHitsAsTheTestOfEveryPixel) {
  std::mt19937 rng(14);
  std::size_t hits = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    // Sizes from sub-pixel to larger than the clip; every fourth on the pixel
    // grid (ties on centres), every eighth a sliver with two close vertices.
    const int scale = 1 << (rng() % 7);
    std::array<SnappedVertex, 3> v;
    for (auto& p : v) {
      p.x = static_cast<std::int64_t>(rng() % (scale * 256 * 4)) - scale * 256;
      p.y = static_cast<std::int64_t>(rng() % (scale * 256 * 4)) - scale * 256;
      if (trial % 4 == 0) p = {p.x & ~std::int64_t{255}, p.y & ~std::int64_t{255}};
    }
    if (trial % 8 == 1) v[2] = {v[1].x + static_cast<std::int64_t>(rng() % 5), v[1].y - 3};
    const int cx = static_cast<int>(rng() % 8), cy = static_cast<int>(rng() % 8);
    const PixelBounds clip{cx, cy, cx + 1 + static_cast<int>(rng() % 200), cy + 1 + static_cast<int>(rng() % 200)};
    const std::vector<Hit> want = perPixel(v, clip);
    ASSERT_EQ(spans(v, clip), want) << "trial " << trial;
    hits += want.size();
  }
  EXPECT_GT(hits, 100000u);  // the comparison covered many pixels
}

// A thread's share (rowStride n, rowPhase k: the rows y with y mod n == k):
// the n shares together hit exactly the pixels of the whole triangle, each
// once, with the same weights (GLContext::setThreads' invariance).
TEST(SpanRasterizer, RowSharesTogetherAreTheWholeTriangle) {
  std::mt19937 rng(15);
  for (int trial = 0; trial < 1000; ++trial) {
    const int scale = 1 << (rng() % 7);
    std::array<SnappedVertex, 3> v;
    for (auto& p : v) {
      p.x = static_cast<std::int64_t>(rng() % (scale * 256 * 4)) - scale * 256;
      p.y = static_cast<std::int64_t>(rng() % (scale * 256 * 4)) - scale * 256;
    }
    const int cx = static_cast<int>(rng() % 8) - 4, cy = static_cast<int>(rng() % 8) - 4;
    const PixelBounds clip{cx, cy, cx + 1 + static_cast<int>(rng() % 200), cy + 1 + static_cast<int>(rng() % 200)};
    std::vector<Hit> whole = spans(v, clip), shared;
    for (int n : {2, 3, 8}) {
      shared.clear();
      for (int k = 0; k < n; ++k)
        rasterizeTriangle(
            v, clip,
            [&](int x, int y, std::int64_t w0, std::int64_t w1, std::int64_t w2) {
              EXPECT_EQ(((y % n) + n) % n, k);
              shared.emplace_back(x, y, w0, w1, w2);
            },
            n, k);
      // The whole triangle's order: rows upwards, each left to right.
      std::sort(shared.begin(), shared.end(), [](const Hit& a, const Hit& b) {
        return std::make_pair(std::get<1>(a), std::get<0>(a)) < std::make_pair(std::get<1>(b), std::get<0>(b));
      });
      ASSERT_EQ(shared, whole) << "trial " << trial << ", " << n << " shares";
    }
  }
}

}  // namespace
}  // namespace mpr
