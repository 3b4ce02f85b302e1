#include "reference/accuracy/rgb8_image.hpp"

#include "reference/reference_image.hpp"
#include "util/image_io.hpp"

namespace mpr {

Rgb8Image quantiseReference(const ReferenceImage& im) { return {im.width, im.height, quantiseToRgb8(im)}; }

// 8-bit files come back as v / 255 and quantise to v again (v / 255 * 255
// is within 1e-5 of v in float).
Rgb8Image readRgb8Image(const std::string& path) { return quantiseReference(readReferenceImage(path)); }

std::string encodePng(const Rgb8Image& image) {
  const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(image.width) * 3;
  const std::uint8_t* top = image.rgb.data() + static_cast<std::size_t>(image.height - 1) * image.width * 3;
  return encodePngBytes(image.width, image.height, 3, top, -row);
}

}  // namespace mpr
