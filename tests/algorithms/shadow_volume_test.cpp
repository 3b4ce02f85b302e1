// Shadow volumes: closed, outward, containing exactly the receivers behind
// the caster; the z-pass counting they are drawn for; the near-rectangle
// test that decides z-pass against z-fail; near-plane corners.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/shadow_volume.hpp"
#include "shadow_test_support.hpp"

namespace mpr {
namespace {

using test::allFinite;
using test::boxAt;
using test::Random;

const BoundingSphere kRoom{DVec3(0.0), 6.0};
const Vec3 kAbove{0.0f, 3.0f, 0.0f};
const Vec3 kDiagonal{2.0f, 2.0f, 2.0f};

DVec3 normalOf(const VolumeTriangle& t) {
  return glm::cross(DVec3(t[1]) - DVec3(t[0]), DVec3(t[2]) - DVec3(t[0]));
}

TEST(ShadowVolume, BoxLitFromAboveHasFourSidesAndTwoCaps) {
  const ShadowVolume v = buildShadowVolume(makeBox(), kAbove, kRoom);
  EXPECT_EQ(v.sides.size(), 4u);
  EXPECT_EQ(v.lightCap.size(), 2u);
  EXPECT_EQ(v.darkCap.size(), 2u);
  EXPECT_TRUE(v.casterClosed);
  EXPECT_EQ(v.triangles().size(), 12u);
  // The light cap is the top face exactly as the mesh draws it.
  const Mesh box = makeBox();
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(v.lightCap[static_cast<std::size_t>(k)][static_cast<std::size_t>(i)],
                box.positions[box.triangles[static_cast<std::size_t>(8 + k)][static_cast<std::size_t>(i)]]);
  // Extruded points all at the extrusion radius from the light.
  for (const auto& q : v.sides)
    for (int i = 2; i < 4; ++i)
      EXPECT_NEAR(glm::length(DVec3(q[static_cast<std::size_t>(i)]) - DVec3(kAbove)), v.extrusionRadius,
                  1e-6 * v.extrusionRadius);
}

TEST(ShadowVolume, EveryFaceFacesAwayFromAnInsidePoint) {
  // Lit from above, the volume is a convex frustum: every face's plane must
  // have the inside point (under the box) on its back side.
  const ShadowVolume v = buildShadowVolume(makeBox(), kAbove, kRoom);
  const DVec3 inside(0.1, -1.0, -0.05);
  for (const auto& t : v.triangles()) EXPECT_LT(glm::dot(normalOf(t), inside - DVec3(t[0])), 0.0);
  // The side quads alone, with the box centre.
  for (const auto& q : v.sides) {
    const DVec3 n = glm::cross(DVec3(q[1]) - DVec3(q[0]), DVec3(q[2]) - DVec3(q[0]));
    EXPECT_LT(glm::dot(n, DVec3(0.0) - DVec3(q[0])), 0.0);
    // Planar: the fourth corner is on the plane of the first three.
    EXPECT_NEAR(glm::dot(glm::normalize(n), DVec3(q[3]) - DVec3(q[0])), 0.0, 1e-5 * v.extrusionRadius);
  }
}

TEST(ShadowVolume, ClosedCastersGiveWatertightOutwardSurfaces) {
  const std::vector<std::pair<Mesh, Vec3>> cases = {
      {makeBox(), kAbove},
      {makeBox(), kDiagonal},
      {makeBox(), Vec3(0.0f, 0.5f, 3.0f)},  // light in the top face's plane
      {makeSphere(32, 16), Vec3(3.1f, 2.3f, -1.7f)},
      {makeSphere(12, 6), Vec3(0.0f, 4.0f, 0.0f)},
      {boxAt({0.5f, 1.0f, -0.3f}, {2.0f, 0.2f, 1.0f}), Vec3(-0.7f, 4.0f, 1.1f)},
  };
  for (const auto& [mesh, light] : cases) {
    const ShadowVolume v = buildShadowVolume(mesh, light, kRoom);
    const auto tris = v.triangles();
    ASSERT_FALSE(tris.empty());
    EXPECT_TRUE(allFinite(tris));
    // Every edge shared by exactly two faces, in opposite directions.
    EXPECT_EQ(test::manifoldEdgeViolations(tris), 0);
    // Zero net flux: the area vectors of a closed surface sum to zero.
    DVec3 flux(0.0), scale(0.0);
    for (const auto& t : tris) flux += test::areaVector(t), scale += glm::abs(test::areaVector(t));
    EXPECT_LT(glm::length(flux), 1e-9 * glm::length(scale));
    // Outward: positive enclosed volume.
    EXPECT_GT(test::enclosedVolume(tris), 0.0);
  }
}

TEST(ShadowVolume, DarkCapLiesOutsideTheReceiverSphereEverywhere) {
  // A light just above a wide lit face: the cap corners are far apart, and a
  // flat cap triangle between them dips back towards the light; extruding
  // each corner just past the sphere would let the cap cut through it.
  const Mesh slab = boxAt({0.0f, 0.0f, 0.0f}, {8.0f, 0.2f, 8.0f});
  for (const Vec3 light : {Vec3(0.0f, 0.15f, 0.0f), Vec3(3.0f, 0.5f, -2.0f), Vec3(0.0f, 5.0f, 0.0f)}) {
    const ShadowVolume v = buildShadowVolume(slab, light, kRoom);
    ASSERT_FALSE(v.darkCap.empty());
    for (const auto& t : v.darkCap) {
      const DVec3 c = test::closestPointOnTriangle(kRoom.centre, DVec3(t[0]), DVec3(t[1]), DVec3(t[2]));
      EXPECT_GT(glm::length(c - kRoom.centre), kRoom.radius);
    }
    for (const auto& q : v.sides) {
      // The side quad's far edge too (it is a cap edge).
      const DVec3 c = test::closestPointOnSegment(kRoom.centre, DVec3(q[2]), DVec3(q[3]));
      EXPECT_GT(glm::length(c - kRoom.centre), kRoom.radius);
    }
  }
}

TEST(ShadowVolume, PointsBehindTheBoxAreInside) {
  const ShadowVolume v = buildShadowVolume(makeBox(), kAbove, kRoom);
  // The frustum from (0, 3, 0) through the top square (y = 0.5): half
  // width 0.5 * (3 - y) / 2.5 at height y, so 0.8 at y = -1.
  EXPECT_TRUE(pointInsideShadowVolume(v, {0.0f, -1.0f, 0.0f}));
  EXPECT_TRUE(pointInsideShadowVolume(v, {0.7f, -1.0f, 0.0f}));
  EXPECT_TRUE(pointInsideShadowVolume(v, {-0.75f, -1.0f, 0.75f}));
  EXPECT_TRUE(pointInsideShadowVolume(v, {0.0f, 0.0f, 0.0f}));   // inside the caster
  EXPECT_TRUE(pointInsideShadowVolume(v, {0.3f, -5.9f, 0.2f}));  // deep down, still in the room
  EXPECT_FALSE(pointInsideShadowVolume(v, {0.9f, -1.0f, 0.0f}));
  EXPECT_FALSE(pointInsideShadowVolume(v, {0.0f, 1.0f, 0.0f}));  // between light and box
  EXPECT_FALSE(pointInsideShadowVolume(v, {0.0f, 4.0f, 0.0f}));  // above the light
  EXPECT_FALSE(pointInsideShadowVolume(v, {3.0f, -1.0f, 2.0f}));
  EXPECT_NEAR(shadowVolumeWinding(v, {0.0f, -1.0f, 0.0f}), 1.0, 1e-9);
  EXPECT_NEAR(shadowVolumeWinding(v, {3.0f, -1.0f, 2.0f}), 0.0, 1e-9);
}

// The truth for a box caster: p is shadowed when the segment from the light
// to p meets the box. Points within `margin` of the shadow's boundary are
// skipped (the truth flips between the shrunk and the grown box).
void expectInsideMatchesTruth(const Mesh& box, DVec3 lo, DVec3 hi, Vec3 light, std::uint64_t seed) {
  const ShadowVolume v = buildShadowVolume(box, light, kRoom);
  Random rng(seed);
  const double margin = 1e-3;
  int checked = 0, shadowed = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 p = rng.point(-kRoom.radius, kRoom.radius);
    if (!kRoom.contains(DVec3(p))) continue;
    const bool grown = test::segmentHitsBox(DVec3(light), DVec3(p), lo - margin, hi + margin);
    const bool shrunk = test::segmentHitsBox(DVec3(light), DVec3(p), lo + margin, hi - margin);
    if (grown != shrunk) continue;
    ++checked;
    shadowed += grown ? 1 : 0;
    EXPECT_EQ(pointInsideShadowVolume(v, p), grown) << p.x << ", " << p.y << ", " << p.z;
  }
  EXPECT_GT(checked, 1000);
  EXPECT_GT(shadowed, 10);
}

TEST(ShadowVolume, EveryReceiverBehindTheCasterIsInsideAndNoOtherPoint) {
  const DVec3 lo(-0.5), hi(0.5);
  expectInsideMatchesTruth(makeBox(), lo, hi, kAbove, 1);
  expectInsideMatchesTruth(makeBox(), lo, hi, kDiagonal, 2);
  expectInsideMatchesTruth(makeBox(), lo, hi, {0.1f, 0.7f, -0.2f}, 3);  // light close to the top
  expectInsideMatchesTruth(makeBox(), lo, hi, {5.5f, 0.3f, 0.0f}, 4);   // light in the room's edge
  // A wide, thin slab lit from just above.
  expectInsideMatchesTruth(boxAt(Vec3(0.0f), {8.0f, 0.2f, 8.0f}), DVec3(-4.0, -0.1, -4.0), DVec3(4.0, 0.1, 4.0),
                           {0.5f, 0.3f, 0.2f}, 5);
}

TEST(ShadowVolume, ZPassCountsEqualInsideness) {
  // Heidmann's in-out principle on this geometry: from an eye outside every
  // volume, front faces (facing the eye) crossed before a point count +1,
  // back faces -1; the sum must be 1 for shadowed points and 0 otherwise.
  const ShadowVolume v = buildShadowVolume(makeBox(), kDiagonal, kRoom);
  const auto tris = v.triangles();
  const DVec3 eye(4.5, 0.4, -3.3);
  ASSERT_FALSE(pointInsideShadowVolume(v, Vec3(eye)));
  Random rng(11);
  int inside = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p = rng.point(-5.0, 5.0);
    int count = 0;
    for (const auto& t : tris) count += test::segmentCrossing(eye, DVec3(p), DVec3(t[0]), DVec3(t[1]), DVec3(t[2]));
    const bool in = pointInsideShadowVolume(v, p);
    inside += in ? 1 : 0;
    EXPECT_EQ(count, in ? 1 : 0) << p.x << ", " << p.y << ", " << p.z;
  }
  EXPECT_GT(inside, 50);
}

