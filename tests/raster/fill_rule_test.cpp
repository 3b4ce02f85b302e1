// Coverage of the fixed-point rasterizer: the top-left rule, exact tiling of
// shared edges and fans, sub-pixel snapping, and tile independence.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "raster/triangle_rasterizer.hpp"

namespace mpr {
namespace {

constexpr int kW = 64, kH = 64;

struct Coverage {
  std::vector<int> hits = std::vector<int>(kW * kH, 0);
  int& at(int x, int y) { return hits[y * kW + x]; }
};

void draw(Coverage& c, float x0, float y0, float x1, float y1, float x2, float y2,
          PixelBounds clip = {0, 0, kW, kH}) {
  rasterizeTriangle({snapVertex(x0, y0), snapVertex(x1, y1), snapVertex(x2, y2)}, clip,
                    [&](int x, int y, std::int64_t, std::int64_t, std::int64_t) { ++c.at(x, y); });
}

// Pixels (x, y) for which the given predicate holds at the pixel centre.
std::vector<std::pair<int, int>> covered(Coverage& c) {
  std::vector<std::pair<int, int>> out;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      if (c.at(x, y)) out.emplace_back(x, y);
  return out;
}

TEST(FillRule, RectangleThroughPixelCentresOwnsLeftAndBottomEdgesOnly) {
  // Square with corners on pixel centres (1.5, 1.5) .. (4.5, 4.5): centres on
  // the left edge x = 1.5 and the bottom edge y = 1.5 (GL window coordinates,
  // y up: the top edge of a y-down framebuffer) belong to it, those on the
  // right (x = 4.5) and top (y = 4.5) edges do not. Measured on llvmpipe.
  Coverage c;
  draw(c, 1.5f, 1.5f, 4.5f, 1.5f, 4.5f, 4.5f);
  draw(c, 1.5f, 1.5f, 4.5f, 4.5f, 1.5f, 4.5f);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const bool inside = x >= 1 && x <= 3 && y >= 1 && y <= 3;
      EXPECT_EQ(c.at(x, y), inside ? 1 : 0) << "pixel " << x << "," << y;
    }
}

TEST(FillRule, WindingDoesNotChangeCoverage) {
  Coverage ccw, cw;
  draw(ccw, 2.5f, 2.5f, 20.25f, 5.5f, 9.5f, 17.5f);
  draw(cw, 2.5f, 2.5f, 9.5f, 17.5f, 20.25f, 5.5f);
  EXPECT_EQ(ccw.hits, cw.hits);
  EXPECT_GT(covered(ccw).size(), 50u);
}

TEST(FillRule, SharedDiagonalNeverDoubleHits) {
  // Random quads split along the diagonal p0-p2, with p1 and p3 on opposite
  // sides of it so the two triangles do not overlap: no pixel is hit twice,
  // and every pixel covered by the quad as one polygon is hit once.
  std::mt19937 rng(12345);
  std::uniform_real_distribution<float> d(0.0f, 64.0f);
  int trials = 0;
  while (trials < 300) {
    float px[4], py[4];
    for (int k = 0; k < 4; ++k) {
      px[k] = d(rng);
      py[k] = d(rng);
    }
    const auto side = [&](int k) {
      return (px[2] - px[0]) * (py[k] - py[0]) - (py[2] - py[0]) * (px[k] - px[0]);
    };
    if (!(side(1) * side(3) < 0.0f)) continue;
    ++trials;
    Coverage c;
    draw(c, px[0], py[0], px[1], py[1], px[2], py[2]);
    draw(c, px[0], py[0], px[2], py[2], px[3], py[3]);
    for (int v : c.hits) ASSERT_LE(v, 1) << "trial " << trials;
  }
}

TEST(FillRule, FanAroundAPointCoversEveryPixelExactlyOnce) {
  // A fan of triangles around an interior point that together tile the whole
  // window rectangle: every pixel is covered exactly once.
  for (const auto& centre : {std::pair{32.0f, 32.0f}, std::pair{17.5f, 40.5f}, std::pair{21.371f, 9.8125f}}) {
    const float cx = centre.first, cy = centre.second;
    // Boundary points on the rectangle [0, 64]^2, counter-clockwise, some on
    // pixel centres, some not.
    const std::vector<std::pair<float, float>> ring = {
        {0, 0}, {10.5f, 0}, {33.3f, 0}, {64, 0}, {64, 20.5f}, {64, 47.77f}, {64, 64},
        {40.5f, 64}, {12.01f, 64}, {0, 64}, {0, 31.5f}, {0, 12.2f}};
    Coverage c;
    for (size_t i = 0; i < ring.size(); ++i) {
      const auto& a = ring[i];
      const auto& b = ring[(i + 1) % ring.size()];
      draw(c, cx, cy, a.first, a.second, b.first, b.second);
    }
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) ASSERT_EQ(c.at(x, y), 1) << "pixel " << x << "," << y << " centre " << cx;
  }
}

