#include "reference/reference_image.hpp"

#include <cctype>
#include <filesystem>
#include <stdexcept>

#include "framebuffer/fragment_ops.hpp"
#include "framebuffer/image_writer.hpp"
#include "util/image_io.hpp"

namespace mpr {
namespace {

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

void writeReferenceImage(const ReferenceImage& image, AtomicFile& file) {
  if (floatFormat(file.target())) writeRgbImage(file, image.width, image.height, image.rgb.data());
  else writeRgbImage(file, image.width, image.height, quantiseToRgb8(image).data());
}

void writeReferenceImage(const ReferenceImage& image, const std::string& path) {
  AtomicFile file(path);
  writeReferenceImage(image, file);
  file.commit();
}

ReferenceImage readReferenceImage(const std::string& path) {
  const DecodedImage in = readImageFile(path);
  if (in.channels < 3) throw std::runtime_error("cannot read " + path + ": it has fewer than three channels");
  const int w = in.width, h = in.height, channels = in.channels;
  const bool eightBit = !in.isFloat;
  const std::vector<std::uint8_t>& bytes = in.bytes;
  const std::vector<float>& floats = in.floats;
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
