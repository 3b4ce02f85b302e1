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
  bool any() const { return pixelOffset != DVec2(0.0) || lens != DVec2(0.0); }
};

// How many images a scene needs: one, unless it asks for antialiasing,
// depth of field or soft shadows. The antialias (and lens) samples and the
// light samples are paired image by image, each table cycled: N = max(A, S).
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
Scene lightSampleScene(const Scene& scene, int i, int n);

}  // namespace mpr
