#include "reference/reference_image.hpp"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "framebuffer/fragment_ops.hpp"

namespace mpr {
namespace {

std::string temporaryNameFor(const std::string& path) {
  const std::filesystem::path p(path);
  // The extension stays last so that OpenImageIO picks the format.
  // Appended piece by piece: "." + string trips GCC 12's -Wrestrict.
  std::string name = ".";
  name += p.stem().string();
  name += ".tmp" + std::to_string(::getpid());
  name += p.extension().string();
  return (p.parent_path() / name).string();
}

bool floatFormat(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext == ".exr";
}

}  // namespace

std::vector<std::uint8_t> quantiseToRgb8(const ReferenceImage& image) {
  std::vector<std::uint8_t> out(image.rgb.size());
  for (std::size_t i = 0; i < image.rgb.size(); ++i) out[i] = floatToUnorm8(image.rgb[i]);
  return out;
}

void writeReferenceImage(const ReferenceImage& image, const std::string& path) {
  const int w = image.width, h = image.height;
  const bool linear = floatFormat(path);
  const std::vector<std::uint8_t> bytes = linear ? std::vector<std::uint8_t>{} : quantiseToRgb8(image);
  // Flip to top row first.
  std::vector<float> floats;
  std::vector<std::uint8_t> rows;
  const std::size_t stride = static_cast<std::size_t>(w) * 3;
  for (int y = h - 1; y >= 0; --y) {
    const std::size_t at = static_cast<std::size_t>(y) * stride;
    if (linear) floats.insert(floats.end(), image.rgb.begin() + at, image.rgb.begin() + at + stride);
    else rows.insert(rows.end(), bytes.begin() + at, bytes.begin() + at + stride);
  }
  const OIIO::TypeDesc type = linear ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error("cannot write " + path + ": " + OIIO::geterror());
  const std::string tmp = temporaryNameFor(path);
  const OIIO::ImageSpec spec(w, h, 3, type);
  const void* data = linear ? static_cast<const void*>(floats.data()) : static_cast<const void*>(rows.data());
  if (!out->open(tmp, spec) || !out->write_image(type, data) || !out->close()) {
    const std::string why = out->geterror();
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write " + path + ": " + why);
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write " + path + ": " + ec.message());
  }
}

ReferenceImage readReferenceImage(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw std::runtime_error("cannot read " + path + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels < 3) throw std::runtime_error("cannot read " + path + ": it has fewer than three channels");
  const int w = spec.width, h = spec.height, channels = spec.nchannels;
  const bool eightBit = spec.format == OIIO::TypeDesc::UINT8;
  std::vector<float> floats(static_cast<std::size_t>(w) * h * channels);
  std::vector<std::uint8_t> bytes(eightBit ? floats.size() : 0);
  const bool ok = eightBit ? in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, bytes.data())
                           : in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, floats.data());
  if (!ok) throw std::runtime_error("cannot read " + path + ": " + in->geterror());
  ReferenceImage image;
  image.width = w, image.height = h;
  image.rgb.resize(static_cast<std::size_t>(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        // File row 0 is the top: window row h - 1.
        const std::size_t src = (static_cast<std::size_t>(y) * w + x) * channels + c;
        const float v = eightBit ? static_cast<float>(bytes[src]) / 255.0f : floats[src];
        image.rgb[(static_cast<std::size_t>(h - 1 - y) * w + x) * 3 + c] = v;
      }
  return image;
}

}  // namespace mpr
