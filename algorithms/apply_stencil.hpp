#pragma once
// The 1994 paper's stencil notation (Figure 4) translated into GL calls.
//
// The paper writes stencil(COMP_FUNC, COMP_VALUE, PASS_FUNC, PASS_VALUE):
// "where the stored value COMP_FUNC COMP_VALUE, apply PASS_FUNC with
// PASS_VALUE", and the text reads GREATER, SHAD_MIN as "stencil values greater
// than the shadow minimum". GL's glStencilFunc(func, ref, mask) instead passes
// when (ref & mask) func (stored & mask), the reference on the left, and
// GL_REPLACE can only write the very `ref` it compares with. So each use in
// Figure 4 is translated by its meaning, and tests/algorithms prove every
// translation on all stencil values:
//
//   EQUAL A, REPLACE B   glStencilFunc(EQUAL, A, max), glStencilMask(A ^ B),
//                        glStencilOp(KEEP, KEEP, INVERT): A ^ (A ^ B) = B on
//                        exactly the pixels holding A; exact for any A, B.
//   EQUAL A, KEEP        glStencilFunc(EQUAL, A, max), glStencilOp(KEEP x3).
//   GREATER SHAD_MIN,    glStencilFunc(LESS, SHAD_MIN, max) (SHAD_MIN < stored),
//     REPLACE ZERO       glStencilOp(KEEP, KEEP, ZERO): exact.
//   GREATER SHAD_MIN,    No single GL pass maps every value above SHAD_MIN to
//     REPLACE SHAD_ZERO  SHAD_ZERO while keeping SHAD_MIN itself (REPLACE writes
//                        the compared ref; no op makes a constant of a range
//                        otherwise). Translated as "stored >= SHAD_MIN":
//                        glStencilFunc(LEQUAL, SHAD_ZERO, SHAD_MIN) compares
//                        the top bit only (SHAD_MIN <= stored & SHAD_MIN), and
//                        REPLACE writes the ref, SHAD_ZERO. It differs
//                        from the paper only at stored == SHAD_MIN, a value the
//                        algorithm never holds: recursion levels stay below
//                        SHAD_MIN and shadow counts above it (counts are
//                        checked, see draw_window.cpp).
#include <cstdint>
#include <string>

#include "pipeline/gl/gl_api.hpp"
#include "algorithms/stencil_levels.hpp"

namespace mpr {

enum class PaperCompare : std::uint8_t { Equal, Greater };
enum class PaperPass : std::uint8_t { Keep, Replace };

struct PaperStencil {
  PaperCompare compare;
  std::uint32_t compareValue;
  PaperPass pass;
  std::uint32_t passValue;
};

// The GL state one PaperStencil becomes.
struct GLStencilSetting {
  GLenum func;
  std::uint32_t ref, valueMask, writeMask;
  GLenum zpass;  // sfail and zfail are GL_KEEP
};

// Throws std::logic_error for a combination Figure 4 never uses.
GLStencilSetting translateStencil(const PaperStencil& s, const StencilLevels& levels);

// "EQUAL, 0" as the paper writes it, for pass labels and the stepper.
std::string paperStencilText(const PaperStencil& s, const StencilLevels& levels);

// stencil(...): sets the stencil state for the draws that follow.
void stencil(GLApi& gl, const PaperStencil& s, const StencilLevels& levels);

// apply_stencil(...): stencil(...) applied to every pixel, as a full-screen
// quad under identity matrices with colour and depth writes off, and the
// depth test, lighting, fog, culling and clip plane 0 off (DESIGN.md). It does
// not restore them: every step of draw_window sets the state it draws with.
void apply_stencil(GLApi& gl, const PaperStencil& s, const StencilLevels& levels);

// apply_to_screen() of Figure 4 with a GL stencil setting of the caller's
// (face_light_stencil raises every shadow value by one this way).
void apply_to_screen(GLApi& gl, const GLStencilSetting& g);

}  // namespace mpr
