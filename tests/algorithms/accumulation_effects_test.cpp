// The accumulation effects: the indigo words' precision for N images, the
// sample tables, soft shadows by images (1994's first method), antialiasing
// by jittered projections (Haeberli and Akeley 1990).
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "algorithms/image_samples.hpp"
#include "algorithms/scene_renderer.hpp"
#include "scene/scene_loader.hpp"

namespace mpr {
namespace {

// N images of one 8-bit value v, each added with glAccum(GL_ACCUM, 1/N),
// then glAccum(GL_RETURN, 1), on the indigo words (16-bit, saturating).
int accumulateSame(int v, int n) {
  GLContext gl(1, 1, indigoProfile());
  gl.clearAccum(0, 0, 0, 0);
  gl.clear(GL_ACCUM_BUFFER_BIT);
  gl.clearColor(static_cast<float>(v) / 255.0f, 0, 0, 1);
  for (int i = 0; i < n; ++i) {
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.accum(GL_ACCUM, 1.0f / static_cast<float>(n));
  }
  gl.accum(GL_RETURN, 1.0f);
  return gl.colorAt(0, 0)[0];
}

// The bound. Each GL_ACCUM adds the word trunc(v/255 * 1/N * 32767): it
// loses less than one unit (plus float rounding, below 0.004 units at
// 32767). N images lose less than N (1 + 0.004) units, so the returned
// v' = round(S * 255 / 32767) has S * 255 / 32767 in (v - 255 N 1.004 / 32767, v].
// For N <= 64 that is (v - 0.4999, v]: it rounds to v, every v exactly. At
// N = 128 the loss reaches 0.996: v - 1 for some v.
TEST(AccumulationWords, SixtyFourImagesOfOneValueReturnIt) {
  for (int n = 1; n <= 64; ++n)
    for (int v = 0; v <= 255; ++v) ASSERT_EQ(accumulateSame(v, n), v) << "N " << n << ", v " << v;
  int lost = 0;
  for (int v = 0; v <= 255; ++v) {
    const int r = accumulateSame(v, 128);
    EXPECT_TRUE(r == v || r == v - 1) << v;
    lost += r != v;
  }
  EXPECT_GT(lost, 0);
}

// Different values (a penumbra: some images lit, some not) return their
// mean m within (m - 0.4999 - 0.5, m + 0.5]: |v' - m| < 1 for N <= 64.
TEST(AccumulationWords, MixedImagesReturnTheirMeanWithinOne) {
  for (int n : {2, 3, 16, 64}) {
    GLContext gl(1, 1, indigoProfile());
    gl.clearAccum(0, 0, 0, 0);
    gl.clear(GL_ACCUM_BUFFER_BIT);
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const int v = (i * 97 + 13) % 256;
      sum += v;
      gl.clearColor(static_cast<float>(v) / 255.0f, 0, 0, 1);
      gl.clear(GL_COLOR_BUFFER_BIT);
      gl.accum(GL_ACCUM, 1.0f / static_cast<float>(n));
    }
    gl.accum(GL_RETURN, 1.0f);
    EXPECT_LT(std::abs(gl.colorAt(0, 0)[0] - sum / n), 1.0) << "N " << n;
  }
}

// Looking straight down from 8 (fov 40, 64 x 48: a pixel is 0.1213 wide,
// image right = +x, window x = x / 0.1213 + 31.5 on the row through z = 0,
// window y 23.5) at a 1 x 1 block 1 above the floor, lit from (3, 4, 0).
const char* kAccumulationScene = R"(
camera: {position: [0, 8, 0], look_at: [0, 0, 0], up: [0, 0, -1], fov: 40, near: 0.1, far: 30}
ambient: [0.1, 0.1, 0.1]
lights: [{position: [3, 4, 0], radius: 0.6, attenuation: [1, 0, 0]}]
materials: {grey: {diffuse: [0.8, 0.8, 0.8]}}
objects:
  - {name: floor, primitive: plane, subdivisions: 8, scale: [8, 1, 8], material: grey}
  - {name: block, primitive: box, translate: [0, 1, 0], scale: [1, 0.2, 1], material: grey}
render: {width: 64, height: 48, soft_shadow_samples: 16}
)";

