// Every translation of the 1994 paper's stencil notation that Figure 4 uses,
// proved on every stencil value: a 16x16 window holds the values 0..255 (one
// per pixel), apply_stencil runs through the emulated GL, and each pixel must
// hold what the paper's words say ("where stored COMP_FUNC COMP_VALUE, set
// PASS_VALUE"), and the colour and depth buffers must be untouched.
#include <gtest/gtest.h>

#include <functional>

#include "algorithms/apply_stencil.hpp"
#include "algorithms/gl_command_stream.hpp"
#include "framebuffer/profile.hpp"

namespace mpr {
namespace {

constexpr StencilLevels kLevels = stencilLevelsForBits(8);

// Runs apply_stencil on a window whose pixel (x, y) holds y * 16 + x, and
// checks each against `meaning(stored)`.
void expectMeaning(const PaperStencil& s, const std::function<std::uint32_t(std::uint32_t)>& meaning) {
  GLContext context(16, 16, indigoProfile());
  GLCommandStream gl(context, false);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      context.framebuffer().stencil(x, y) = static_cast<std::uint8_t>(y * 16 + x);
      context.framebuffer().depth(x, y) = 12345u;
    }
  gl.enable(GL_STENCIL_TEST);
  apply_stencil(gl, s, kLevels);
  EXPECT_EQ(gl.glErrors(), 0u);
  int wrong = 0;
  for (std::uint32_t v = 0; v < 256; ++v) {
    const int x = static_cast<int>(v % 16), y = static_cast<int>(v / 16);
    if (context.stencilAt(x, y) != meaning(v) && ++wrong <= 8)
      ADD_FAILURE() << paperStencilText(s, kLevels) << ": stored " << v << " became " << context.stencilAt(x, y)
                    << ", the paper means " << meaning(v);
    EXPECT_EQ(context.depthAt(x, y), 12345u);
    EXPECT_EQ(context.colorAt(x, y), (Rgba8{0, 0, 0, 0}));
  }
}

TEST(ApplyStencil, LevelsForEightBits) {
  EXPECT_EQ(kLevels.shadMin, 128u);
  EXPECT_EQ(kLevels.shadZero, 192u);
  EXPECT_EQ(kLevels.maxRecursionDepth(), 127);
  EXPECT_EQ(stencilLevelsForBits(4).shadMin, 8u);
  EXPECT_EQ(stencilLevelsForBits(4).shadZero, 12u);
}

// draw_window: apply_stencil(EQUAL, ZERO, REPLACE, SHAD_ZERO)
TEST(ApplyStencil, EqualZeroReplaceShadZero) {
  expectMeaning({PaperCompare::Equal, 0, PaperPass::Replace, kLevels.shadZero},
                [](std::uint32_t v) { return v == 0 ? 192u : v; });
}

// draw_window, draw_ref_shadows, draw_all_shadows:
// apply_stencil(GREATER, SHAD_MIN, REPLACE, SHAD_ZERO). Exact for every value
// but SHAD_MIN itself, which the algorithm never holds (see apply_stencil.hpp).
TEST(ApplyStencil, GreaterShadMinReplaceShadZero) {
  expectMeaning({PaperCompare::Greater, kLevels.shadMin, PaperPass::Replace, kLevels.shadZero},
                [](std::uint32_t v) { return v > 128 ? 192u : v == 128 ? 192u : v; });
}

// draw_window: apply_stencil(GREATER, SHAD_MIN, REPLACE, ZERO)
TEST(ApplyStencil, GreaterShadMinReplaceZero) {
  expectMeaning({PaperCompare::Greater, kLevels.shadMin, PaperPass::Replace, 0},
                [](std::uint32_t v) { return v > 128 ? 0u : v; });
}

// draw_ref_objects: apply_stencil(EQUAL, ZERO, REPLACE, REF_LEVEL) and
// apply_stencil(EQUAL, REF_LEVEL, REPLACE, ZERO), for every level.
TEST(ApplyStencil, EqualZeroReplaceLevelAndBackForEveryLevel) {
  for (std::uint32_t level = 1; level < 128; ++level) {
    expectMeaning({PaperCompare::Equal, 0, PaperPass::Replace, level},
                  [&](std::uint32_t v) { return v == 0 ? level : v; });
    expectMeaning({PaperCompare::Equal, level, PaperPass::Replace, 0},
                  [&](std::uint32_t v) { return v == level ? 0u : v; });
  }
}

// draw_normal_objects: stencil(EQUAL, STEN_VALUE, KEEP, STEN_VALUE) changes nothing.
TEST(ApplyStencil, EqualKeepChangesNothing) {
  expectMeaning({PaperCompare::Equal, kLevels.shadZero, PaperPass::Keep, kLevels.shadZero},
                [](std::uint32_t v) { return v; });
}

TEST(ApplyStencil, TheGLSettingsAreTheDocumentedOnes) {
  const GLStencilSetting a = translateStencil({PaperCompare::Equal, 0, PaperPass::Replace, 192}, kLevels);
  EXPECT_EQ(a.func, static_cast<GLenum>(GL_EQUAL));
  EXPECT_EQ(a.ref, 0u);
  EXPECT_EQ(a.writeMask, 0xC0u);
  EXPECT_EQ(a.zpass, static_cast<GLenum>(GL_INVERT));
  const GLStencilSetting b = translateStencil({PaperCompare::Greater, 128, PaperPass::Replace, 192}, kLevels);
  EXPECT_EQ(b.func, static_cast<GLenum>(GL_LEQUAL));
  EXPECT_EQ(b.ref, 192u);
  EXPECT_EQ(b.valueMask, 0x80u);
  EXPECT_EQ(b.writeMask, 0xFFu);
  EXPECT_EQ(b.zpass, static_cast<GLenum>(GL_REPLACE));
  EXPECT_THROW(translateStencil({PaperCompare::Greater, 5, PaperPass::Replace, 0}, kLevels), std::logic_error);
}

// A 4-bit profile: SHAD_MIN 8, SHAD_ZERO 12; the same translations hold.
TEST(ApplyStencil, FourBitProfile) {
  HardwareProfile p = indigoProfile();
  p.stencilBits = 4;
  const StencilLevels l = stencilLevelsFor(p);
  GLContext context(16, 1, p);
  GLCommandStream gl(context, false);
  for (int x = 0; x < 16; ++x) context.framebuffer().stencil(x, 0) = static_cast<std::uint8_t>(x);
  gl.enable(GL_STENCIL_TEST);
  apply_stencil(gl, {PaperCompare::Greater, l.shadMin, PaperPass::Replace, l.shadZero}, l);
  for (std::uint32_t v = 0; v < 16; ++v) EXPECT_EQ(context.stencilAt(static_cast<int>(v), 0), v >= 8 ? 12u : v);
  apply_stencil(gl, {PaperCompare::Equal, 0, PaperPass::Replace, l.shadZero}, l);
  EXPECT_EQ(context.stencilAt(0, 0), 12u);
}

}  // namespace
}  // namespace mpr
