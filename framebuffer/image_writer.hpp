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

// Writes `bytes` to `path` atomically (temporary file, then rename).
void writeFileAtomically(const std::string& path, const std::string& bytes);

}  // namespace mpr
