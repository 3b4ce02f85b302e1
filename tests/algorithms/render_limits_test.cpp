// Issue 15, "numerically hard cases, end to end": whole renders at the
// limits of the Iris words. Shadow counts up to the last the stencil holds
// (SHAD_ZERO + 62 = 254 in 8 bits; 63 and more are warned of in
// hard_cases_test), and 64 jittered images summed in the 48-bit
// accumulation buffer (1994 paper's antialiasing by accumulation).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "algorithms/scene_renderer.hpp"
#include "scene/scene_loader.hpp"

namespace mpr {
namespace {

// `boxes` thin boxes stacked along the light's axis, between it and a wall:
// their shadows nest, the nearest box's the largest (hard_cases_test's stack).
std::string stackedBoxes(int boxes) {
  std::string text = R"(
camera: {position: [0.9, 0, -1], look_at: [0.3, 0, -4], fov: 20, near: 0.05, far: 20}
lights: [{position: [0, 0, -1]}]
objects:
  - {primitive: quad, translate: [0, 0, -4], scale: [8, 8, 1]}
)";
  for (int i = 0; i < boxes; ++i)
    text += "  - {primitive: box, translate: [0, 0, " + std::to_string(-1.5 - 0.0004 * i) + "], scale: [0.2, 0.2, 0.0002]}\n";
  return text + "render: {width: 8, height: 8}\n";
}

struct ShadowRun {
  std::vector<Rgba8> color;
  std::vector<std::uint8_t> counted;  // the stencil after make_all_shadows
  std::vector<std::string> warnings;
};

ShadowRun renderShadows(const Scene& scene) {
  GLContext gl(8, 8, indigoProfile());
  GLCommandStream stream(gl, false);
  ShadowRun run;
  stream.onPassEnd([&](const std::string& label) {
    if (label.find("make_all_shadows") != std::string::npos) run.counted = gl.framebuffer().stencilData();
  });
  run.warnings = renderScene(scene, stream).counts.warnings;
  run.color = gl.framebuffer().colorData();
  return run;
}

// 62 nested volumes: the stencil counts them exactly, up to 254, no warning;
// a pixel in all 62 shadows is as dark as in the nearest box's shadow alone.
TEST(RenderLimits, SixtyTwoNestedShadowsAreCountedExactly) {
  const ShadowRun many = renderShadows(loadSceneText(stackedBoxes(62), "stack62.yaml"));
  const ShadowRun one = renderShadows(loadSceneText(stackedBoxes(1), "stack1.yaml"));
  EXPECT_TRUE(many.warnings.empty()) << many.warnings.front();
  ASSERT_EQ(many.counted.size(), 64u);
  ASSERT_EQ(one.counted.size(), 64u);
  int deepest = 0;
  for (std::size_t i = 0; i < 64; ++i) {
    // Below SHAD_ZERO (192) never: the counts stay out of the recursion levels.
    EXPECT_GE(many.counted[i], 192) << "pixel " << i;
    if (many.counted[i] != 192 + 62) continue;
    ++deepest;
    EXPECT_EQ(one.counted[i], 193) << "pixel " << i;
    EXPECT_EQ(many.color[i], one.color[i]) << "pixel " << i;
  }
  EXPECT_GT(deepest, 0);
}

// No light: every face is one colour (emission + ambient), so a pixel whose
// 3x3 neighbourhood is one colour in the single image is covered by that face
// in all 64 jittered images (the jitter stays within half a pixel), and the
// 48-bit sum of 64 equal values, times 1/64, returns the value exactly. An
// edge pixel is a mean of its neighbours' colours: within their range.
TEST(RenderLimits, SixtyFourAccumulatedImagesKeepFlatColoursExactly) {
  const char* yaml = R"(
camera: {position: [0, 1.5, 4], look_at: [0, 0.5, 0], fov: 50, near: 0.1, far: 20}
ambient: [0.6, 0.6, 0.6]
materials: {red: {diffuse: [0.9, 0.3, 0.1]}, blue: {diffuse: [0.1, 0.3, 0.9]}}
objects:
  - {primitive: plane, scale: [6, 1, 6], material: blue}
  - {primitive: box, translate: [0.2, 0.5, 0], rotate: [30, 0, 1, 0], scale: 0.9, material: red}
render: {width: 32, height: 24}
)";
  Scene single = loadSceneText(yaml, "flat.yaml");
  Scene accumulated = single;
  accumulated.render.antialiasSamples = 64;
  const auto colours = [](const Scene& s) {
    GLContext gl(s.render.width, s.render.height, indigoProfile());
    GLCommandStream stream(gl, false);
    renderScene(s, stream);
    return gl.framebuffer().colorData();
  };
  const std::vector<Rgba8> a = colours(single), b = colours(accumulated);
  const int w = 32, h = 24;
  int interior = 0, edges = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Rgba8& c = a[static_cast<std::size_t>(y * w + x)];
      Rgba8 lo = c, hi = c;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const Rgba8& n = a[static_cast<std::size_t>(std::clamp(y + dy, 0, h - 1) * w + std::clamp(x + dx, 0, w - 1))];
          for (int k = 0; k < 4; ++k) lo[k] = std::min(lo[k], n[k]), hi[k] = std::max(hi[k], n[k]);
        }
      const Rgba8& got = b[static_cast<std::size_t>(y * w + x)];
      if (lo == hi) {
        ++interior;
        EXPECT_EQ(got, c) << "interior pixel " << x << "," << y;
      } else {
        ++edges;
        // One step of rounding either side: each image is rounded to 8 bits
        // before it is accumulated, and the return rounds again.
        for (int k = 0; k < 4; ++k) {
          EXPECT_GE(int{got[k]}, int{lo[k]} - 1) << "edge pixel " << x << "," << y << " channel " << k;
          EXPECT_LE(int{got[k]}, int{hi[k]} + 1) << "edge pixel " << x << "," << y << " channel " << k;
        }
      }
    }
  EXPECT_GT(interior, w * h / 2);
  EXPECT_GT(edges, 0);
}

}  // namespace
}  // namespace mpr