TEST(ShadowVolume, OpenQuadStillGivesAClosedVolume) {
  const Mesh quad = makeQuad();
  const Vec3 light(0.2f, 0.1f, 2.0f);
  const ShadowVolume v = buildShadowVolume(quad, light, kRoom);
  EXPECT_FALSE(v.casterClosed);
  EXPECT_EQ(v.casterBoundaryEdges, 4u);
  EXPECT_EQ(v.sides.size(), 4u);
  EXPECT_EQ(v.lightCap.size(), 2u);
  EXPECT_EQ(test::manifoldEdgeViolations(v.triangles()), 0);
  EXPECT_TRUE(pointInsideShadowVolume(v, {0.0f, 0.0f, -1.0f}));
  EXPECT_FALSE(pointInsideShadowVolume(v, {0.0f, 0.0f, 1.0f}));
  EXPECT_FALSE(pointInsideShadowVolume(v, {2.0f, 0.0f, -1.0f}));
  // Lit from behind: nothing.
  EXPECT_TRUE(buildShadowVolume(quad, {0.0f, 0.0f, -2.0f}, kRoom).empty());
}

TEST(ShadowVolume, DegenerateLightsGiveNoNaN) {
  // A light on a corner lights nothing: an empty volume, never inside.
  const ShadowVolume corner = buildShadowVolume(makeBox(), {0.5f, 0.5f, 0.5f}, kRoom);
  EXPECT_TRUE(corner.empty());
  EXPECT_TRUE(corner.triangles().empty());
  EXPECT_EQ(corner.extrusionRadius, 0.0);
  EXPECT_FALSE(pointInsideShadowVolume(corner, {-1.0f, -1.0f, -1.0f}));
  EXPECT_FALSE(shadowVolumeTouchesNearRectangle(corner, nearPlaneCorners({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 45, 1, 0.1),
                                                {0, 0, 3}));
  // In a face's plane: that face is unlit, the rest still closes.
  const ShadowVolume plane = buildShadowVolume(makeBox(), {0.0f, 0.5f, 3.0f}, kRoom);
  EXPECT_TRUE(allFinite(plane.triangles()));
  EXPECT_EQ(plane.lightCap.size(), 2u);
  EXPECT_TRUE(std::isfinite(plane.extrusionRadius));
  // Receivers' sphere of radius zero around the light: the dark cap still
  // lies beyond the light cap (the top face's corners are sqrt(6.75) away).
  const ShadowVolume tiny = buildShadowVolume(makeBox(), kAbove, BoundingSphere{DVec3(kAbove), 0.0});
  EXPECT_TRUE(allFinite(tiny.triangles()));
  EXPECT_EQ(test::manifoldEdgeViolations(tiny.triangles()), 0);
  for (const auto& t : tiny.darkCap) {
    const DVec3 c = test::closestPointOnTriangle(DVec3(kAbove), DVec3(t[0]), DVec3(t[1]), DVec3(t[2]));
    EXPECT_GT(glm::length(c - DVec3(kAbove)), std::sqrt(6.75));
  }
}

TEST(ShadowVolume, ZeroAreaTrianglesChangeNothing) {
  Mesh box = makeBox();
  box.triangles.push_back({16, 16, 17});
  const auto n = static_cast<std::uint32_t>(box.positions.size());
  box.positions.push_back({-0.5f, 0.5f, 0.5f});
  box.positions.push_back({0.0f, 0.5f, 0.5f});
  box.positions.push_back({0.5f, 0.5f, 0.5f});
  box.triangles.push_back({n, n + 2, n + 1});
  const ShadowVolume a = buildShadowVolume(makeBox(), kDiagonal, kRoom), b = buildShadowVolume(box, kDiagonal, kRoom);
  EXPECT_EQ(a.triangles(), b.triangles());
}

TEST(ShadowVolume, TouchingBoxesGiveABalancedVolume) {
  const Mesh two = test::concat(boxAt({0, 0, 0}), boxAt({1, 1, 0}));
  const ShadowVolume v = buildShadowVolume(two, {0.3f, 5.0f, 0.1f}, kRoom);
  EXPECT_TRUE(v.casterClosed);
  EXPECT_EQ(test::balanceViolations(v.triangles()), 0);
  EXPECT_TRUE(pointInsideShadowVolume(v, {0.0f, -2.0f, 0.0f}));   // under A
  EXPECT_TRUE(pointInsideShadowVolume(v, {1.0f, 0.0f, 0.0f}));    // under B, beside A
  EXPECT_FALSE(pointInsideShadowVolume(v, {-1.5f, 0.0f, 0.0f}));
}

TEST(ShadowVolume, BoundingSpheres) {
  const BoundingSphere s = boundingSphereOf(makeBox().positions);
  EXPECT_EQ(s.centre, DVec3(0.0));
  EXPECT_NEAR(s.radius, std::sqrt(0.75), 1e-12);
  Scene scene;
  scene.objects.push_back({"a", boxAt({2, 0, 0}), 0, 0});
  scene.objects.push_back({"b", boxAt({-2, 0, 0}), 0, 0});
  const BoundingSphere t = sceneBoundingSphere(scene);
  EXPECT_EQ(t.centre, DVec3(0.0));
  for (const auto& o : scene.objects)
    for (const Vec3& p : o.mesh.positions) EXPECT_TRUE(t.contains(DVec3(p)));
}

// ---- near rectangle and z-pass / z-fail

TEST(NearPlaneCorners, MatchGluLookAtAndPerspective) {
  const Vec3 eye(1.0f, 2.0f, 5.0f), at(0.2f, 0.9f, -1.0f), up(0.1f, 1.0f, 0.0f);
  const double fov = 50.0, aspect = 4.0 / 3.0, zNear = 0.25;
  const auto c = nearPlaneCorners(eye, at, up, fov, aspect, zNear);
  const glm::dmat4 view = glm::lookAt(DVec3(eye), DVec3(at), DVec3(up));
  const glm::dmat4 proj = glm::perspective(glm::radians(fov), aspect, zNear, 100.0);
  const double want[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int i = 0; i < 4; ++i) {
    const glm::dvec4 clip = proj * view * glm::dvec4(DVec3(c[static_cast<std::size_t>(i)]), 1.0);
    EXPECT_NEAR(clip.x / clip.w, want[i][0], 1e-5);
    EXPECT_NEAR(clip.y / clip.w, want[i][1], 1e-5);
    EXPECT_NEAR(clip.z / clip.w, -1.0, 1e-5);
  }
  // Counter-clockwise seen from the eye: the normal points at the eye.
  const DVec3 n = glm::cross(DVec3(c[1]) - DVec3(c[0]), DVec3(c[2]) - DVec3(c[0]));
  EXPECT_GT(glm::dot(n, DVec3(eye) - DVec3(c[0])), 0.0);
  // Camera overload, and a singular up gives numbers, not NaN.
  Camera cam;
  const auto d = nearPlaneCorners(cam, 1.5);
  const auto e = nearPlaneCorners(cam.position, cam.lookAt, cam.up, cam.fovY, 1.5, cam.near);
  EXPECT_EQ(d, e);
  for (const Vec3& p : nearPlaneCorners({0, 5, 0}, {0, 0, 0}, {0, 1, 0}, 45, 1, 0.1))
    EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
}

TEST(TrianglesMayIntersect, BasicCases) {
  using T = std::array<DVec3, 3>;
  const T base{DVec3(0, 0, 0), DVec3(2, 0, 0), DVec3(0, 2, 0)};
  EXPECT_TRUE(trianglesMayIntersect(base, T{DVec3(0.5, 0.5, -1), DVec3(0.5, 0.5, 1), DVec3(1.5, 0.5, 0)}));
  EXPECT_FALSE(trianglesMayIntersect(base, T{DVec3(0.5, 0.5, 0.1), DVec3(0.5, 0.5, 1), DVec3(1.5, 0.5, 0.5)}));
  EXPECT_FALSE(trianglesMayIntersect(base, T{DVec3(3, 3, -1), DVec3(3, 3, 1), DVec3(4, 3, 0)}));
  // Coplanar overlapping / disjoint (separated across the hypotenuse).
  EXPECT_TRUE(trianglesMayIntersect(base, T{DVec3(0.5, 0.5, 0), DVec3(3, 0.5, 0), DVec3(0.5, 3, 0)}));
  EXPECT_FALSE(trianglesMayIntersect(base, T{DVec3(2, 2, 0), DVec3(3, 2, 0), DVec3(2, 3, 0)}));
  // Touching at one corner counts.
  EXPECT_TRUE(trianglesMayIntersect(base, T{DVec3(2, 0, 0), DVec3(3, 0, 1), DVec3(3, 1, -1)}));
  // An edge piercing the interior without any corner inside.
  EXPECT_TRUE(trianglesMayIntersect(base, T{DVec3(0.3, 0.3, -5), DVec3(0.3, 0.3, 5), DVec3(-10, -10, 0.1)}));
}

TEST(NearRectangle, EyeInsideTheVolume) {
  const ShadowVolume v = buildShadowVolume(makeBox(), kAbove, kRoom);
  const Vec3 eye(0.1f, -2.0f, 0.0f);
  ASSERT_TRUE(pointInsideShadowVolume(v, eye));
  EXPECT_TRUE(shadowVolumeTouchesNearRectangle(v, nearPlaneCorners(eye, {0.1f, -2.0f, -1.0f}, {0, 1, 0}, 45, 1, 0.1),
                                               eye));
}

TEST(NearRectangle, NearPlaneCutsAThinShadowColumn) {
  // A small box under the light casts a thin column; a camera beside it
  // with a large near rectangle has the column pass through the rectangle's
  // middle, with the eye and all four corners outside.
  const Mesh small = boxAt(Vec3(0.0f), Vec3(0.1f));
  const ShadowVolume v = buildShadowVolume(small, kAbove, kRoom);
  const Vec3 eye(0.0f, -1.0f, 1.0f);
  const auto corners = nearPlaneCorners(eye, {0.0f, -1.0f, -5.0f}, {0, 1, 0}, 90.0, 1.0, 1.0);
  ASSERT_FALSE(pointInsideShadowVolume(v, eye));
  for (const Vec3& c : corners) ASSERT_FALSE(pointInsideShadowVolume(v, c));
  EXPECT_TRUE(shadowVolumeTouchesNearRectangle(v, corners, eye));
  // Moved back a little, the near plane no longer reaches the column.
  const Vec3 back(0.0f, -1.0f, 1.5f);
  EXPECT_FALSE(
      shadowVolumeTouchesNearRectangle(v, nearPlaneCorners(back, {0.0f, -1.0f, -5.0f}, {0, 1, 0}, 90.0, 1.0, 0.1), back));
}

TEST(NearRectangle, CamerasFarAwayOrLookingAwayAreSafe) {
  const ShadowVolume v = buildShadowVolume(makeBox(), kAbove, kRoom);
  const Vec3 far(10.0f, 0.0f, 10.0f);
  EXPECT_FALSE(shadowVolumeTouchesNearRectangle(v, nearPlaneCorners(far, {0, 0, 0}, {0, 1, 0}, 45, 1.5, 0.1), far));
  const Vec3 side(3.0f, -1.0f, 0.0f);
  EXPECT_FALSE(shadowVolumeTouchesNearRectangle(v, nearPlaneCorners(side, {0, -1, 0}, {0, 1, 0}, 60, 1.5, 0.1), side));
  // Looking at the volume from just above the light: outside it.
  const Vec3 top(0.0f, 4.0f, 0.5f);
  EXPECT_FALSE(shadowVolumeTouchesNearRectangle(v, nearPlaneCorners(top, {0, 0, 0}, {0, 0, -1}, 45, 1, 0.1), top));
}

TEST(NearRectangle, NeverMissesARectangleThatIsPartlyInside) {
  // Conservative: for random cameras, whenever a sample of the near
  // rectangle lies inside the volume, the test must say so.
  const ShadowVolume v = buildShadowVolume(makeBox(), kDiagonal, kRoom);
  Random rng(23);
  int hits = 0, positives = 0;
  for (int i = 0; i < 300; ++i) {
    const Vec3 eye = rng.point(-3.0, 3.0), at = rng.point(-3.0, 3.0);
    if (glm::length(DVec3(at) - DVec3(eye)) < 0.1) continue;
    const double zNear = rng.uniform(0.05, 1.5);
    const auto c = nearPlaneCorners(eye, at, {0, 1, 0}, rng.uniform(20.0, 100.0), rng.uniform(0.5, 2.0), zNear);
    bool sampleInside = false;
    for (int a = 0; a <= 8 && !sampleInside; ++a)
      for (int b = 0; b <= 8 && !sampleInside; ++b) {
        const DVec3 p = DVec3(c[0]) + (DVec3(c[1]) - DVec3(c[0])) * (a / 8.0) + (DVec3(c[3]) - DVec3(c[0])) * (b / 8.0);
        sampleInside = pointInsideShadowVolume(v, Vec3(p));
      }
    const bool touches = shadowVolumeTouchesNearRectangle(v, c, eye);
    hits += sampleInside ? 1 : 0;
    positives += touches ? 1 : 0;
    if (sampleInside) {
      EXPECT_TRUE(touches) << "camera " << i;
    }
  }
  EXPECT_GT(hits, 10);
  EXPECT_LT(positives, 300);
}

}  // namespace
}  // namespace mpr
