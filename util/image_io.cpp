#include "util/image_io.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <stdexcept>

#include "util/image_io_table.hpp"
#include "util/png_writer.hpp"

namespace mpr {
namespace {

constexpr const char* kModuleName = "libmpr_image_io.so";

std::vector<std::string> modulePaths() {
  if (const char* env = std::getenv("MPR_IMAGE_IO"); env && *env) return {env};
  std::vector<std::string> paths;
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path dir = exe.parent_path();
    paths.push_back((dir / kModuleName).string());        // the build tree's mpr
    paths.push_back((dir / ".." / kModuleName).string());  // its tests, one folder down
#ifdef MPR_IMAGE_IO_INSTALLED
    paths.push_back((dir / ".." / MPR_IMAGE_IO_INSTALLED).string());  // bin/mpr of an installation
#endif
  }
#ifdef MPR_IMAGE_IO_BUILT
  paths.push_back(MPR_IMAGE_IO_BUILT);  // where this build put it, for programs elsewhere
#endif
  return paths;
}

struct Module {
  const ImageIoTable* table = nullptr;
  std::string problem;
};

const ImageIoTable& module() {
  static Module m;
  static std::once_flag once;
  std::call_once(once, [] {
    std::string tried;
    for (const std::string& path : modulePaths()) {
      std::error_code ec;
      if (!std::filesystem::is_regular_file(path, ec)) {
        tried += (tried.empty() ? "" : ", ") + path + " (absent)";
        continue;
      }
      void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!handle) {
        const char* e = dlerror();
        tried += (tried.empty() ? "" : ", ") + path + " (" + (e ? e : "cannot open") + ")";
        continue;
      }
      using Entry = const ImageIoTable* (*)();
      const auto entry = reinterpret_cast<Entry>(dlsym(handle, kImageIoTableSymbol));
      const ImageIoTable* t = entry ? entry() : nullptr;
      if (!t || t->version != kImageIoTableVersion) {
        tried += (tried.empty() ? "" : ", ") + path + " (not this build's module)";
        continue;
      }
      m.table = t;
      return;
    }
    m.problem = "cannot load the image module " + std::string(kModuleName) + " (tried " + tried +
                "); set MPR_IMAGE_IO to its path";
  });
  if (!m.table) throw std::runtime_error(m.problem);
  return *m.table;
}

void check(const std::string& error, const std::string& what) {
  if (!error.empty()) throw std::runtime_error(what + ": " + error);
}

}  // namespace

void writeImageFile(AtomicFile& file, int width, int height, int channels, const std::uint8_t* top,
                    std::ptrdiff_t rowStride) {
  // An RGB PNG, the image every render writes, without the module.
  if (channels == 3 && namesPngFile(file.target())) return file.write(encodeRgbPng(width, height, top, rowStride));
  // The module opens by name: the descriptor's own path, never the
  // temporary's name, which another process could have replaced.
  check(module().write(file.target(), file.descriptorPath(), width, height, channels, false, top, rowStride),
        "cannot write " + file.target());
}

void writeImageFile(AtomicFile& file, int width, int height, int channels, const float* top, std::ptrdiff_t rowStride) {
  check(module().write(file.target(), file.descriptorPath(), width, height, channels, true, top,
                       rowStride * static_cast<std::ptrdiff_t>(sizeof(float))),
        "cannot write " + file.target());
}

std::string encodePngBytes(int width, int height, int channels, const std::uint8_t* top, std::ptrdiff_t rowStride) {
  std::string png;
  check(module().encodePng(width, height, channels, top, rowStride, png), "cannot encode PNG");
  return png;
}

DecodedImage readImageFile(const std::string& path) {
  DecodedImage image;
  check(module().read(path, image), "cannot read " + path);
  return image;
}

std::string drawCanvasPng(int width, int height, const std::vector<CanvasOp>& ops) {
  std::string png;
  check(module().drawCanvas(width, height, ops, png), "cannot encode the drawing");
  return png;
}

}  // namespace mpr
