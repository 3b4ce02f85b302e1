#include "reference/accuracy/rgb8_image.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <stdexcept>

#include "reference/reference_image.hpp"

namespace mpr {

Rgb8Image quantiseReference(const ReferenceImage& im) { return {im.width, im.height, quantiseToRgb8(im)}; }

// 8-bit files come back as v / 255 and quantise to v again (v / 255 * 255
// is within 1e-5 of v in float).
Rgb8Image readRgb8Image(const std::string& path) { return quantiseReference(readReferenceImage(path)); }

std::string encodePng(const Rgb8Image& image) {
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput proxy(bytes);
  auto out = OIIO::ImageOutput::create("image.png");
  if (!out || !out->set_ioproxy(&proxy)) throw std::runtime_error("cannot encode PNG: " + OIIO::geterror());
  const OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(image.width) * 3;
  const std::uint8_t* top = image.rgb.data() + static_cast<std::size_t>(image.height - 1) * image.width * 3;
  if (!out->open("image.png", spec) || !out->write_image(OIIO::TypeDesc::UINT8, top, OIIO::AutoStride, -row) ||
      !out->close())
    throw std::runtime_error("cannot encode PNG: " + out->geterror());
  return std::string(bytes.begin(), bytes.end());
}

}  // namespace mpr
