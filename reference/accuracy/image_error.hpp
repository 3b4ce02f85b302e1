#pragma once
// The error of an image against the reference, as the 1997 paper measures it
// (§7.4, Fig. 15): the RMS of the luminance difference "over the range of
// luminance values" of the reference, in percent.
//
// Units: both images are compared as 8-bit colour, the reference quantised
// exactly as the pipeline quantises its colour buffer (clamp to [0, 1],
// v * 255 rounded to nearest, ties to even), and each 8-bit value read as
// the linear v / 255 (the emulated pipeline has no gamma: its colour buffer
// holds the lighting equation's values). Luminance is Rec. 709's
// Y = 0.2126 R + 0.7152 G + 0.0722 B on those linear values.
#include <cstdint>
#include <vector>

#include "reference/accuracy/rgb8_image.hpp"

namespace mpr {

double luminance(std::uint8_t r, std::uint8_t g, std::uint8_t b);

struct ImageError {
  double rmsPercent = 0.0;          // 100 * sqrt(mean((Y - Yref)^2)) / (max Yref - min Yref)
  double maxErrorPercent = 0.0;     // 100 * max |Y - Yref| / range
  double shareOver5Percent = 0.0;   // percent of pixels with |Y - Yref| > 5 % of the range
  double referenceMin = 0.0, referenceMax = 0.0;  // the reference's luminance range
};

// Throws std::invalid_argument when the sizes differ or the images are empty.
// A reference of a single luminance has no range: its range is taken as 1
// (the whole 8-bit scale) so that the measure stays finite.
ImageError compareLuminance(const Rgb8Image& image, const Rgb8Image& reference);

// A difference image for the eye: grey where the luminances agree, red where
// `image` is brighter than the reference, blue where darker, saturated at
// `fullScalePercent` of the reference's range.
Rgb8Image luminanceDifferenceImage(const Rgb8Image& image, const Rgb8Image& reference, double fullScalePercent = 10.0);

}  // namespace mpr
