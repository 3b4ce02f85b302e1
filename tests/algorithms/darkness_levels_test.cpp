// Soft shadows by darkness levels (1994, "Soft shadows and caustics", second
// method): every light sample's shadow volume counted in one stencil, the
// light added once per level with the stencil stepped down between levels,
// the levels accumulated. Stencil pictures derived by hand, the planner's
// prediction, and the method against images (the first).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "algorithms/image_samples.hpp"
#include "algorithms/scene_renderer.hpp"
#include "scene/scene_loader.hpp"

namespace mpr {
namespace {

// Straight down from (0, 10, 0) with tan(fov / 2) = 0.4 on a 12 x 8 window:
// the floor (y = 0) is 12 x 8 units, one unit a pixel; pixel (px, py) sees
// x = px - 5.5 and z = 3.5 - py (image right = +x, up = -z). A thin box,
// x, z in [-1, 1], y in [1.8, 2], under a light at (0, 4, 0) of radius 2.
// The light's disc faces the scene's middle (0, 1, 0), straight down:
// u = (0, 0, 1), v = (-1, 0, 0). The two table points (0.25, 0.25) and
// (0.75, 0.5833) map to the disc points (-0.3536, -0.3536) and
// (0.4830, 0.1294), so the samples lie at (0.707, 4, -0.707) and
// (-0.259, 4, 0.966). From either the light sees only the box's top, whose
// square projects from height 2 to the floor doubled about the light:
// x in [-2 - lx, 2 - lx], z in [-2 - lz, 2 - lz]:
//   sample 0: x in [-2.707, 1.293], z in [-1.293, 2.707]
//   sample 1: x in [-1.742, 2.258], z in [-2.966, 1.034]
// (every edge at least 0.2 pixel from a pixel centre). The box's own top
// covers the four pixels at x, z = +-0.5, lit from both samples.
const char* kDarknessScene = R"(
camera: {position: [0, 10, 0], look_at: [0, 0, 0], up: [0, 0, -1], fov: 43.60281897270362, near: 1, far: 30}
ambient: [0.1, 0.1, 0.1]
lights: [{position: [0, 4, 0], radius: 2, attenuation: [1, 0, 0]}]
materials: {grey: {diffuse: [0.8, 0.8, 0.8]}}
objects:
  - {name: floor, primitive: plane, subdivisions: 8, scale: [16, 1, 16], material: grey}
  - {name: box, primitive: box, translate: [0, 1.9, 0], scale: [2, 0.2, 2], material: grey}
render: {width: 12, height: 8, soft_shadow_samples: 2, soft_shadow_method: darkness_levels}
)";

// How many sample volumes enclose each pixel, rows top (py = 7) to bottom.
const std::vector<std::string> kCounts = {
    "000000000000",  // z = -3.5
    "000011110000",  // z = -2.5: sample 1 only
    "000011110000",  // z = -1.5
    "000120010000",  // z = -0.5: sample 0 alone at x = -2.5, both at -1.5,
    "000120010000",  // z = +0.5   the box's top at -0.5 and 0.5, sample 1 alone at 1.5
    "000111100000",  // z = +1.5: sample 0 only
    "000111100000",  // z = +2.5
    "000000000000",  // z = +3.5
};

// The picture stepped down once: values above SHAD_ZERO less one.
std::vector<std::string> steppedDown(std::vector<std::string> rows) {
  for (std::string& r : rows)
    for (char& c : r)
      if (c > '0') --c;
  return rows;
}

std::vector<std::string> stencilPicture(const GLContext& gl, std::uint32_t shadZero) {
  std::vector<std::string> rows;
  for (int y = 7; y >= 0; --y) {
    std::string r;
    for (int x = 0; x < 12; ++x) {
      const std::uint32_t s = gl.stencilAt(x, y);
      r += s >= shadZero && s < shadZero + 10 ? static_cast<char>('0' + (s - shadZero)) : '?';
    }
    rows.push_back(r);
  }
  return rows;
}

struct Captured {
  std::vector<std::string> counted;                // after make_all_shadows
  std::vector<std::vector<std::string>> stepped;   // after each step down
  RenderResult result;
};

Captured renderCapturing(const Scene& s, GLContext& gl) {
  Captured c;
  GLCommandStream stream(gl, false);
  const std::uint32_t shadZero = planRender(s).levels.shadZero;
  stream.onPassEnd([&](const std::string& label) {
    if (label.find("make_all_shadows(ALWAYS)") != std::string::npos) c.counted = stencilPicture(gl, shadZero);
    if (label.find("step the levels down") != std::string::npos) c.stepped.push_back(stencilPicture(gl, shadZero));
  });
  c.result = renderScene(s, stream);
  return c;
}

TEST(DarknessLevels, StencilPicturesOfTheLevelsSteppedDown) {
  const Scene s = loadSceneText(kDarknessScene, "s.yaml");
  EXPECT_NEAR(lightSamplePosition(s, s.lights[0], 0).x, 0.7071, 1e-4);
  EXPECT_NEAR(lightSamplePosition(s, s.lights[0], 0).z, -0.7071, 1e-4);
  EXPECT_NEAR(lightSamplePosition(s, s.lights[0], 1).x, -0.2588, 1e-4);
  EXPECT_NEAR(lightSamplePosition(s, s.lights[0], 1).z, 0.9659, 1e-4);
  GLContext gl(12, 8, indigoProfile());
  const Captured c = renderCapturing(s, gl);
  EXPECT_EQ(c.counted, kCounts);
  ASSERT_EQ(c.stepped.size(), 1u);  // two levels: one step between them
  EXPECT_EQ(c.stepped[0], steppedDown(kCounts));
  // One image, one view; S = 2 lit passes; one shadow-volume pass.
  EXPECT_EQ(c.result.plan.images, 1);
  EXPECT_EQ(c.result.counts.views, 1u);
  EXPECT_EQ(c.result.counts.lightPasses, 2u);
  EXPECT_EQ(c.result.counts.lightPasses, c.result.plan.predictedLightPasses());
  EXPECT_EQ(c.result.counts.shadowPasses, c.result.plan.predictedShadowPasses());
  EXPECT_EQ(c.result.counts.shadowPasses, 1u);
}

// What each method makes of a pixel inside k of the S sample volumes:
//   images: ambient + (1/S) sum over the samples i that see it of lit_i
//   levels: ambient + (S - k) / S lit_c   (lit from the light's centre)
// Equal in the umbra (k = S: ambient alone) and equal counts: the pixel's
// darkness level is the number of the images in which it is in shadow.
// Elsewhere the levels image is the centre-lit light scaled by (S - k) / S,
// within the return's rounding: the level images are the centre-lit pass
// q on black, exactly the hard image less the ambient, each added as a word
// truncated by less than 1/32767 (accumulation_effects_test.cpp): 0.5 + 0.02.
TEST(DarknessLevels, AgainstImages) {
  const Scene levels = loadSceneText(kDarknessScene, "s.yaml");
  const Scene images = loadSceneText(kDarknessScene, "s.yaml", {"render.soft_shadow_method=images"});
  GLContext gl(12, 8, indigoProfile()), gi(12, 8, indigoProfile());
  const Captured c = renderCapturing(levels, gl);
  // The images method: per image, where its make_all_shadows counted a volume.
  std::vector<std::vector<std::string>> perImage;
  {
    GLCommandStream stream(gi, false);
    const std::uint32_t shadZero = planRender(images).levels.shadZero;
    stream.onPassEnd([&](const std::string& label) {
      if (label.find("make_all_shadows(ALWAYS)") != std::string::npos) perImage.push_back(stencilPicture(gi, shadZero));
    });
    EXPECT_EQ(renderScene(images, stream).plan.images, 2);
  }
  ASSERT_EQ(perImage.size(), 2u);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 12; ++x) {
      const auto row = static_cast<std::size_t>(y), col = static_cast<std::size_t>(x);
      EXPECT_EQ(c.counted[row][col] - '0', (perImage[0][row][col] - '0') + (perImage[1][row][col] - '0'))
          << "pixel " << x << ", " << 7 - y;
    }
  // The light alone from its centre, no shadows: lit_c = that image less the ambient.
  // (By --set, as a comparison does: in the file the soft-shadow keys would
  // have no radius to act on.)
  const Scene centre = loadSceneText(kDarknessScene, "s.yaml", {"render.shadows=false", "lights.0.radius=0"});
  const Scene dark =
      loadSceneText(kDarknessScene, "s.yaml", {"render.shadows=false", "lights.0.radius=0", "lights.0.color=[0, 0, 0]"});
  GLContext gc(12, 8, indigoProfile()), gd(12, 8, indigoProfile());
  GLCommandStream sc(gc, false), sd(gd, false);
  renderScene(centre, sc);
  renderScene(dark, sd);
  int umbra = 0, penumbra = 0;
  for (int py = 0; py < 8; ++py)
    for (int x = 0; x < 12; ++x) {
      const int k = c.counted[static_cast<std::size_t>(7 - py)][static_cast<std::size_t>(x)] - '0';
      const int ambient = gd.colorAt(x, py)[0], lit = gc.colorAt(x, py)[0] - ambient;
      const double expected = ambient + (2 - k) / 2.0 * lit;
      EXPECT_LE(std::abs(gl.colorAt(x, py)[0] - expected), 0.52) << "pixel " << x << ", " << py << ", k " << k;
      if (k == 2) {
        EXPECT_EQ(gl.colorAt(x, py)[0], ambient);
        EXPECT_EQ(gl.colorAt(x, py)[0], gi.colorAt(x, py)[0]);
        ++umbra;
      }
      penumbra += k == 1;
    }
  EXPECT_EQ(umbra, 2);
  EXPECT_EQ(penumbra, 20);
}