TEST(FillRule, SubpixelSnappingRoundsToEighthBit) {
  // An edge 1/1024 pixel right of the centre x = 3.5 snaps onto it (8 bits):
  // the left edge then owns the centre. 1/128 to the right does not snap.
  Coverage snapped, unsnapped;
  draw(snapped, 3.5f + 1.0f / 1024, 0.5f, 10.0f, 0.5f, 3.5f + 1.0f / 1024, 10.0f);
  draw(unsnapped, 3.5f + 1.0f / 128, 0.5f, 10.0f, 0.5f, 3.5f + 1.0f / 128, 10.0f);
  EXPECT_EQ(snapped.at(3, 5), 1);
  EXPECT_EQ(unsnapped.at(3, 5), 0);
  EXPECT_EQ(snapped.at(4, 5), 1);
}

TEST(FillRule, DegenerateTrianglesCoverNothing) {
  Coverage c;
  draw(c, 1, 1, 5, 5, 9, 9);          // collinear
  draw(c, 3, 3, 3, 3, 3, 3);          // a point
  draw(c, 1.5f, 2, 1.5f + 1.0f / 1024, 8, 1.5f, 20);  // collinear after snapping
  EXPECT_TRUE(covered(c).empty());
}

TEST(FillRule, TilesRasterizeIndependently) {
  // Splitting the window into tiles changes no pixel: the basis for running
  // tiles on several threads.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> d(-8.0f, 72.0f);
  for (int trial = 0; trial < 100; ++trial) {
    const float v[6] = {d(rng), d(rng), d(rng), d(rng), d(rng), d(rng)};
    Coverage whole, tiled;
    draw(whole, v[0], v[1], v[2], v[3], v[4], v[5]);
    for (int ty = 0; ty < kH; ty += 16)
      for (int tx = 0; tx < kW; tx += 16) draw(tiled, v[0], v[1], v[2], v[3], v[4], v[5], {tx, ty, tx + 16, ty + 16});
    ASSERT_EQ(whole.hits, tiled.hits) << "trial " << trial;
  }
}

TEST(FillRule, WeightsSumToTheDoubledArea) {
  const auto a = snapVertex(2.25f, 3.5f), b = snapVertex(30.0f, 7.75f), c = snapVertex(12.5f, 28.0f);
  const std::int64_t area = signedArea2(a, b, c);
  ASSERT_GT(area, 0);
  int n = 0;
  rasterizeTriangle({a, b, c}, {0, 0, kW, kH}, [&](int, int, std::int64_t w0, std::int64_t w1, std::int64_t w2) {
    EXPECT_EQ(w0 + w1 + w2, area);
    EXPECT_GE(w0, 0);
    EXPECT_GE(w1, 0);
    EXPECT_GE(w2, 0);
    ++n;
  });
  EXPECT_GT(n, 100);
}

}  // namespace
}  // namespace mpr
