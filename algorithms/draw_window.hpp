#pragma once
// The drawwindow recursion of the 1994 paper's Figure 4, on the emulated GL:
// draw_window, draw_ref_objects, draw_normal_objects, draw_all_shadows,
// make_all_shadows and apply_stencil, each step a call on the command stream.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "algorithms/gl_command_stream.hpp"
#include "algorithms/image_samples.hpp"
#include "algorithms/render_plan.hpp"
#include "scene/scene.hpp"

namespace mpr {

// What the recursion did, for --stats and the pass-count tests.
struct DrawWindowCounts {
  std::uint64_t views = 0;          // draw_window calls (scene renderings)
  std::uint64_t lightPasses = 0;    // lit draw_normal_objects passes
  std::uint64_t shadowPasses = 0;   // make_all_shadows passes (one per light per shadowed view)
  std::uint64_t facesSkipped = 0;   // ref faces culled (seen from behind, or no pixel visible)
  std::uint64_t zfailVolumes = 0;   // volumes drawn by z-fail because the eye was inside
  std::vector<int> viewsAtLevel;    // views per recursion level
  std::vector<std::string> warnings;
};

struct DrawWindowProgress {
  std::uint64_t views = 0;
  std::uint64_t passes = 0;  // views, lit passes and shadow passes so far
  std::string label;
};

class ShadowPass;

// `sample`: the view of one image of an accumulation (image_samples.hpp).
// `pivotBase`: the pivot method's volumes, built once from the lights'
// centres (shadow_pass.hpp); this image's are pivoted from them.
DrawWindowCounts drawScene(const Scene& scene, const RenderPlan& plan, GLCommandStream& gl,
                           const std::function<void(const DrawWindowProgress&)>& progress = {},
                           const ViewSample& sample = {}, const ShadowPass* pivotBase = nullptr);

}  // namespace mpr