// The method counts volumes, not samples: where two casters shadow a pixel
// for one sample, that sample counts twice ("intensities based on the
// number of enclosed shadow volumes"). A second box, y in [1.1, 1.3] under
// the first (hidden by it from the camera: its top spans x, z = +-1.149 on
// the floor's scale, the first's +-1.25), throws from the samples, doubling
// about the light by 4 / 2.7 = 1.4815:
//   sample 0: x in [-1.822, 1.141], z in [-1.141, 1.822]
//   sample 1: x in [-1.357, 1.606], z in [-1.947, 1.016]
// (each inside the first box's shadow from the same sample: images draws
// the same bytes as without it; every edge at least 0.1 pixel from a pixel
// centre). Its counts add to kCounts; the 8 pixels where they make one
// sample count twice are lit in S - 2 = 0 levels, ambient, where images
// still light them from the other sample. Measured on
// scenes/soft_shadows.yaml: the floor under the table, where its top's and
// legs' shadows overlap, comes out up to 65 of 255 darker than images.
TEST(DarknessLevels, OverlappingCastersCountTwice) {
  std::string twice = kDarknessScene;
  const std::string box = "  - {name: box, primitive: box, translate: [0, 1.9, 0], scale: [2, 0.2, 2], material: grey}\n";
  twice.insert(twice.find(box) + box.size(),
               "  - {name: lower box, primitive: box, translate: [0, 1.2, 0], scale: [2, 0.2, 2], material: grey}\n");
  const Scene levels = loadSceneText(twice, "s.yaml");
  const Scene images = loadSceneText(twice, "s.yaml", {"render.soft_shadow_method=images"});
  const Scene once = loadSceneText(kDarknessScene, "s.yaml", {"render.soft_shadow_method=images"});
  GLContext gl(12, 8, indigoProfile()), gi(12, 8, indigoProfile()), go(12, 8, indigoProfile());
  const Captured c = renderCapturing(levels, gl);
  const std::vector<std::string> counts = {
      "000000000000",  //
      "000011110000",  //
      "000012220000",  // z = -1.5: the lower box from sample 1 at x = -0.5 .. 1.5
      "000130020000",  // z = -0.5: from sample 0 at -1.5, from 1 at 1.5 (the first box's top between)
      "000130020000",  //
      "000122200000",  // z = +1.5: from sample 0 at x = -1.5 .. 0.5
      "000111100000",  //
      "000000000000",  //
  };
  EXPECT_EQ(c.counted, counts);
  GLCommandStream si(gi, false), so(go, false);
  renderScene(images, si);
  renderScene(once, so);
  const Rgba8 ambient = gl.colorAt(4, 4);  // the umbra: row z = -0.5, x = -1.5
  int twiceCounted = 0;
  for (int py = 0; py < 8; ++py)
    for (int x = 0; x < 12; ++x) {
      EXPECT_EQ(gi.colorAt(x, py), go.colorAt(x, py)) << "pixel " << x << ", " << py;
      const auto r = static_cast<std::size_t>(7 - py), col = static_cast<std::size_t>(x);
      if (!(kCounts[r][col] == '1' && counts[r][col] == '2')) continue;
      ++twiceCounted;
      EXPECT_EQ(gl.colorAt(x, py), ambient) << "pixel " << x << ", " << py;
      EXPECT_GT(gi.colorAt(x, py)[0], ambient[0]) << "pixel " << x << ", " << py;
    }
  EXPECT_EQ(twiceCounted, 8);
}