// Table points: stratified offsets within half a pixel, distinct; nothing
// moves with one image.
TEST(ImageSamples, TheTablesAreStratifiedAndFixed) {
  Scene s = loadSceneText(kAccumulationScene, "s.yaml", {"render.antialias_samples=4"});
  std::set<double> xs;
  for (int i = 0; i < 4; ++i) {
    const ViewSample v = viewSample(s, i, 4);
    EXPECT_GE(v.pixelOffset.x, -0.5);
    EXPECT_LT(v.pixelOffset.x, 0.5);
    EXPECT_GE(v.pixelOffset.y, -0.5);
    EXPECT_LT(v.pixelOffset.y, 0.5);
    xs.insert(v.pixelOffset.x);
  }
  // (i + 1/2) / 4 - 1/2 across: -0.375, -0.125, 0.125, 0.375.
  EXPECT_EQ(xs, (std::set<double>{-0.375, -0.125, 0.125, 0.375}));
  EXPECT_FALSE(viewSample(s, 0, 1).any());
  EXPECT_EQ(accumulatedImages(s), 16);
}

// Light samples lie on the disc of the light's radius facing the scene's
// middle (the bounding box's centre, (0, 0.55, 0)): within 0.6 of the light,
// at right angles to the direction from it to the middle.
TEST(ImageSamples, LightSamplesLieOnTheLightsDisc) {
  const Scene s = loadSceneText(kAccumulationScene, "s.yaml");
  const DVec3 light(3, 4, 0), axis = glm::normalize(DVec3(0, 0.55, 0) - light);
  std::set<std::pair<float, float>> seen;
  for (int i = 0; i < 16; ++i) {
    const DVec3 p(lightSampleScene(s, i, 16).lights[0].position);
    EXPECT_NEAR(glm::dot(p - light, axis), 0.0, 1e-6);
    EXPECT_LE(glm::length(p - light), 0.6 + 1e-6);
    seen.insert({static_cast<float>(p.x), static_cast<float>(p.z)});
  }
  EXPECT_EQ(seen.size(), 16u);
}

// The block's shadow: its left edge (x = -0.5, y = 1) seen from the
// light's centre (3, 4) lands at x = 3 - 3.5 * 4 / 3 = -1.667; from the
// disc's ends (about 0.6 to either side) the edge moves by about
// 0.6 * 1 / 3 = 0.2 either way (similar triangles: the block is 1 above the
// floor, the light 3 above the block): a penumbra about 0.4 wide or more
// (the disc faces the scene's middle, tilted to this edge), 3 to 5 pixels,
// around window x 17.8 (measured: 14 to 18); the umbra from x = -1.45 to the block (-0.5), window
// x 20 to 27. Walking from the umbra outwards (leftwards) along the row
// through z = 0, the red channel holds the ambient term (0.8 * 0.1 * 255 =
// 20.4: 20) in the umbra, then rises monotonically over several pixels to
// the lit floor. With one sample the same walk meets one hard step.
TEST(SoftShadows, ThePenumbraRisesMonotonically) {
  const Scene s = loadSceneText(kAccumulationScene, "s.yaml");
  GLContext gl(s.render.width, s.render.height, indigoProfile());
  GLCommandStream stream(gl, false);
  const RenderResult r = renderScene(s, stream);
  EXPECT_EQ(r.plan.images, 16);
  EXPECT_EQ(r.counts.views, 16u);
  const int y = 23;
  EXPECT_EQ(gl.colorAt(23, y)[0], 20);
  int top = 23;
  for (int x = 23; x >= 10; --x)
    if (gl.colorAt(x, y)[0] > gl.colorAt(top, y)[0]) top = x;
  int rises = 0;
  for (int x = 22; x >= top; --x) {
    EXPECT_GE(gl.colorAt(x, y)[0], gl.colorAt(x + 1, y)[0]) << "pixel " << x;
    rises += gl.colorAt(x, y)[0] > gl.colorAt(x + 1, y)[0];
  }
  EXPECT_GE(rises, 3);  // a ramp over several pixels, not one hard step
  const Scene hard = loadSceneText(kAccumulationScene, "s.yaml", {"render.soft_shadow_samples=1"});
  GLContext g1(64, 48, indigoProfile());
  GLCommandStream s1(g1, false);
  renderScene(hard, s1);
  int steps = 0;
  for (int x = 22; x >= 10; --x) steps += std::abs(g1.colorAt(x, y)[0] - g1.colorAt(x + 1, y)[0]) > 8;
  EXPECT_EQ(steps, 1);
}

