#include "framebuffer/framebuffer.hpp"

#include <algorithm>
#include <new>
#include <string>

namespace mpr {

PixelRect PixelRect::intersect(const PixelRect& o) const {
  return {std::max(x0, o.x0), std::max(y0, o.y0), std::min(x1, o.x1), std::min(y1, o.y1)};
}

namespace {

// Bytes as MiB, or KiB below one MiB, rounded up (16385x1 is not "0 MiB").
std::string bufferSizeText(unsigned long long width, unsigned long long height) {
  const unsigned long long bytes = width * height * Framebuffer::kBytesPerPixel;  // both sides below 2^31
  if (bytes >= (1ull << 20)) return std::to_string((bytes + (1ull << 20) - 1) >> 20) + " MiB";
  return std::to_string((bytes + 1023) >> 10) + " KiB";
}

}  // namespace

std::string Framebuffer::checkSize(long long width, long long height) {
  if (width <= 0 || height <= 0)
    return "framebuffer size " + std::to_string(width) + "x" + std::to_string(height) +
           " is not positive";
  if (width > kMaxSide || height > kMaxSide) {
    std::string m = "framebuffer size " + std::to_string(width) + "x" + std::to_string(height) +
                    " exceeds the largest side of " + std::to_string(kMaxSide) + " pixels";
    if (width < (1ll << 31) && height < (1ll << 31))
      m += " (" + bufferSizeText(static_cast<unsigned long long>(width), static_cast<unsigned long long>(height)) +
           " of buffers would be needed)";
    return m;
  }
  return {};
}

Framebuffer::Framebuffer(int width, int height, HardwareProfile profile)
    : width_(width), height_(height), profile_(std::move(profile)) {
  if (auto why = checkSize(width, height); !why.empty()) throw FramebufferSizeError(why);
  if (profile_.stencilBits < 1 || profile_.stencilBits > 8 || profile_.depthBits < 1 ||
      profile_.depthBits > 24)
    throw FramebufferSizeError("profile '" + profile_.name + "' has unsupported buffer widths");
  const std::size_t n = static_cast<std::size_t>(width) * height;
  try {
    color_.assign(n, Rgba8{0, 0, 0, 0});
    depth_.assign(n, 0);
    stencil_.assign(n, 0);
    accum_.assign(n * 4, 0);
  } catch (const std::bad_alloc&) {
    throw FramebufferSizeError("cannot allocate a " + std::to_string(width) + "x" +
                               std::to_string(height) + " framebuffer (" +
                               bufferSizeText(static_cast<unsigned long long>(width), static_cast<unsigned long long>(height)) + ")");
  }
}

}  // namespace mpr
