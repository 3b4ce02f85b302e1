#pragma once
// A scene file's text rendered by the pipeline, its colour buffer returned
// (rows bottom up, as GL stores them): what the whole-render tests compare.
#include <string>
#include <vector>

#include "algorithms/scene_renderer.hpp"
#include "scene/scene_loader.hpp"

namespace mpr::test {

inline std::vector<Rgba8> renderedColours(const std::string& yaml, const std::string& file,
                                          const std::vector<std::string>& overrides = {}) {
  const Scene scene = loadSceneText(yaml, file, overrides);
  GLContext gl(scene.render.width, scene.render.height, *findProfile(scene.render.profile));
  GLCommandStream stream(gl, false);
  renderScene(scene, stream);
  return gl.framebuffer().colorData();
}

}  // namespace mpr::test
