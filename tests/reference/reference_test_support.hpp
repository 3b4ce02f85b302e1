#pragma once
// Shared by the reference tests: a scene from YAML text, traced, and its
// pixels as the 8-bit values an image file would hold.
#include <gtest/gtest.h>

#include <string>

#include "framebuffer/fragment_ops.hpp"
#include "reference/reference_image.hpp"
#include "reference/reference_renderer.hpp"
#include "scene/scene_loader.hpp"

namespace mpr::test {

inline ReferenceImage traceText(const std::string& yaml, int spp, int threads = 2) {
  const Scene scene = loadSceneText(yaml, "<test scene>");
  ReferenceOptions o;
  o.samplesPerPixel = spp;
  o.threads = threads;
  return renderReference(scene, o);
}

// Channel c of window pixel (x, y) quantised as the pipeline quantises.
inline int byteAt(const ReferenceImage& im, int x, int y, int c) {
  return floatToUnorm8(im.at(x, y)[c]);
}

inline int quantise(double v) { return floatToUnorm8(static_cast<float>(v)); }

}  // namespace mpr::test
