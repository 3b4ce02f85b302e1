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

void writeColorImage(const Framebuffer& fb, const std::string& path) {
  const int w = fb.width(), h = fb.height();
  const std::string tmp = temporaryNameFor(path);
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error("cannot write " + path + ": " + OIIO::geterror());
  // Colour only: a viewer should not show the destination alpha that the
  // multi-pass algorithms use as scratch. GL rows are bottom-up; images top-down.
  OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Rgba8& c = fb.color(x, y);
      std::uint8_t* dst = &rgb[(static_cast<std::size_t>(h - 1 - y) * w + x) * 3];
      for (int i = 0; i < 3; ++i) dst[i] = c[i];
    }
  if (!out->open(tmp, spec) || !out->write_image(OIIO::TypeDesc::UINT8, rgb.data()) || !out->close()) {
    const std::string why = out->geterror();
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write " + path + ": " + why);
  }
  renameIntoPlace(tmp, path);
}

}  // namespace mpr
