#pragma once
// Shared by the per-pixel stencil tests (stencil_func_, stencil_op_,
// stencil_selection_ and stencil_four_bits_per_pixel_test.cpp): the stencil
// test and the stencil operations (GL 1.1 section 4.1.4 and
// EXT_stencil_wrap), checked per pixel through processFragment against
// truth tables written by hand from the GL text:
//   - the test: "(ref & mask) FUNC (stored & mask)", the reference on the left,
//     so GL_GREATER passes when ref > stored;
//   - the operations: KEEP, ZERO, REPLACE (by ref), INCR / DECR saturating at
//     0 and 2^bits - 1, INVERT (bitwise, within the width), INCR_WRAP /
//     DECR_WRAP modulo 2^bits;
//   - the write mask: only the bits set in it are replaced by the op's value;
//   - which op: sfail when the stencil test fails, dpfail when it passes and the
//     depth test fails, dppass when both pass or the depth test is disabled.
// Every expected value in those tests is written out by hand; none is
// computed by the code under test. Here: the ops in GL's order, fragments,
// and the states that take a fragment through one stencil path.
#include <array>
#include <cstdint>
#include <vector>

#include "framebuffer/compare_func.hpp"
#include "framebuffer/fragment_ops.hpp"
#include "framebuffer/framebuffer.hpp"
#include "framebuffer/stencil.hpp"

namespace mpr::stencil_per_pixel {

inline constexpr std::array<StencilOp, 8> kOps = {StencilOp::Keep,   StencilOp::Zero,    StencilOp::Replace,
                                                  StencilOp::Incr,   StencilOp::Decr,    StencilOp::Invert,
                                                  StencilOp::IncrWrap, StencilOp::DecrWrap};
inline constexpr std::array<const char*, 8> kOpNames = {"KEEP",   "ZERO",   "REPLACE",   "INCR",
                                                        "DECR",   "INVERT", "INCR_WRAP", "DECR_WRAP"};

inline Fragment frag(int x, int y, std::uint32_t depth = 0x800000) {
  return Fragment{x, y, depth, Rgba8{10, 20, 30, 40}, 1.0f};
}

// A state that only runs the stencil test: no alpha, depth or blending.
inline FragmentState stencilOnly(CompareFunc f, std::uint32_t ref, std::uint32_t valueMask) {
  FragmentState s;
  s.stencil.enabled = true;
  s.stencil.func = f;
  s.stencil.ref = ref;
  s.stencil.valueMask = valueMask;
  return s;
}

inline void setRow(Framebuffer& fb, int y, const std::vector<int>& values) {
  for (int x = 0; x < static_cast<int>(values.size()); ++x) fb.stencil(x, y) = static_cast<std::uint8_t>(values[x]);
}

// How the op is reached: as sfail, as dpfail or as dppass.
enum class Path { Sfail, Dpfail, Dppass };
inline constexpr std::array<Path, 3> kPaths = {Path::Sfail, Path::Dpfail, Path::Dppass};
inline constexpr std::array<const char*, 3> kPathNames = {"sfail", "dpfail", "dppass"};

// A state whose fragments take `op` through `path`; the other two slots hold
// ZERO so that a wrong selection shows.
inline FragmentState opState(StencilOp op, Path path, std::uint32_t writeMask, std::uint32_t ref) {
  FragmentState s;
  s.stencil.enabled = true;
  s.stencil.ref = ref;
  s.stencil.writeMask = writeMask;
  s.stencil.sfail = s.stencil.dpfail = s.stencil.dppass = StencilOp::Zero;
  s.depth.enabled = true;
  s.depth.func = CompareFunc::Always;
  switch (path) {
    case Path::Sfail:
      s.stencil.func = CompareFunc::Never;
      s.stencil.sfail = op;
      break;
    case Path::Dpfail:
      s.stencil.func = CompareFunc::Always;
      s.depth.func = CompareFunc::Never;
      s.stencil.dpfail = op;
      break;
    case Path::Dppass:
      s.stencil.func = CompareFunc::Always;
      s.stencil.dppass = op;
      break;
  }
  return s;
}

}  // namespace mpr::stencil_per_pixel