// The penumbra of a 16-sample light rises monotonically from the umbra
// outwards, as with images (accumulation_effects_test.cpp's scene).
TEST(DarknessLevels, ThePenumbraRisesMonotonically) {
  const std::string scene = R"(
camera: {position: [0, 8, 0], look_at: [0, 0, 0], up: [0, 0, -1], fov: 40, near: 0.1, far: 30}
ambient: [0.1, 0.1, 0.1]
lights: [{position: [3, 4, 0], radius: 0.6, attenuation: [1, 0, 0]}]
materials: {grey: {diffuse: [0.8, 0.8, 0.8]}}
objects:
  - {name: floor, primitive: plane, subdivisions: 8, scale: [8, 1, 8], material: grey}
  - {name: block, primitive: box, translate: [0, 1, 0], scale: [1, 0.2, 1], material: grey}
render: {width: 64, height: 48, soft_shadow_samples: 16, soft_shadow_method: darkness_levels}
)";
  const Scene s = loadSceneText(scene, "s.yaml");
  GLContext gl(64, 48, indigoProfile());
  GLCommandStream stream(gl, false);
  const RenderResult r = renderScene(s, stream);
  EXPECT_EQ(r.plan.images, 1);
  EXPECT_EQ(r.counts.lightPasses, 16u);
  EXPECT_EQ(r.counts.lightPasses, r.plan.predictedLightPasses());
  const int y = 23;
  EXPECT_EQ(gl.colorAt(23, y)[0], 20);  // the umbra: ambient alone
  int top = 23;
  for (int x = 23; x >= 10; --x)
    if (gl.colorAt(x, y)[0] > gl.colorAt(top, y)[0]) top = x;
  int rises = 0;
  for (int x = 22; x >= top; --x) {
    EXPECT_GE(gl.colorAt(x, y)[0], gl.colorAt(x + 1, y)[0]) << "pixel " << x;
    rises += gl.colorAt(x, y)[0] > gl.colorAt(x + 1, y)[0];
  }
  EXPECT_GE(rises, 3);
}

