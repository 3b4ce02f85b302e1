#include "framebuffer/image_writer.hpp"

#include <OpenImageIO/imageio.h>

#include <stdexcept>
#include <vector>

namespace mpr {
namespace {

template <typename T>
void writeRgb(AtomicFile& file, int w, int h, const T* rgb, OIIO::TypeDesc type) {
  const std::string& path = file.target();
  // The format comes from the target's name; the bytes go to the temporary.
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error("cannot write " + path + ": " + OIIO::geterror());
  OIIO::ImageSpec spec(w, h, 3, type);
  // GL rows are bottom-up; images top-down: start at the top row, step down.
  const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(w) * 3 * static_cast<std::ptrdiff_t>(sizeof(T));
  const T* top = rgb + static_cast<std::size_t>(h - 1) * w * 3;
  if (!out->open(file.temporaryPath(), spec) || !out->write_image(type, top, OIIO::AutoStride, -row) ||
      !out->close())
    throw std::runtime_error("cannot write " + path + ": " + out->geterror());
  file.finish();
}

template <typename T>
void writeRgbTo(const std::string& path, int w, int h, const T* rgb, OIIO::TypeDesc type) {
  AtomicFile file(path);
  writeRgb(file, w, h, rgb, type);
  file.commit();
}

std::vector<std::uint8_t> colorRgb(const Framebuffer& fb) {
  // Colour only: a viewer should not show the destination alpha that the
  // multi-pass algorithms use as scratch.
  std::vector<std::uint8_t> rgb;
  rgb.reserve(fb.colorData().size() * 3);
  for (const Rgba8& c : fb.colorData()) rgb.insert(rgb.end(), {c[0], c[1], c[2]});
  return rgb;
}

}  // namespace

void writeRgbImage(const std::string& path, int width, int height, const std::uint8_t* rgb) {
  writeRgbTo(path, width, height, rgb, OIIO::TypeDesc::UINT8);
}

void writeRgbImage(const std::string& path, int width, int height, const float* rgb) {
  writeRgbTo(path, width, height, rgb, OIIO::TypeDesc::FLOAT);
}

void writeRgbImage(AtomicFile& file, int width, int height, const std::uint8_t* rgb) {
  writeRgb(file, width, height, rgb, OIIO::TypeDesc::UINT8);
}

void writeRgbImage(AtomicFile& file, int width, int height, const float* rgb) {
  writeRgb(file, width, height, rgb, OIIO::TypeDesc::FLOAT);
}

void writeColorImage(const Framebuffer& fb, const std::string& path) {
  writeRgbImage(path, fb.width(), fb.height(), colorRgb(fb).data());
}

void writeColorImage(const Framebuffer& fb, AtomicFile& file) {
  writeRgbImage(file, fb.width(), fb.height(), colorRgb(fb).data());
}

}  // namespace mpr
