#pragma once
// Draws a scene through the emulated pipeline, every step a GL call on the
// command stream. For now one ambient pass and one additive pass per light
// with a depth-equal test (1997 paper, section 7.2: lights are added in RGB
// space, the first pass ambient only); the multi-pass effects of the 1994
// paper plug in as further passes.
#include <functional>
#include <string>

#include "algorithms/gl_command_stream.hpp"
#include "scene/scene.hpp"

namespace mpr {

struct RenderProgress {
  int pass = 0, passes = 0;
  std::string label;
};

// Renders `scene` on `stream` (whose context has the scene's size and profile).
void renderScene(const Scene& scene, GLCommandStream& stream,
                 const std::function<void(const RenderProgress&)>& progress = {});

}  // namespace mpr
