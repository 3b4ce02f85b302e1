#include "reference/accuracy/rgb8_image.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <stdexcept>

#include "framebuffer/fragment_ops.hpp"

namespace mpr {

Rgb8Image quantiseReference(const ReferenceImage& im) {
  Rgb8Image q{im.width, im.height, std::vector<std::uint8_t>(im.rgb.size())};
  for (std::size_t i = 0; i < im.rgb.size(); ++i) q.rgb[i] = floatToUnorm8(im.rgb[i]);
  return q;
}

Rgb8Image readRgb8Image(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw std::runtime_error("cannot read " + path + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  const int w = spec.width, h = spec.height;
  if (w <= 0 || h <= 0 || spec.nchannels < 3) throw std::runtime_error(path + " is not an RGB image");
  const bool floats = spec.format.basetype == OIIO::TypeDesc::FLOAT || spec.format.basetype == OIIO::TypeDesc::HALF;
  const std::size_t n = static_cast<std::size_t>(w) * h * 3;
  Rgb8Image out{w, h, std::vector<std::uint8_t>(n)};
  // Files are top row first; the measure's rows start at window y = 0.
  const auto flip = [&](std::size_t i) {
    const std::size_t px = i / 3, c = i % 3, x = px % w, y = px / w;
    return ((h - 1 - y) * w + x) * 3 + c;
  };
  if (floats) {
    std::vector<float> f(n);
    if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, f.data())) throw std::runtime_error(in->geterror());
    for (std::size_t i = 0; i < n; ++i) out.rgb[flip(i)] = floatToUnorm8(f[i]);
  } else {
    std::vector<std::uint8_t> b(n);
    if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, b.data())) throw std::runtime_error(in->geterror());
    for (std::size_t i = 0; i < n; ++i) out.rgb[flip(i)] = b[i];
  }
  return out;
}

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
