#include "framebuffer/image_writer.hpp"

#include <vector>

#include "util/image_io.hpp"

namespace mpr {
namespace {

template <typename T>
void writeRgb(AtomicFile& file, int w, int h, const T* rgb) {
  // The format comes from the target's name; the bytes go to its file.
  // GL rows are bottom-up; images top-down: start at the top row, step down.
  const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(w) * 3;
  const T* top = rgb + static_cast<std::size_t>(h - 1) * w * 3;
  writeImageFile(file, w, h, 3, top, -row);
  file.finish();
}

template <typename T>
void writeRgbTo(const std::string& path, int w, int h, const T* rgb) {
  AtomicFile file(path);
  writeRgb(file, w, h, rgb);
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
  writeRgbTo(path, width, height, rgb);
}

void writeRgbImage(const std::string& path, int width, int height, const float* rgb) {
  writeRgbTo(path, width, height, rgb);
}

void writeRgbImage(AtomicFile& file, int width, int height, const std::uint8_t* rgb) {
  writeRgb(file, width, height, rgb);
}

void writeRgbImage(AtomicFile& file, int width, int height, const float* rgb) {
  writeRgb(file, width, height, rgb);
}

void writeColorImage(const Framebuffer& fb, const std::string& path) {
  writeRgbImage(path, fb.width(), fb.height(), colorRgb(fb).data());
}

void writeColorImage(const Framebuffer& fb, AtomicFile& file) {
  writeRgbImage(file, fb.width(), fb.height(), colorRgb(fb).data());
}

}  // namespace mpr
