#pragma once
// NumPy .npy files (format version 1.0, little-endian, C order), the dump
// format of spec/gl-script.md. Rows go from window y = 0 (the bottom row), as
// glReadPixels returns them.
#include <cstdint>
#include <string>
#include <vector>

#include "framebuffer/framebuffer.hpp"

namespace mpr {

// The bytes of a .npy file holding `data` with dtype `descr` ("|u1", "<u4", "<i2") and `shape`.
std::string npyBytes(const std::string& descr, const std::vector<std::size_t>& shape, const void* data,
                     std::size_t dataBytes);

// The four buffer dumps of a framebuffer, keyed by buffer name: "color"
// (H, W, 4) |u1, "depth" (H, W) <u4, "stencil" (H, W) |u1, "accum" (H, W, 4) <i2.
struct NamedBytes {
  std::string name;
  std::string bytes;
};
std::vector<NamedBytes> framebufferNpyDumps(const Framebuffer& fb);
// Their names, in that order: what a dump folder will hold, known before
// the render (cli/output_set checks them against inputs and other outputs).
const std::vector<std::string>& framebufferDumpNames();

}  // namespace mpr
