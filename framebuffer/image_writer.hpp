#pragma once
// Writing the colour buffer as an ordinary image (top row first) through
// OpenImageIO; the format follows the file extension (PNG, TIFF, EXR, ...).
// Files are written to a temporary name and renamed into place, so a reader
// never sees half a file and a failed write leaves the old file untouched.
#include <string>

#include "framebuffer/framebuffer.hpp"

namespace mpr {

// Throws std::runtime_error with OpenImageIO's message on failure.
void writeColorImage(const Framebuffer& fb, const std::string& path);

// RGB pixels, three values a pixel, rows bottom-up (window y = 0 first) as
// the framebuffer stores them; written top row first, atomically. 8-bit
// values as they are; floats as floats where the format holds them (EXR).
void writeRgbImage(const std::string& path, int width, int height, const std::uint8_t* rgb);
void writeRgbImage(const std::string& path, int width, int height, const float* rgb);

// Writes `bytes` to `path` atomically (temporary file, then rename).
void writeFileAtomically(const std::string& path, const std::string& bytes);

}  // namespace mpr
