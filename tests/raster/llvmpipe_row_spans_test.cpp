// LlvmpipeRowSpans: the row-by-row spans of llvmpipe's triangles are
// exactly the pixels covers() accepts, carried or solved.
#include "raster/llvmpipe_row_spans.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace mpr {
namespace {

ClipVertex vertex(float x, float y, float z, float w) {
  ClipVertex v{};
  v.clip = Vec4(x, y, z, w);
  return v;
}

// Random triangles through draw's clipper and llvmpipe's set-up, in a window
// scaled by `scale` (1: 640x480; far larger: positions past the carried walk's
// limit, solved row by row).
std::vector<LlvmpipeDepth::Triangle> randomTriangles(std::mt19937& rng, float scale, int count) {
  std::uniform_real_distribution<double> coordinate(-1.4, 1.4), logW(-2.0, 2.0), unit(0.0, 1.0);
  const std::vector<ClipPlane> noUserPlanes;
  std::vector<LlvmpipeDepth::Triangle> out;
  while (static_cast<int>(out.size()) < count) {
    LlvmpipeDepth setup{WindowTransform{320.0f * scale, 320.0f, 240.0f * scale, 240.0f, 0.5f, 0.5f, 480},
                        &noUserPlanes, {}};
    std::array<ClipVertex, 3> v;
    for (auto& p : v) {
      const float w = static_cast<float>(std::pow(10.0, logW(rng)));
      // Small triangles (a few pixels) as often as large clipped ones.
      const double spread = rng() % 2 == 0 ? 1.0 : 0.02;
      const double cx = coordinate(rng), cy = coordinate(rng);
      p = vertex(static_cast<float>(cx * spread * w), static_cast<float>(cy * spread * w),
                 static_cast<float>(unit(rng) * 1.8 - 0.9) * w, w);
    }
    setup.add(v[0], v[1], v[2]);
    for (const auto& t : setup.triangles) out.push_back(t);
  }
  return out;
}

// The walk gives, on rows `step` apart, the columns in [x0, x1] that
// covers() accepts, and solveRow's span, for every row of a band around
// the triangle (rows above and below it empty).
void expectWalkIsCoverage(const LlvmpipeDepth::Triangle& t, std::int64_t y0, std::int64_t y1, std::int64_t x0,
                          std::int64_t x1, std::int64_t step, int& coveredPixels) {
  LlvmpipeRowSpans walk(t, y0, step, x0, x1);
  for (std::int64_t y = y0; y <= y1; y += step) {
    std::int64_t lo, hi;
    walk.next(lo, hi);
    std::int64_t solvedLo = x0, solvedHi = x1;
    LlvmpipeRowSpans::solveRow(t, y, solvedLo, solvedHi);
    ASSERT_EQ(lo <= hi, solvedLo <= solvedHi) << "row " << y;
    if (lo <= hi) {
      ASSERT_EQ(lo, solvedLo) << "row " << y;
      ASSERT_EQ(hi, solvedHi) << "row " << y;
    }
    for (std::int64_t x = x0; x <= x1; ++x) {
      const bool inSpan = lo <= x && x <= hi;
      ASSERT_EQ(inSpan, t.covers(static_cast<int>(x), static_cast<int>(y))) << "pixel " << x << ", " << y;
      coveredPixels += inSpan ? 1 : 0;
    }
  }
}

// Vertices on the half-pixel grid, w = 1: pixel centres lie exactly on edges
// (the fill rule decides them) and a row's bound is often an exact quotient.
std::vector<LlvmpipeDepth::Triangle> gridTriangles(std::mt19937& rng, int count) {
  const std::vector<ClipPlane> noUserPlanes;
  std::vector<LlvmpipeDepth::Triangle> out;
  while (static_cast<int>(out.size()) < count) {
    LlvmpipeDepth setup{WindowTransform{320.0f, 320.0f, 240.0f, 240.0f, 0.5f, 0.5f, 480}, &noUserPlanes, {}};
    std::array<ClipVertex, 3> v;
    const int cx = static_cast<int>(rng() % 1400) - 700, cy = static_cast<int>(rng() % 1000) - 500;
    const int size = rng() % 2 == 0 ? 12 : 400;
    for (auto& p : v) {
      const int x = cx + static_cast<int>(rng() % size) - size / 2, y = cy + static_cast<int>(rng() % size) - size / 2;
      p = vertex(static_cast<float>(x) / 640.0f, static_cast<float>(y) / 480.0f, 0.0f, 1.0f);
    }
    setup.add(v[0], v[1], v[2]);
    for (const auto& t : setup.triangles) out.push_back(t);
  }
  return out;
}

TEST(LlvmpipeRowSpans, CarriedWalkIsCoverageOnGridTriangles) {
  std::mt19937 rng(88);
  int covered = 0;
  for (const auto& t : gridTriangles(rng, 1500)) {
    const std::int64_t minY = std::min({t.fixedY[0], t.fixedY[1], t.fixedY[2]}) / 256 - 2;
    const std::int64_t maxY = std::max({t.fixedY[0], t.fixedY[1], t.fixedY[2]}) / 256 + 2;
    const std::int64_t minX = std::min({t.fixedX[0], t.fixedX[1], t.fixedX[2]}) / 256 - 2;
    const std::int64_t maxX = std::max({t.fixedX[0], t.fixedX[1], t.fixedX[2]}) / 256 + 2;
    for (std::int64_t step : {1, 2}) expectWalkIsCoverage(t, minY, maxY, minX, maxX, step, covered);
  }
  EXPECT_GT(covered, 1000000);
}

TEST(LlvmpipeRowSpans, CarriedWalkIsCoverageOnEveryRow) {
  std::mt19937 rng(1994);
  int covered = 0;
  for (const auto& t : randomTriangles(rng, 1.0f, 1500)) {
    const std::int64_t minY = std::min({t.fixedY[0], t.fixedY[1], t.fixedY[2]}) / 256 - 3;
    const std::int64_t maxY = std::max({t.fixedY[0], t.fixedY[1], t.fixedY[2]}) / 256 + 3;
    const std::int64_t minX = std::min({t.fixedX[0], t.fixedX[1], t.fixedX[2]}) / 256 - 3;
    const std::int64_t maxX = std::max({t.fixedX[0], t.fixedX[1], t.fixedX[2]}) / 256 + 3;
    for (std::int64_t step : {1, 2, 3}) expectWalkIsCoverage(t, minY, maxY, minX, maxX, step, covered);
  }
  EXPECT_GT(covered, 1000000);  // large and small triangles alike
}

// Positions past 2^20 pixels (the carried walk's limit; llvmpipe's products
// wrap not far beyond): the walk solves each row, still covers() to the
// pixel, in a window around a vertex. (Further out, past 2^22 pixels,
// covers() itself wraps; no framebuffer holds such pixels.)
TEST(LlvmpipeRowSpans, FarVerticesAreSolvedRowByRow) {
  std::mt19937 rng(2026);
  int covered = 0, far = 0;
  for (const auto& t : randomTriangles(rng, 1.0e4f, 300)) {
    bool isFar = false;
    for (int k = 0; k < 3; ++k)
      isFar = isFar || std::abs(t.fixedX[k]) >= (std::int64_t{1} << 28) || std::abs(t.fixedY[k]) >= (std::int64_t{1} << 28);
    far += isFar ? 1 : 0;
    const int i = static_cast<int>(rng() % 3);
    const std::int64_t cx = t.fixedX[i] / 256, cy = t.fixedY[i] / 256;
    expectWalkIsCoverage(t, cy - 40, cy + 40, cx - 40, cx + 40, 1 + static_cast<std::int64_t>(rng() % 2), covered);
  }
  EXPECT_GT(far, 100);
  EXPECT_GT(covered, 1000);
}

}  // namespace
}  // namespace mpr
