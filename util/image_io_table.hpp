#pragma once
// The table libmpr_image_io.so exports (mpr_image_io_table), between
// util/image_io.cpp, which opens the module, and the module itself
// (util/image_io_module/), the only code linked with OpenImageIO. Both are
// built together by the same compiler, so C++ types cross it; each entry
// returns an empty string, or why it failed.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "util/image_io.hpp"

namespace mpr {

struct ImageIoTable {
  int version;  // kImageIoTableVersion
  std::string (*write)(const std::string& formatPath, const std::string& filePath, int width, int height,
                       int channels, bool isFloat, const void* top, std::ptrdiff_t rowStrideBytes);
  std::string (*encodePng)(int width, int height, int channels, const std::uint8_t* top,
                           std::ptrdiff_t rowStrideBytes, std::string& png);
  std::string (*read)(const std::string& path, DecodedImage& image);
  std::string (*drawCanvas)(int width, int height, const std::vector<CanvasOp>& ops, std::string& png);
};

inline constexpr int kImageIoTableVersion = 1;
inline constexpr const char* kImageIoTableSymbol = "mpr_image_io_table";

}  // namespace mpr
