#pragma once
// Reference images on disk, through OpenImageIO, top row first. 8-bit files
// (PNG, TIFF) hold each channel clamped to [0, 1] and quantised as the
// pipeline quantises a colour (floatToUnorm8: round to nearest, ties to even,
// of v * 255), so they compare byte for byte with `mpr render`'s images; EXR
// holds the linear floats. Files are written through util/atomic_file (a fresh
// temporary beside the target, renamed into place).
#include <cstdint>
#include <string>
#include <vector>

#include "reference/reference_renderer.hpp"
#include "util/atomic_file.hpp"

namespace mpr {

// RGB bytes, three a pixel, in the image's own row order (window y = 0 first).
std::vector<std::uint8_t> quantiseToRgb8(const ReferenceImage& image);

// By extension: .png, .tif, .tiff (8-bit) or .exr (32-bit float). Throws
// std::runtime_error on failure, leaving any old file at `path` untouched.
void writeReferenceImage(const ReferenceImage& image, const std::string& path);
// Into a prepared temporary (util/atomic_file), finished, not committed.
void writeReferenceImage(const ReferenceImage& image, AtomicFile& file);

// Reads PNG, TIFF or EXR (anything OpenImageIO reads, first three channels);
// 8-bit values come back as v / 255. Rows come back bottom first, as stored
// in a ReferenceImage. Throws std::runtime_error.
ReferenceImage readReferenceImage(const std::string& path);

}  // namespace mpr
