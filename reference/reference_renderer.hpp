#pragma once
// The reference: a Whitted-style ray tracer over the scene model (scene/),
// never over GL calls, so the pipeline learns nothing from it. It is the
// yardstick `mpr accuracy` measures the multi-pass approximations against
// (1997 paper §7.4, Fig. 15: the pipeline against a Radiance image).
#include <cstdint>
#include <functional>
#include <vector>

#include "scene/scene.hpp"

namespace mpr {

// `Pipeline`: the local model the emulated GL evaluates (GL 1.x lighting with
// the scene's materials, Ward materials through the eq. (6) Phong fit), per
// pixel in floating point. `Physical`: Ward's isotropic Gaussian (1997 eqs.
// 3/5) where a material gives `roughness`.
enum class ShadingModel { Pipeline, Physical };

struct ReferenceOptions {
  int samplesPerPixel = 16;  // stratified, fixed seed per pixel
  ShadingModel model = ShadingModel::Pipeline;
  int bounces = -1;          // specular bounces; -1: until the contribution falls below 1/512
  int threads = 0;           // 0: every hardware thread; the bytes do not depend on it
  // Called now and then with the rows finished so far (from any thread, serialised).
  std::function<void(int rowsDone, int rows)> progress;
};

struct ReferenceStats {
  std::uint64_t cameraRays = 0, specularRays = 0, shadowRays = 0;
  double seconds = 0.0;
};

// Linear RGB, three floats a pixel, rows from window y = 0 (bottom) upwards,
// as the framebuffer stores them.
struct ReferenceImage {
  int width = 0, height = 0;
  std::vector<float> rgb;
  ReferenceStats stats;
  const float* at(int x, int y) const { return &rgb[3 * (static_cast<std::size_t>(y) * width + x)]; }
};

// Renders `scene` at scene.render.width x height.
ReferenceImage renderReference(const Scene& scene, const ReferenceOptions& options);

}  // namespace mpr