// Antialiasing: pixels wholly inside a surface keep the one-sample value
// (the bound above: exact for N <= 64 when every image gives the same
// value, and the floor is lit per vertex, smoothly, so half a pixel moves it
// by less than the rounding), and somewhere along the block's silhouette
// against the floor a pixel takes a value strictly between the two.
TEST(Antialiasing, EdgesBlendInteriorsStay) {
  // A point light: its radius set to 0 (a --set, as a comparison does; in
  // the file soft_shadow_samples would have no light to sample).
  const Scene one = loadSceneText(kAccumulationScene, "s.yaml", {"lights.0.radius=0"});
  const Scene eight = loadSceneText(kAccumulationScene, "s.yaml", {"lights.0.radius=0", "render.antialias_samples=8"});
  EXPECT_EQ(accumulatedImages(eight), 8);
  GLContext g1(64, 48, indigoProfile()), g8(64, 48, indigoProfile());
  GLCommandStream s1(g1, false), s8(g8, false);
  renderScene(one, s1);
  renderScene(eight, s8);
  int between = 0, interiorDiffer = 0;
  for (int y = 1; y < 47; ++y)
    for (int x = 1; x < 63; ++x) {
      // A pixel whose 3x3 neighbourhood is uniform in the one-sample image
      // lies inside a surface; one where it is not, on an edge.
      bool uniform = true;
      int lo = 255, hi = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int v = g1.colorAt(x + dx, y + dy)[0];
          uniform = uniform && std::abs(v - g1.colorAt(x, y)[0]) <= 1;
          lo = std::min(lo, v), hi = std::max(hi, v);
        }
      const int v8 = g8.colorAt(x, y)[0];
      if (uniform) interiorDiffer += std::abs(v8 - g1.colorAt(x, y)[0]) > 1;
      else if (hi - lo > 40 && v8 > lo + 4 && v8 < hi - 4 && v8 != g1.colorAt(x, y)[0]) ++between;
    }
  EXPECT_EQ(interiorDiffer, 0);
  EXPECT_GT(between, 10);
}

// Depth of field: the lens shear keeps the focal plane where it was
// (x' = x - a - a z / f is x at z = -f), so an emitting square in that plane
// stays as sharp as through a pinhole, while a square far behind it blurs:
// its edge pixels take values between its colour and the black behind.
TEST(DepthOfField, TheFocalPlaneStaysSharp) {
  const std::string scene = R"(
camera: {position: [0, 0, 5], look_at: [0, 0, 0], fov: 40, near: 0.1, far: 100, aperture: 0.3}
ambient: [0, 0, 0]
materials: {lamp: {diffuse: [0, 0, 0], emission: [1, 1, 1]}}
objects:
  - {name: near square, primitive: quad, translate: [-0.6, 0, 0], scale: 0.8, material: lamp}
  - {name: far square, primitive: quad, translate: [4, 0, -15], scale: 4, material: lamp}
render: {width: 64, height: 48, antialias_samples: 16}
)";
  const Scene lens = loadSceneText(scene, "s.yaml");
  const Scene pinhole = loadSceneText(scene, "s.yaml", {"camera.aperture=0"});
  EXPECT_EQ(viewSample(lens, 3, 16).focalDistance, 5.0);
  GLContext gl(64, 48, indigoProfile()), gp(64, 48, indigoProfile());
  GLCommandStream sl(gl, false), sp(gp, false);
  renderScene(lens, sl);
  renderScene(pinhole, sp);
  // The near square's pixels: the same coverage through every lens point,
  // so the same bytes as the pinhole (antialiased alike).
  int nearDiffer = 0, farBlurred = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 32; ++x) nearDiffer += gl.colorAt(x, y)[0] != gp.colorAt(x, y)[0];
  for (int y = 0; y < 48; ++y)
    for (int x = 32; x < 64; ++x) {
      const int a = gl.colorAt(x, y)[0], p = gp.colorAt(x, y)[0];
      farBlurred += a != p && a > 0 && a < 255;
    }
  EXPECT_EQ(nearDiffer, 0);
  EXPECT_GT(farBlurred, 20);
}

}  // namespace
}  // namespace mpr
