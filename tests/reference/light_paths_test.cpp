// Light bent by a refracting face reaches the point below it: at the path
// length's attenuation in the pipeline model, and with the ray tube's
// spreading (the caustic factor) in the physical one.
#include "reference/light_paths.hpp"

#include <gtest/gtest.h>

#include "scene/scene_loader.hpp"

namespace mpr {
namespace {

// A light 1 above a glass plane (y = 0, facing up, ior 1.5, all
// transmitted), a floor 1 below it; attenuation 1 / d^2.
const char* kGlass = R"(
lights: [{position: [0, 1, 0], color: [1, 1, 1], attenuation: [0, 0, 1]}]
materials:
  white: {diffuse: [1, 1, 1]}
  glass: {kind: refractive, diffuse: [0, 0, 0], ior: 1.5, transmittance: 1}
objects:
  - {name: glass, primitive: quad, rotate: [-90, 1, 0, 0], scale: [10, 10, 1], material: glass}
  - {name: floor, primitive: plane, translate: [0, -1, 0], scale: [10, 1, 10], material: white}
)";

DVec3 lightBelow(ShadingModel model, std::uint64_t& rays) {
  const Scene scene = loadSceneText(kGlass, "<test scene>");
  const Bvh bvh(scene);
  const LightPaths paths = findLightPaths(scene, -1);
  const SceneMaterial& white = scene.materials[0].name == "white" ? scene.materials[0] : scene.materials[1];
  const ShadingPoint at{{0.0, -1.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 1.0, 0.0}, &white};
  return directLight(scene, bvh, paths, at, model, LightSampling{}, rays);
}

TEST(LightPaths, RefractedLightAtNormalIncidence) {
  std::uint64_t rays = 0;
  // Straight down: the crossing is (0, 0, 0), the path 1 + 1 = 2 long, N.L =
  // 1: 1 / 2^2 = 0.25. The straight ray is stopped by the glass (a
  // refracting face passes light only bent), so this is all the light.
  EXPECT_NEAR(lightBelow(ShadingModel::Pipeline, rays).x, 0.25, 1e-9);
  EXPECT_GT(rays, 0u);
  // Paraxially, rays leaving the light at angle t are at t / 1.5 in the
  // glass: at depth 1 below it they are 1 * t + 1 * t / 1.5 from the axis,
  // so dOmega / dA = 1 / (1 + 1 / 1.5)^2 = 0.36, against 1 / 2^2 for a
  // straight path: a factor of 1.44.
  EXPECT_NEAR(lightBelow(ShadingModel::Physical, rays).x, 0.36, 1e-5);
}

}  // namespace
}  // namespace mpr
