#include "cli/frame_delta_encoder.hpp"

#include <cstring>
#include <type_traits>

#include "cli/page_encoding.hpp"

namespace mpr::cli {
namespace {

// Gaps shorter than this are cheaper inside a run (as zero differences) than
// as a new run's two varints.
constexpr std::size_t kFoldGap = 4;

// Element-wise wrapping difference of E-typed elements, n per pixel, appended
// little-endian; `prev` becomes `now`.
template <typename E, std::size_t N>
void encodeBuffer(std::string& out, const E* now, E* prev, std::size_t pixels) {
  auto changed = [&](std::size_t p) { return std::memcmp(now + p * N, prev + p * N, sizeof(E) * N) != 0; };
  std::string runs;
  std::size_t count = 0, end = 0;  // end: the pixel after the last run
  std::size_t p = 0;
  while (p < pixels) {
    if (!changed(p)) {
      ++p;
      continue;
    }
    std::size_t last = p;  // the run's last changed pixel
    for (std::size_t q = p + 1; q < pixels && q - last - 1 < kFoldGap; ++q)
      if (changed(q)) last = q;
    const std::size_t q = last + 1;
    putVarint(runs, p - end);
    putVarint(runs, q - p);
    for (std::size_t i = p * N; i < q * N; ++i) {
      using U = std::make_unsigned_t<E>;
      U d = static_cast<U>(static_cast<U>(now[i]) - static_cast<U>(prev[i]));
      for (std::size_t b = 0; b < sizeof(E); ++b) runs.push_back(static_cast<char>((d >> (8 * b)) & 0xff));
      prev[i] = now[i];
    }
    ++count;
    end = p = q;
  }
  putVarint(out, count);
  out += runs;
}

}  // namespace

FrameDeltaEncoder::FrameDeltaEncoder(int width, int height) {
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  colour_.assign(n, Rgba8{});
  depth_.assign(n, 0);
  stencil_.assign(n, 0);
  accum_.assign(n * 4, 0);
}

std::string FrameDeltaEncoder::encode(const Framebuffer& fb) {
  const std::size_t n = stencil_.size();
  std::string out;
  static_assert(sizeof(Rgba8) == 4, "colour pixels are 4 packed bytes");
  encodeBuffer<std::uint8_t, 4>(out, reinterpret_cast<const std::uint8_t*>(fb.colorData().data()),
                                reinterpret_cast<std::uint8_t*>(colour_.data()), n);
  encodeBuffer<std::uint32_t, 1>(out, fb.depthData().data(), depth_.data(), n);
  encodeBuffer<std::uint8_t, 1>(out, fb.stencilData().data(), stencil_.data(), n);
  encodeBuffer<std::int16_t, 4>(out, fb.accumData().data(), accum_.data(), n);
  return out;
}

}  // namespace mpr::cli
