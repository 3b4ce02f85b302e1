#pragma once
// Reading and writing image files (PNG, TIFF, EXR, ...) through OpenImageIO,
// which is loaded only when an image is read or written: it lives in its own
// module, libmpr_image_io.so (util/image_io_module/), opened on first use.
// OpenImageIO and the ~250 libraries it pulls in cost every process about
// 0.3-0.6 s and 130 MB to load; `mpr gl`, `mpr conform`, `mpr step` and most
// tests never need it (issue 14, start-up).
//
// The module is looked for at $MPR_IMAGE_IO, then beside the executable
// (libmpr_image_io.so, ../libmpr_image_io.so, ../LIBDIR/mpr/), then where
// this build and its installation put it. Every function throws
// std::runtime_error with the reason (OpenImageIO's, or why the module
// could not be loaded).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "util/atomic_file.hpp"

namespace mpr {

// Pixels top row first, `channels` values a pixel: bytes for 8-bit files,
// floats otherwise.
struct DecodedImage {
  int width = 0, height = 0, channels = 0;
  bool isFloat = false;
  std::vector<std::uint8_t> bytes;
  std::vector<float> floats;
};

// An 8-bit RGB PNG is written by util/png_writer (libpng, the same bytes)
// without loading the module.
// Writes width x height pixels of `channels` values, the first row (the
// image's top) at `top`, each next row `rowStride` values on (negative for
// rows stored bottom-up), into `file`, in the format its target's extension
// names. The caller finishes and commits the file.
void writeImageFile(AtomicFile& file, int width, int height, int channels, const std::uint8_t* top,
                    std::ptrdiff_t rowStride);
void writeImageFile(AtomicFile& file, int width, int height, int channels, const float* top, std::ptrdiff_t rowStride);

// The bytes of a PNG file of 8-bit pixels (rows as writeImageFile), always
// encoded by the module (tests/util/png_writer_test.cpp holds util/png_writer
// to these bytes).
std::string encodePngBytes(int width, int height, int channels, const std::uint8_t* top, std::ptrdiff_t rowStride);

DecodedImage readImageFile(const std::string& path);

// A drawing on a white canvas, encoded as PNG: lines, boxes and text
// (DejaVu Sans where installed; without the font, no text). Coordinates are
// pixels from the top left.
struct CanvasOp {
  enum class Kind { Line, Box, FilledBox, Text, TextUp } kind = Kind::Line;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // Text: x0, y0 the anchor; TextUp: x0, y0 the top left of a 20 x 300 strip
  float rgb[3] = {0.0f, 0.0f, 0.0f};
  std::string text;
  int size = 12;
  int align = -1;  // Text: -1 left, 0 centre, 1 right of the anchor
};
std::string drawCanvasPng(int width, int height, const std::vector<CanvasOp>& ops);

}  // namespace mpr
