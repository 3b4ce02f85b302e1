#pragma once
// Images in the units the accuracy measure compares: 8-bit RGB as the
// pipeline's colour buffer holds it, rows from window y = 0 upwards.
#include <cstdint>
#include <string>
#include <vector>

#include "reference/reference_renderer.hpp"

namespace mpr {

struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

// The reference quantised exactly as the pipeline quantises a colour
// (reference_image.hpp quantiseToRgb8, floatToUnorm8: clamp, v * 255 in float,
// rounded to nearest with ties to even).
Rgb8Image quantiseReference(const ReferenceImage& image);

// Reads PNG, TIFF or EXR through OpenImageIO: 8-bit files as they are, float
// files (EXR, as `mpr reference` writes them) quantised as above. Throws
// std::runtime_error with OpenImageIO's message.
Rgb8Image readRgb8Image(const std::string& path);

// The image as the bytes of a PNG file (top row first), for files that are
// written as part of a folder (mpr accuracy --report).
std::string encodePng(const Rgb8Image& image);

}  // namespace mpr
