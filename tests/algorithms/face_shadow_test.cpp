// Planes, reflections, and the 1994 paper's pre-shadow checks for
// reflected and refracted shadows (Figure 4, draw_shadow_volume with
// MUST_INTERSECT / CAN'T_INTERSECT): which side of a specular face an
// object lies on, and whether its shadow reaches the face.
#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/plane.hpp"
#include "algorithms/shadow_volume.hpp"
#include "shadow_test_support.hpp"

namespace mpr {
namespace {

using test::boxAt;
using test::Random;

// A 2 x 2 mirror in the floor plane y = 0, facing up.
const std::vector<Vec3> kMirror = {{-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}};
const Vec3 kLight{0.0f, 3.0f, 0.0f};

TEST(Plane, OfPolygonThroughPointAndSignedDistance) {
  const Plane p = planeOfPolygon(kMirror);
  EXPECT_EQ(p.normal, DVec3(0, 1, 0));
  EXPECT_EQ(p.d, 0.0);
  EXPECT_EQ(p.signedDistance(Vec3(3, 2, -7)), 2.0);
  const Plane q = Plane::throughPoint(DVec3(0, 0, -2), DVec3(5, 5, 1.5));
  EXPECT_EQ(q.normal, DVec3(0, 0, -1));
  EXPECT_EQ(q.d, 1.5);
  EXPECT_EQ(q.signedDistance(DVec3(0, 0, 0)), 1.5);
  EXPECT_EQ(q.flipped().signedDistance(DVec3(0, 0, 0)), -1.5);
  EXPECT_EQ(q.equation(), DVec4(0, 0, -1, 1.5));
  // No NaN from a zero normal or an empty polygon.
  EXPECT_EQ(Plane::throughPoint(DVec3(0.0), DVec3(1.0)).normal, DVec3(0, 0, 1));
  EXPECT_TRUE(std::isfinite(planeOfPolygon({}).d));
  // Clockwise winding flips the normal.
  const std::vector<Vec3> cw(kMirror.rbegin(), kMirror.rend());
  EXPECT_EQ(planeOfPolygon(cw).normal, DVec3(0, -1, 0));
}

TEST(Plane, ReflectPoint) {
  const Plane floor1 = Plane::throughPoint(DVec3(0, 1, 0), DVec3(0, 1, 0));  // y = 1
  EXPECT_EQ(reflectPoint(Vec3(2, 3, -4), floor1), Vec3(2, -1, -4));
  EXPECT_EQ(reflectPoint(DVec3(2, 1, -4), floor1), DVec3(2, 1, -4));  // on the plane: fixed
  // An oblique plane: reflecting twice is the identity, the midpoint lies on
  // the plane and the offset is along the normal.
  const Plane oblique = Plane::throughPoint(DVec3(1, 2, -0.5), DVec3(0.3, -0.2, 1.1));
  Random rng(3);
  for (int i = 0; i < 100; ++i) {
    const DVec3 p(rng.point(-5, 5));
    const DVec3 r = reflectPoint(p, oblique);
    EXPECT_NEAR(glm::length(reflectPoint(r, oblique) - p), 0.0, 1e-12);
    EXPECT_NEAR(oblique.signedDistance((p + r) * 0.5), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(glm::cross(r - p, oblique.normal)), 0.0, 1e-12);
    EXPECT_NEAR(oblique.signedDistance(r), -oblique.signedDistance(p), 1e-12);
  }
}

TEST(FaceSide, ObjectsAboveBelowAndAcrossTheMirror) {
  const Plane mirror = planeOfPolygon(kMirror);
  EXPECT_EQ(classifyAgainstFace(boxAt({0.0f, 1.5f, 0.0f}), mirror, kLight), FaceSide::LightSide);
  EXPECT_EQ(classifyAgainstFace(boxAt({0.0f, -1.5f, 0.0f}), mirror, kLight), FaceSide::FarSide);
  EXPECT_EQ(classifyAgainstFace(boxAt({0.3f, 0.2f, 0.0f}), mirror, kLight), FaceSide::Straddles);
  // Resting on the plane (touching) counts as straddling: both checks apply.
  EXPECT_EQ(classifyAgainstFace(boxAt({0.0f, 0.5f, 0.0f}), mirror, kLight), FaceSide::Straddles);
  // Relative to the light, not to the plane's normal.
  const Vec3 under(0.0f, -3.0f, 0.0f);
  EXPECT_EQ(classifyAgainstFace(boxAt({0.0f, 1.5f, 0.0f}), mirror, under), FaceSide::FarSide);
  EXPECT_EQ(classifyAgainstFace(boxAt({0.0f, 1.5f, 0.0f}), mirror.flipped(), kLight), FaceSide::LightSide);
  // The light in the plane: no side is the light's.
  EXPECT_EQ(classifyAgainstFace(boxAt({0.0f, 1.5f, 0.0f}), mirror, {4.0f, 0.0f, 0.0f}), FaceSide::Straddles);
  // Nothing to cast.
  EXPECT_EQ(classifyAgainstFace(Mesh{}, mirror, kLight), FaceSide::FarSide);
}

TEST(ShadowCrossesFace, HandPickedCases) {
  // Between light and mirror, over it: the shadow falls on the mirror.
  EXPECT_TRUE(shadowCrossesFace(boxAt({0.0f, 1.5f, 0.0f}), kMirror, kLight));
  // Its shadow half on the mirror: rays through x = 0.35 and 0.85 at
  // y = 1.25 land at x = 0.6 and 1.46.
  EXPECT_TRUE(shadowCrossesFace(boxAt({0.6f, 1.5f, 0.0f}, Vec3(0.5f)), kMirror, kLight));
  // Off to the side: rays through it meet y = 0 near x = 7.5.
  EXPECT_FALSE(shadowCrossesFace(boxAt({5.0f, 1.0f, 0.0f}), kMirror, kLight));
  // Beyond the mirror (behind it from the light): never.
  EXPECT_FALSE(shadowCrossesFace(boxAt({0.0f, -1.5f, 0.0f}), kMirror, kLight));
  // Above the light: its shadow goes up.
  EXPECT_FALSE(shadowCrossesFace(boxAt({0.0f, 5.0f, 0.0f}), kMirror, kLight));
  // Just outside the pyramid's slanted side: the ray through the box's
  // innermost corner (1, 1, z) lands at x = 1 * 3 / (3 - 1) = 1.5 > 1.
  EXPECT_FALSE(shadowCrossesFace(boxAt({1.25f, 1.25f, 0.0f}, Vec3(0.5f)), kMirror, kLight));
  // The light itself in the mirror's plane: a flat pyramid; an object in
  // that plane between light and mirror still blocks, one above does not.
  const Vec3 side(5.0f, 0.0f, 0.0f);
  EXPECT_TRUE(shadowCrossesFace(boxAt({3.0f, 0.0f, 0.0f}, Vec3(0.4f)), kMirror, side));
  EXPECT_FALSE(shadowCrossesFace(boxAt({3.0f, 1.0f, 0.0f}, Vec3(0.4f)), kMirror, side));
  // A thin triangle through the pyramid without any corner inside it.
  Mesh blade;
  blade.positions = {{-5.0f, 1.5f, 0.0f}, {5.0f, 1.5f, 0.1f}, {5.0f, 1.5f, -0.1f}};
  blade.triangles = {{0, 1, 2}};
  EXPECT_TRUE(shadowCrossesFace(blade, kMirror, kLight));
}

TEST(ShadowCrossesFace, NeverMissesARayThatReachesTheFace) {
  // Conservative: sample points on the object's triangles; whenever the ray
  // from the light through one of them continues to hit the mirror, the
  // predicate must be true.
  const Plane mirror = planeOfPolygon(kMirror);
  Random rng(17);
  int crossing = 0, predicted = 0;
  for (int i = 0; i < 300; ++i) {
    const Vec3 centre = rng.point(-3.0, 3.0);
    const Vec3 light = rng.point(-4.0, 4.0);
    const Mesh object = boxAt(centre, Vec3(static_cast<float>(rng.uniform(0.1, 1.0))));
    bool hit = false;
    for (const auto& t : object.triangles)
      for (int a = 0; a <= 6 && !hit; ++a)
        for (int b = 0; a + b <= 6 && !hit; ++b) {
          const DVec3 p0(object.positions[t[0]]), p1(object.positions[t[1]]), p2(object.positions[t[2]]);
          const DVec3 p = p0 + (p1 - p0) * (a / 6.0) + (p2 - p0) * (b / 6.0);
          const double sl = mirror.signedDistance(light), sp = mirror.signedDistance(p);
          if (!(sl > 0.0 && sp > 0.0 && sp < sl) && !(sl < 0.0 && sp < 0.0 && sp > sl)) continue;
          const DVec3 q = DVec3(light) + (p - DVec3(light)) * (sl / (sl - sp));  // on y = 0, past p
          hit = std::fabs(q.x) <= 1.0 && std::fabs(q.z) <= 1.0;
        }
    const bool says = shadowCrossesFace(object, kMirror, light);
    crossing += hit ? 1 : 0;
    predicted += says ? 1 : 0;
    if (hit) {
      EXPECT_TRUE(says) << "case " << i;
    }
    // And a FarSide object never crosses.
    if (classifyAgainstFace(object, mirror, light) == FaceSide::FarSide) {
      EXPECT_FALSE(says) << "case " << i;
    }
  }
  EXPECT_GT(crossing, 10);
  EXPECT_LT(predicted, 300);
}

}  // namespace
}  // namespace mpr
