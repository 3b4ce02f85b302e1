#pragma once
// One Whitted path: a ray, its hit, the local model there and the specular
// rays the material sends on (1994 paper's materials, physically: the
// scene's render switches are pipeline settings, not physics, and are
// ignored here; `bounces` replaces recursion_depth).
#include <cstdint>

#include "reference/bvh.hpp"
#include "reference/light_paths.hpp"
#include "reference/reference_renderer.hpp"
#include "reference/sampler.hpp"

namespace mpr {

struct TraceContext {
  const Scene& scene;
  const Bvh& bvh;
  const LightPaths& lights;
  ShadingModel model = ShadingModel::Pipeline;
  int bounces = -1;
  std::uint32_t lightPointsPerSample = 1;
};

struct RayCounts {
  std::uint64_t camera = 0, specular = 0, shadow = 0;
};

struct Traced {
  DVec3 colour{0.0};
  double distance = 0.0;  // to the hit; infinity where the ray hit nothing
};

// The colour arriving along `ray` (unit direction), hits with t in (tMin,
// tMax) only. `weight` is the product of the specular weights so far; `depth`
// the number of specular faces passed.
Traced trace(const TraceContext& c, const Ray& ray, double tMin, double tMax, int depth, double weight,
             const PixelSampler& sampler, std::uint32_t sample, RayCounts& counts);

}  // namespace mpr
