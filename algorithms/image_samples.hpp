#pragma once
// The images the accumulation buffer sums (Haeberli and Akeley 1990; the
// 1994 paper's first soft-shadow method; 1997 §4.4): each image is a whole
// drawwindow render with its own sub-pixel offset, lens point and sample of
// every area light, added with weight 1/N (glAccum(GL_ACCUM, 1/N)), the
// sum returned at the end (glAccum(GL_RETURN, 1)).
#include <vector>

#include "scene/scene.hpp"
#include "util/vecmath.hpp"

namespace mpr {

// What one image changes in the view: the projection moved by `pixelOffset`
// (pixels, within [-0.5, 0.5)) and the eye moved by `lens` (eye-space x and
// y, world units) with the frustum sheared so the focal plane stays put.
struct ViewSample {
  DVec2 pixelOffset{0.0};
  DVec2 lens{0.0};
  double focalDistance = 1.0;
  int image = 0, images = 1;  // which image of the accumulation this is
  bool any() const { return pixelOffset != DVec2(0.0) || lens != DVec2(0.0); }
};

// How many images a scene needs: one, unless it asks for antialiasing,
// depth of field, soft shadows, frosted glass or glossy mirrors (a mirror
// with a roughness). The antialias (and lens) samples, the light samples
// and the frosted and glossy faces' shear samples are
// paired image by image, each table cycled: N = max(A, S, F) (S = 1 under
// darkness_levels, which sums its samples within an image).
int accumulatedImages(const Scene& scene);

// The view of image i of n: the i-th point of a fixed table (a Hammersley
// set: stratified in x, base-2 radical inverse in y), as a sub-pixel offset
// and, mapped onto the disc of camera.aperture (Shirley's concentric map),
// a lens point. Nothing moves for n = 1.
ViewSample viewSample(const Scene& scene, int i, int n);

// The scene of image i of n: every light with a radius moved to the i-th
// point of a second table (base-3 radical inverse, so that the pixel and
// light samples of one image are not correlated) on the disc of that radius
// facing the middle of the scene's objects (its bounding box). Lights
// without a radius stay.
// (Images and pivot: with darkness_levels every image keeps the lights' centres.)
Scene lightSampleScene(const Scene& scene, int i, int n);

// Sample i of light `light` (one of scene.lights) on that disc: the
// position lightSampleScene gives it in image i; its own position without a
// radius or with one sample.
Vec3 lightSamplePosition(const Scene& scene, const PointLight& light, int i);

// How many darkness levels light `light` is drawn with (1994's second
// method): soft_shadow_samples for a light with a radius under
// darkness_levels, else 1 (one lit pass, or the images method).
int darknessLevelSamples(const Scene& scene, const PointLight& light);

// The stochastic (X, Y) shear of a frosted face in image i of n (1997 §3):
// m times a pair of normal deviates, from the i mod `samples`-th point of a
// third table (base-5 radical inverse) through Box and Muller's map. The
// face's view is sheared by x' = x + X z, y' = y + Y z in the face's frame
// (z along its normal), so what lies farther behind the face blurs more.
// The light a frosted face passes on is sheared alike from a table of its own
// (base 7: the view's and the light's scattering are independent events).
DVec2 frostedShear(double m, int samples, int i, int base = 5);
inline constexpr int kFrostedLightTable = 7;

// The shear as a world-space matrix: the face's frame F (origin `centre`,
// z along `normal`) times the shear times F's inverse ("premultiplied by
// the global inverse transform of the specular face normal and
// postmultiplied by the global transform of the normal").
DMat4 shearAboutFace(DVec3 centre, DVec3 normal, DVec2 shear);

}  // namespace mpr
