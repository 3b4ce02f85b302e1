#pragma once
// The accumulation buffer (GL 1.1 section 4.2.4): signed 16-bit words, 32767
// standing for 1.0. The word arithmetic is a profile property:
//  - mesa:   exactly Mesa's main/accum.c on an RGBA_SNORM16 buffer: products
//            truncated toward zero into a short, sums wrapping modulo 2^16,
//            GL_RETURN rounding half to even into the 8-bit colour buffer.
//  - indigo: the same products and rounding, but sums saturate at -32768 and
//            32767 as a hardware adder with clamping would; RGB words only
//            (the paper's 48-bit buffer).
#include <array>
#include <cstdint>

#include "framebuffer/framebuffer.hpp"

namespace mpr {

enum class AccumOp : std::uint8_t { Accum, Load, Return, Mult, Add };

// glClearAccum value (already clamped to [-1, 1]) as the stored word.
std::int16_t accumClearWord(float v);

// Applies `op` to the pixels of `region` (the scissored window). GL_RETURN
// writes colour through `colorMask`.
void accumulate(Framebuffer& fb, const PixelRect& region, AccumOp op, float value,
                const std::array<bool, 4>& colorMask);

}  // namespace mpr
