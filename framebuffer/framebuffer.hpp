#pragma once
// The buffers of one window: colour (RGBA8 with destination alpha), depth
// (integer, profile width), stencil (profile width, at most 8 bits) and
// accumulation (signed 16-bit words, 4 per pixel; RGB-only profiles keep the
// alpha word at 0). Rows are stored bottom-up, window y = 0 first, as GL
// addresses them.
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "framebuffer/blend.hpp"
#include "framebuffer/profile.hpp"

namespace mpr {

// Half-open pixel rectangle [x0, x1) x [y0, y1).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x0 >= x1 || y0 >= y1; }
  PixelRect intersect(const PixelRect& o) const;
};

// Refusal to allocate a framebuffer: too large, or not positive.
class FramebufferSizeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Framebuffer {
 public:
  // The largest side accepted, as GL_MAX_VIEWPORT_DIMS of a large implementation.
  static constexpr int kMaxSide = 16384;
  static constexpr std::size_t kBytesPerPixel = 4 + 4 + 1 + 8;

  // Throws FramebufferSizeError before touching memory when the size is refused.
  Framebuffer(int width, int height, HardwareProfile profile);

  // The reason a size would be refused, or empty when it is acceptable.
  static std::string checkSize(long long width, long long height);

  int width() const { return width_; }
  int height() const { return height_; }
  const HardwareProfile& profile() const { return profile_; }
  PixelRect bounds() const { return {0, 0, width_, height_}; }

  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width_ + x; }

  Rgba8& color(int x, int y) { return color_[index(x, y)]; }
  const Rgba8& color(int x, int y) const { return color_[index(x, y)]; }
  std::uint32_t& depth(int x, int y) { return depth_[index(x, y)]; }
  std::uint32_t depth(int x, int y) const { return depth_[index(x, y)]; }
  std::uint8_t& stencil(int x, int y) { return stencil_[index(x, y)]; }
  std::uint8_t stencil(int x, int y) const { return stencil_[index(x, y)]; }
  std::int16_t* accum(int x, int y) { return &accum_[index(x, y) * 4]; }
  const std::int16_t* accum(int x, int y) const { return &accum_[index(x, y) * 4]; }

  const std::vector<Rgba8>& colorData() const { return color_; }
  const std::vector<std::uint32_t>& depthData() const { return depth_; }
  const std::vector<std::uint8_t>& stencilData() const { return stencil_; }
  const std::vector<std::int16_t>& accumData() const { return accum_; }

 private:
  int width_, height_;
  HardwareProfile profile_;
  std::vector<Rgba8> color_;
  std::vector<std::uint32_t> depth_;
  std::vector<std::uint8_t> stencil_;
  std::vector<std::int16_t> accum_;
};

}  // namespace mpr
