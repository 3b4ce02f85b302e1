#include "framebuffer/image_writer.hpp"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace mpr {
namespace {

std::string temporaryNameFor(const std::string& path) {
  const std::filesystem::path p(path);
  // Keep the extension so that OpenImageIO picks the right format.
  return (p.parent_path() / ("." + p.stem().string() + ".tmp" + std::to_string(::getpid()) + p.extension().string()))
      .string();
}

// Moves a finished temporary file over `path`; removes it on failure.
void renameIntoPlace(const std::string& tmp, const std::string& path) {
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write " + path + ": " + ec.message());
  }
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& bytes) {
  const std::string tmp = temporaryNameFor(path);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + path);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
      std::remove(tmp.c_str());
      throw std::runtime_error("cannot write " + path);
    }
  }
  renameIntoPlace(tmp, path);
}

namespace {

template <typename T>
void writeRgb(const std::string& path, int w, int h, const T* rgb, OIIO::TypeDesc type) {
  const std::string tmp = temporaryNameFor(path);
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error("cannot write " + path + ": " + OIIO::geterror());
  OIIO::ImageSpec spec(w, h, 3, type);
  // GL rows are bottom-up; images top-down: start at the top row, step down.
  const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(w) * 3 * static_cast<std::ptrdiff_t>(sizeof(T));
  const T* top = rgb + static_cast<std::size_t>(h - 1) * w * 3;
  if (!out->open(tmp, spec) || !out->write_image(type, top, OIIO::AutoStride, -row) || !out->close()) {
    const std::string why = out->geterror();
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write " + path + ": " + why);
  }
  renameIntoPlace(tmp, path);
}

}  // namespace

void writeRgbImage(const std::string& path, int width, int height, const std::uint8_t* rgb) {
  writeRgb(path, width, height, rgb, OIIO::TypeDesc::UINT8);
}

void writeRgbImage(const std::string& path, int width, int height, const float* rgb) {
  writeRgb(path, width, height, rgb, OIIO::TypeDesc::FLOAT);
}

void writeColorImage(const Framebuffer& fb, const std::string& path) {
  // Colour only: a viewer should not show the destination alpha that the
  // multi-pass algorithms use as scratch.
  std::vector<std::uint8_t> rgb;
  rgb.reserve(fb.colorData().size() * 3);
  for (const Rgba8& c : fb.colorData()) rgb.insert(rgb.end(), {c[0], c[1], c[2]});
  writeRgbImage(path, fb.width(), fb.height(), rgb.data());
}

}  // namespace mpr