// The destination alpha under the levels is what it was before them (masked
// throughout), and the planner predicts the passes of a mirror scene's
// views: S lit passes for the soft light only where shadows are drawn.
TEST(DarknessLevels, PredictedWithMirrors) {
  std::string scene = kDarknessScene;
  const std::string materials = "materials: {grey: {diffuse: [0.8, 0.8, 0.8]}}", objects = "objects:\n";
  scene.replace(scene.find(materials), materials.size(),
                "materials: {grey: {diffuse: [0.8, 0.8, 0.8]}, m: {kind: mirror, reflectance: 0.8}}");
  scene.replace(scene.find(objects), objects.size(),
                "objects:\n  - {name: mirror, primitive: quad, translate: [0, 2, -4], scale: [8, 4, 1], material: m}\n");
  for (const char* depth : {"1", "0"}) {
    Scene s;
    try {
      s = loadSceneText(scene, "s.yaml", {std::string("render.shadow_recursion_depth=") + depth});
    } catch (const SceneError& e) {
      FAIL() << e.what();
    }
    GLContext gl(12, 8, indigoProfile());
    GLCommandStream stream(gl, false);
    const RenderResult r = renderScene(s, stream, {}, false);  // culling off: the counts predicted exactly
    EXPECT_EQ(r.plan.darknessLights, 1);
    EXPECT_EQ(r.counts.lightPasses, r.plan.predictedLightPasses()) << depth;
    EXPECT_EQ(r.counts.shadowPasses, r.plan.predictedShadowPasses()) << depth;
  }
}

}  // namespace
}  // namespace mpr
