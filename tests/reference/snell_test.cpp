// Snell's law both ways, and the sampler's strata.
#include "reference/snell.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "reference/sampler.hpp"
#include "scene/slab_refraction.hpp"

namespace mpr {
namespace {

SpecularFace glassInZ0() {
  SpecularFace f;
  f.kind = MaterialKind::Refractive;
  f.normal = {0, 0, 1};
  f.ior = 1.5;
  return f;
}

TEST(Snell, CrossingObeysSnellsLaw) {
  const SpecularFace f = glassInZ0();
  // Light 2 above the plane, the point 1 below and 3 across.
  const DVec3 a(0, 0, 2), b(3, 0, -1);
  const auto x = snellCrossing(f, a, b);
  ASSERT_TRUE(x.has_value());
  EXPECT_NEAR(x->z, 0.0, 1e-15);
  const double sinA = x->x / std::hypot(x->x, 2.0), sinB = (3.0 - x->x) / std::hypot(3.0 - x->x, 1.0);
  EXPECT_NEAR(1.0 * sinA, 1.5 * sinB, 1e-12);  // air above, glass below
  // From behind the media swap: the same path backwards.
  const auto back = snellCrossing(f, b, a);
  ASSERT_TRUE(back.has_value());
  EXPECT_NEAR(back->x, x->x, 1e-12);
  EXPECT_FALSE(snellCrossing(f, a, DVec3(1, 0, 1)).has_value());  // same side
}

// A slab (thickness 0.2): the crossing X where light from a, shifted
// sideways by the slab and going on parallel to a -> X, passes through b:
// b - shift(X - a) lies on the line a -> X. Seen from either side alike.
TEST(Snell, SlabCrossingGoesOnParallel) {
  SpecularFace f = glassInZ0();
  f.thickness = 0.2;
  const DVec3 a(0, 0, 2), b(3, 0.5, -1);
  const auto x = slabCrossing(f, a, b);
  ASSERT_TRUE(x.has_value());
  EXPECT_NEAR(x->z, 0.0, 1e-15);
  const DVec3 d = glm::normalize(*x - a);
  const DVec3 shifted = b - slabShift(d, f.normal, 1.5, 0.2);
  EXPECT_NEAR(glm::length(glm::cross(glm::normalize(shifted - a), d)), 0.0, 1e-12);
  // The slab shifts the light back toward the normal, so it enters beyond
  // the straight line's crossing (2, 1/3, 0).
  EXPECT_GT(x->x, 2.0);
  const auto back = slabCrossing(f, b, a);  // from the other side, the same rule
  ASSERT_TRUE(back.has_value());
  const DVec3 e = glm::normalize(*back - b);
  EXPECT_NEAR(glm::length(glm::cross(glm::normalize(a - slabShift(e, f.normal, 1.5, 0.2) - b), e)), 0.0, 1e-12);
  EXPECT_FALSE(slabCrossing(f, a, DVec3(1, 0, 1)).has_value());  // same side
}

TEST(Snell, DirectionAndTheCriticalAngle) {
  // 45 degrees into glass: sin(theta_t) = 0.707107 / 1.5 = 0.471405.
  const DVec3 d = glm::normalize(DVec3(1, 0, -1));
  const auto t = refractDirection(d, {0, 0, 1}, 1.0 / 1.5);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(t->x, 0.471405, 1e-6);
  // Out of glass at 45 degrees: 1.5 * 0.707 > 1, past the critical angle (41.8).
  EXPECT_FALSE(refractDirection(d, {0, 0, 1}, 1.5).has_value());
}

TEST(Sampler, PermutationIsABijectionAndGridsCoverEveryCell) {
  for (std::uint32_t n : {1u, 7u, 16u, 100u}) {
    std::set<std::uint32_t> seen;
    for (std::uint32_t i = 0; i < n; ++i) seen.insert(permute(i, n, 12345u));
    EXPECT_EQ(seen.size(), n);
    EXPECT_LT(*seen.rbegin(), n);
  }
  const PixelSampler s{3, 4, 16};
  std::set<int> cells;
  for (std::uint32_t i = 0; i < 16; ++i) {
    const DVec2 o = s.pixelOffset(i);
    cells.insert(static_cast<int>(o.x * 4) + 4 * static_cast<int>(o.y * 4));
  }
  EXPECT_EQ(cells.size(), 16u);
  // The pixel's light points, one per sample, fill a 4x4 grid as well.
  cells.clear();
  for (std::uint32_t i = 0; i < 16; ++i) {
    const DVec2 u = s.lightPoint(i, 0, 1, 0);
    cells.insert(static_cast<int>(u.x * 4) + 4 * static_cast<int>(u.y * 4));
  }
  EXPECT_EQ(cells.size(), 16u);
}

}  // namespace
}  // namespace mpr
