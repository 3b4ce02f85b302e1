#pragma once
// Writing the colour buffer as an ordinary image (top row first) through
// OpenImageIO (util/image_io: loaded on first use); the format follows the
// file extension (PNG, TIFF, EXR, ...).
// Files are written through util/atomic_file: a fresh temporary in the
// target's folder, renamed into place, so a reader never sees half a file, a
// failed write leaves the old file untouched, and nothing else is touched.
#include <cstdint>
#include <string>

#include "framebuffer/framebuffer.hpp"
#include "util/atomic_file.hpp"

namespace mpr {

// Throws std::runtime_error with OpenImageIO's message on failure.
void writeColorImage(const Framebuffer& fb, const std::string& path);
// Into a prepared temporary, finished but not committed (for a group of outputs).
void writeColorImage(const Framebuffer& fb, AtomicFile& file);

// RGB pixels, three values a pixel, rows bottom-up (window y = 0 first) as
// the framebuffer stores them; written top row first, atomically. 8-bit
// values as they are; floats as floats where the format holds them (EXR).
void writeRgbImage(const std::string& path, int width, int height, const std::uint8_t* rgb);
void writeRgbImage(const std::string& path, int width, int height, const float* rgb);
// Into a prepared temporary (OpenImageIO is handed the name AtomicFile
// created), finished but not committed.
void writeRgbImage(AtomicFile& file, int width, int height, const std::uint8_t* rgb);
void writeRgbImage(AtomicFile& file, int width, int height, const float* rgb);

}  // namespace mpr
