#pragma once
// Draws a scene through the emulated pipeline: the planner decides which
// passes of the 1994 paper's Figure 4 the scene needs, and draw_window runs
// them, every step a GL call on the command stream.
#include <functional>
#include <string>

#include "algorithms/draw_window.hpp"
#include "algorithms/gl_command_stream.hpp"
#include "algorithms/render_plan.hpp"
#include "scene/scene.hpp"

namespace mpr {

struct RenderProgress {
  std::uint64_t views = 0, predictedViews = 0;
  std::uint64_t passes = 0;  // views, lit and shadow passes so far (what --max-passes bounds)
  std::string label;
};

struct RenderResult {
  RenderPlan plan;
  DrawWindowCounts counts;
};

// Renders `scene` on `stream` (whose context has the scene's size and profile).
RenderResult renderScene(const Scene& scene, GLCommandStream& stream,
                         const std::function<void(const RenderProgress&)>& progress = {}, bool cull = true);

}  // namespace mpr
