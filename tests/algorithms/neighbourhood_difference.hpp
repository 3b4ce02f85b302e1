#pragma once
// The metamorphic renders' measure (docs/dev/reliability.md, "Numerically
// hard cases"): each channel of each pixel of image b must lie within the
// range that channel takes over the pixel's neighbourhood in image a (reach
// 1: 3x3, 2: 5x5), widened by 1 -- an edge may move by a pixel, a colour by
// one step, and nothing else may change.
#include <algorithm>
#include <cstdlib>
#include <vector>

#include "framebuffer/blend.hpp"

namespace mpr {

struct NeighbourhoodDifference {
  int outsideRange = 0;  // pixels with a channel outside their neighbourhood's range (+-1)
  int changed = 0;       // pixels that changed by more than 1
};

inline NeighbourhoodDifference neighbourhoodDifference(const std::vector<Rgba8>& a, const std::vector<Rgba8>& b,
                                                       int width, int height, int reach) {
  NeighbourhoodDifference d;
  const auto at = [width, height](int px, int py) {
    return static_cast<std::size_t>(std::clamp(py, 0, height - 1) * width + std::clamp(px, 0, width - 1));
  };
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Rgba8& got = b[at(x, y)];
      bool outside = false, changed = false;
      for (int k = 0; k < 4; ++k) {
        int lo = 255, hi = 0;
        for (int dy = -reach; dy <= reach; ++dy)
          for (int dx = -reach; dx <= reach; ++dx) {
            const int v = a[at(x + dx, y + dy)][k];
            lo = std::min(lo, v), hi = std::max(hi, v);
          }
        outside = outside || got[k] < lo - 1 || got[k] > hi + 1;
        changed = changed || std::abs(int{got[k]} - int{a[at(x, y)][k]}) > 1;
      }
      d.outsideRange += outside;
      d.changed += changed;
    }
  return d;
}

}  // namespace mpr
