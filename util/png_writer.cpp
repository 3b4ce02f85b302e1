#include "util/png_writer.hpp"

#include <png.h>

#include <algorithm>
#include <cctype>
#include <csetjmp>
#include <filesystem>
#include <stdexcept>

namespace mpr {
namespace {

void appendBytes(png_structp png, png_bytep data, png_size_t size) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), size);
}

void flushNothing(png_structp) {}

// libpng reports an error by longjmp after calling this: keep its message.
void keepMessage(png_structp png, png_const_charp message) {
  *static_cast<std::string*>(png_get_error_ptr(png)) = message;
  png_longjmp(png, 1);
}

void ignoreWarning(png_structp, png_const_charp) {}

}  // namespace

std::string encodeRgbPng(int width, int height, const std::uint8_t* top, std::ptrdiff_t rowStride) {
  std::string bytes, error;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, keepMessage, ignoreWarning);
  if (!png) throw std::runtime_error("cannot start libpng");
  png_infop info = png_create_info_struct(png);
  // Nothing with a destructor is made below this point: a longjmp back here
  // skips none.
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error(error.empty() ? "libpng failed" : "libpng: " + error);
  }
  png_set_write_fn(png, &bytes, appendBytes, flushNothing);
  // OpenImageIO 2.4's choices (png.imageio/pngoutput.cpp, png_pvt.h).
  png_set_compression_level(png, 6);
  png_set_compression_strategy(png, 0);  // Z_DEFAULT_STRATEGY
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_oFFs(png, info, 0, 0, PNG_OFFSET_PIXEL);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y)
    png_write_row(png, const_cast<png_bytep>(top + static_cast<std::ptrdiff_t>(y) * rowStride));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return bytes;
}

bool namesPngFile(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".png";
}

}  // namespace mpr
