// renderReference: camera rays through stratified sub-pixel positions, rows
// handed to worker threads. Each pixel's value depends only on its own
// samples (sampler.hpp), summed in sample order, so the bytes are the same
// at any thread count.
#include "reference/reference_renderer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "reference/camera_rays.hpp"
#include "reference/ray_tracer.hpp"

namespace mpr {
namespace {

// The area-light points one camera sample takes: the pixel as a whole takes
// max(16, samples) (light_paths.hpp), spread evenly over its samples.
std::uint32_t lightPointsPerSample(int spp) { return static_cast<std::uint32_t>(std::max(1, (16 + spp - 1) / spp)); }

void renderRow(const TraceContext& c, const CameraRays& camera, int spp, int y, float* row, RayCounts& counts) {
  for (int x = 0; x < camera.width; ++x) {
    const PixelSampler sampler{static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y),
                               static_cast<std::uint32_t>(spp)};
    DVec3 sum(0.0);
    for (int i = 0; i < spp; ++i) {
      const DVec2 o = sampler.pixelOffset(static_cast<std::uint32_t>(i));
      const Ray ray = camera.through(x + o.x, y + o.y, sampler.lensPoint(static_cast<std::uint32_t>(i)));
      ++counts.camera;
      // The near and far planes clip camera rays only (the virtual views'
      // own clipping is part of what the pipeline approximates).
      sum += trace(c, ray, camera.nearAlong(ray), camera.farAlong(ray), 0, 1.0, sampler, static_cast<std::uint32_t>(i),
                   counts).colour;
    }
    const DVec3 mean = sum / static_cast<double>(spp);
    for (int k = 0; k < 3; ++k) row[3 * x + k] = static_cast<float>(mean[k]);
  }
}

}  // namespace

ReferenceImage renderReference(const Scene& scene, const ReferenceOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const int spp = std::max(1, options.samplesPerPixel);
  const Bvh bvh(scene);
  const LightPaths lights = findLightPaths(scene, options.bounces);
  const TraceContext context{scene, bvh, lights, options.model, options.bounces, lightPointsPerSample(spp)};
  const CameraRays camera(scene.camera, scene.render.width, scene.render.height);

  ReferenceImage image;
  image.width = scene.render.width, image.height = scene.render.height;
  image.rgb.assign(static_cast<std::size_t>(image.width) * image.height * 3, 0.0f);
  int threads = options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::clamp(threads, 1, std::max(1, image.height));

  std::atomic<int> nextRow{0};
  std::mutex progressMutex;
  int rowsDone = 0;
  std::vector<RayCounts> counts(static_cast<std::size_t>(threads));
  const auto work = [&](int t) {
    for (int y; (y = nextRow.fetch_add(1)) < image.height;) {
      renderRow(context, camera, spp, y, &image.rgb[static_cast<std::size_t>(y) * image.width * 3],
                counts[static_cast<std::size_t>(t)]);
      std::lock_guard lock(progressMutex);
      ++rowsDone;
      if (options.progress) options.progress(rowsDone, image.height);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (std::thread& th : pool) th.join();

  for (const RayCounts& c : counts) {
    image.stats.cameraRays += c.camera;
    image.stats.specularRays += c.specular;
    image.stats.shadowRays += c.shadow;
  }
  image.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return image;
}

}  // namespace mpr
