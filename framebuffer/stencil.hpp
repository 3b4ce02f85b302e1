#pragma once
// The stencil test and stencil operations (GL 1.1 section 4.1.4, plus the
// INCR_WRAP / DECR_WRAP of EXT_stencil_wrap). All arithmetic is on the
// profile's stencil width: INCR and DECR saturate at 0 and 2^bits - 1.
#include <cstdint>

#include "framebuffer/compare_func.hpp"

namespace mpr {

enum class StencilOp : std::uint8_t { Keep, Zero, Replace, Incr, Decr, Invert, IncrWrap, DecrWrap };

struct StencilState {
  bool enabled = false;
  CompareFunc func = CompareFunc::Always;
  std::uint32_t ref = 0;         // already clamped to [0, max] by the caller
  std::uint32_t valueMask = ~0u; // glStencilFunc mask
  std::uint32_t writeMask = ~0u; // glStencilMask
  StencilOp sfail = StencilOp::Keep;
  StencilOp dpfail = StencilOp::Keep;
  StencilOp dppass = StencilOp::Keep;
};

// GL: (ref & mask) FUNC (stored & mask).
constexpr bool stencilTest(const StencilState& s, std::uint32_t stored) {
  return compare(s.func, s.ref & s.valueMask, stored & s.valueMask);
}

// The value an operation computes, before the write mask.
constexpr std::uint32_t stencilOpValue(StencilOp op, std::uint32_t stored, std::uint32_t ref,
                                       std::uint32_t max) {
  switch (op) {
    case StencilOp::Keep: return stored;
    case StencilOp::Zero: return 0;
    case StencilOp::Replace: return ref & max;
    case StencilOp::Incr: return stored < max ? stored + 1 : max;
    case StencilOp::Decr: return stored > 0 ? stored - 1 : 0;
    case StencilOp::Invert: return ~stored & max;
    case StencilOp::IncrWrap: return (stored + 1) & max;
    case StencilOp::DecrWrap: return (stored - 1) & max;
  }
  return stored;
}

// The stored value after applying `op`: only bits set in the write mask change.
constexpr std::uint32_t applyStencilOp(StencilOp op, std::uint32_t stored, const StencilState& s,
                                       std::uint32_t max) {
  const std::uint32_t v = stencilOpValue(op, stored, s.ref, max);
  const std::uint32_t m = s.writeMask & max;
  return (stored & ~m) | (v & m);
}

}  // namespace mpr
