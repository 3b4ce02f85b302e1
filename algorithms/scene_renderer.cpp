#include "algorithms/scene_renderer.hpp"

#include <optional>

#include "algorithms/image_samples.hpp"
#include "algorithms/shadow_pass.hpp"
#include "scene/camera_origin.hpp"
#include "scene/tessellation.hpp"

namespace mpr {
namespace {

void addCounts(DrawWindowCounts& total, const DrawWindowCounts& c) {
  total.views += c.views;
  total.lightPasses += c.lightPasses;
  total.shadowPasses += c.shadowPasses;
  total.facesSkipped += c.facesSkipped;
  total.zfailVolumes += c.zfailVolumes;
  if (total.viewsAtLevel.size() < c.viewsAtLevel.size()) total.viewsAtLevel.resize(c.viewsAtLevel.size(), 0);
  for (std::size_t l = 0; l < c.viewsAtLevel.size(); ++l) total.viewsAtLevel[l] += c.viewsAtLevel[l];
  for (const std::string& w : c.warnings) total.warnings.push_back(w);
}

}  // namespace

RenderResult renderScene(const Scene& modelled, GLCommandStream& gl,
                         const std::function<void(const RenderProgress&)>& progress, bool cull) {
  // On a copy (the scene as modelled is what the reference traces): the
  // scene relative to its camera (camera-relative rendering, issue 43: the
  // float pipeline sees small numbers wherever the scene lies), then its
  // lit faces split for per-vertex lighting (render.tessellation).
  Scene drawn;
  const bool tessellate = modelled.render.tessellation != 0.0f;
  const bool moved = modelled.camera.position != Vec3(0.0f);
  if (tessellate || moved) {
    drawn = modelled;
    moveOriginToCamera(drawn);
    if (tessellate) tessellateLitObjects(drawn, modelled.render.tessellation);
  }
  const Scene& scene = tessellate || moved ? drawn : modelled;
  RenderResult r;
  r.plan = planRender(scene, cull);
  const std::uint64_t predicted = r.plan.predictedViews() * static_cast<std::uint64_t>(r.plan.images);
  std::uint64_t viewsBefore = 0, passesBefore = 0;
  const auto report = [&](const DrawWindowProgress& p) {
    if (progress) progress({viewsBefore + p.views, predicted, passesBefore + p.passes, p.label});
  };
  const int n = r.plan.images;
  if (n <= 1) {
    r.counts = drawScene(scene, r.plan, gl, report);
    return r;
  }
  // The accumulation effects (image_samples.hpp): n whole renders, each with
  // its view and light sample, summed with weight 1/n in the accumulation
  // buffer and returned to the colour buffer (Haeberli and Akeley 1990; the
  // 1994 paper's first soft-shadow method).
  // The pivot method (1997 §4.4): the shadow volumes built once, from the
  // lights' centres; each image pivots their far ends to its light sample.
  std::optional<ShadowPass> pivotBase;
  if (scene.render.softShadowMethod == SoftShadowMethod::Pivot) pivotBase.emplace(scene, r.plan, true);
  gl.pass("accumulate", "accumulate | clear the accumulation buffer");
  gl.clearAccum(0.0f, 0.0f, 0.0f, 0.0f);
  gl.clear(GL_ACCUM_BUFFER_BIT);
  for (int i = 0; i < n; ++i) {
    const Scene sampled = lightSampleScene(scene, i, n);
    addCounts(r.counts, drawScene(sampled, r.plan, gl, report, viewSample(scene, i, n), pivotBase ? &*pivotBase : nullptr));
    viewsBefore = r.counts.views;
    passesBefore = r.counts.views + r.counts.lightPasses + r.counts.shadowPasses;
    gl.pass("accumulate", "accumulate | image " + std::to_string(i + 1) + " of " + std::to_string(n) +
                              ": glAccum(GL_ACCUM, 1/" + std::to_string(n) + ")");
    gl.accum(GL_ACCUM, 1.0f / static_cast<float>(n));
  }
  gl.pass("accumulate", "accumulate | glAccum(GL_RETURN, 1)");
  gl.accum(GL_RETURN, 1.0f);
  gl.finish();
  return r;
}

}  // namespace mpr
