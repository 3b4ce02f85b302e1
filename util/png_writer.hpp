#pragma once
// PNG files of 8-bit RGB pixels written by libpng itself, without loading
// OpenImageIO's module (util/image_io.hpp): every `mpr render` and every
// `mpr gl --dump` writes one, and loading OpenImageIO and the libraries it
// pulls in took 0.27 s of each such process (issue 14). The bytes are the
// ones OpenImageIO 2.4 writes for the same pixels (its PNG writer also calls
// libpng: zlib level 6, the default strategy and row filters, an oFFs chunk
// of 0, 0), which tests/util/png_writer_test.cpp holds on every image it
// draws.
#include <cstddef>
#include <cstdint>
#include <string>

namespace mpr {

// The PNG file of width x height RGB pixels, the first row (the image's top)
// at `top`, each next row `rowStride` bytes on (negative for rows stored
// bottom-up). Throws std::runtime_error with libpng's message.
std::string encodeRgbPng(int width, int height, const std::uint8_t* top, std::ptrdiff_t rowStride);

// True when `path` names a PNG file (its extension, any case), which
// encodeRgbPng writes.
bool namesPngFile(const std::string& path);

}  // namespace mpr
