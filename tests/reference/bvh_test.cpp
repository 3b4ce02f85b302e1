// The BVH finds what testing every triangle finds.
#include "reference/bvh.hpp"

#include <gtest/gtest.h>

#include "reference/sampler.hpp"
#include "scene/scene_loader.hpp"

namespace mpr {
namespace {

TEST(Bvh, ClosestAndAnyHitAgreeWithEveryTriangle) {
  const Scene scene = loadSceneText(defaultSceneText(), "<default scene>");
  const Bvh bvh(scene);
  ASSERT_EQ(bvh.triangles().size(), scene.triangleCount());
  // Brute force over every triangle, through a one-triangle tree each.
  int hits = 0;
  for (std::uint32_t i = 0; i < 400; ++i) {
    const DVec3 o(-3.0 + 6.0 * unitFromBits(mix64(3 * i)), 0.2 + 3.0 * unitFromBits(mix64(3 * i + 1)), 4.0);
    const DVec3 target(-4.0 + 8.0 * unitFromBits(mix64(3 * i + 2)), 0.5 * (i % 7), -3.0);
    const Ray ray{o, glm::normalize(target - o)};
    const Hit h = bvh.closest(ray, 0.0, 1e30, Facing::Both);
    double best = 1e300;
    for (const BvhTriangle& t : bvh.triangles()) {
      Scene one;
      one.materials.resize(1);
      SceneObject obj;
      obj.mesh.positions = {Vec3(t.p0), Vec3(t.p0 + t.e1), Vec3(t.p0 + t.e2)};
      obj.mesh.normals.assign(3, Vec3(0, 0, 1));
      obj.mesh.triangles = {{0, 1, 2}};
      one.objects.push_back(obj);
      const Hit single = Bvh(one).closest(ray, 0.0, 1e30, Facing::Both);
      if (single.found()) best = std::min(best, single.t);
    }
    if (best < 1e300) {
      ++hits;
      ASSERT_TRUE(h.found()) << "ray " << i;
      EXPECT_NEAR(h.t, best, 1e-9) << "ray " << i;
      EXPECT_TRUE(bvh.occluded(ray, 0.0, best + 1e-6));
      EXPECT_FALSE(bvh.occluded(ray, 0.0, best * 0.999));
    } else {
      EXPECT_FALSE(h.found()) << "ray " << i;
    }
  }
  EXPECT_GT(hits, 300);
}

TEST(Bvh, BackFacesAreSkippedWhenAsked) {
  // The default scene's front wall (z = 5) faces -z, into the room; the
  // camera (z = 6.5) sees its back. From behind, a front-only ray passes it
  // and meets the mirror (z = -2.98, facing +z) 8.98 on.
  const Scene scene = loadSceneText(defaultSceneText(), "<default scene>");
  const Bvh bvh(scene);
  const Ray behind{{0.0, 2.0, 6.0}, {0.0, 0.0, -1.0}};
  EXPECT_NEAR(bvh.closest(behind, 0.0, 1e30, Facing::Both).t, 1.0, 1e-6);
  const Hit h = bvh.closest(behind, 0.0, 1e30, Facing::FrontOnly);
  ASSERT_TRUE(h.found());
  EXPECT_NEAR(h.t, 8.98, 1e-6);
  EXPECT_EQ(scene.objects[bvh.triangles()[h.id].object].name, "mirror");
  const Ray inside{{0.0, 2.0, 4.0}, {0.0, 0.0, 1.0}};
  const Hit wall = bvh.closest(inside, 0.0, 1e30, Facing::FrontOnly);
  ASSERT_TRUE(wall.found());
  EXPECT_NEAR(wall.t, 1.0, 1e-6);
  EXPECT_EQ(scene.objects[bvh.triangles()[wall.id].object].name, "front wall");
}

}  // namespace
}  // namespace mpr
