#pragma once
// Pass states as values (after Gallium's pipe_depth_stencil_alpha_state and
// pipe_blend_state, which softpipe binds whole): the fixed-function state one
// pass of the algorithm draws with, each part optional (unset: the pass does
// not care), with named constants for the algorithm's recurring passes.
//
// applyPassState sets every part a state holds, in one fixed order (the
// order of the fields below), so a named pass is the same GL calls wherever
// it is used. applyPassStateDifference sets only the parts that differ from a
// known current state.
#include <array>
#include <optional>
#include <utility>

#include "pipeline/gl/gl_api.hpp"

namespace mpr {

struct StencilSetting {
  GLenum func;
  GLint ref;
  GLuint valueMask, writeMask;
  std::optional<std::array<GLenum, 3>> ops;  // sfail, dpfail, dppass; unset: left as they are
  bool operator==(const StencilSetting&) const = default;
};

struct PassState {
  std::optional<StencilSetting> stencil;
  std::optional<std::array<bool, 4>> colorMask;
  std::optional<bool> depthMask;
  std::optional<bool> depthTest;
  std::optional<GLenum> depthFunc;
  std::optional<bool> lighting;
  std::optional<bool> fog;
  std::optional<bool> blend;
  std::optional<std::pair<GLenum, GLenum>> blendFunc;
  std::optional<bool> cullFace;
  std::optional<bool> clipPlane0;
  bool operator==(const PassState&) const = default;
};

// `over`'s parts replace `base`'s.
PassState merged(const PassState& base, const PassState& over);
// `s` with a stencil setting.
PassState withStencil(PassState s, const StencilSetting& stencil);

void applyPassState(GLApi& gl, const PassState& s);
// Only the parts of `to` that `current` does not already hold; `current`
// becomes `to` merged over it.
void applyPassStateDifference(GLApi& gl, const PassState& to, PassState& current);

namespace passes {

// apply_stencil's screen pass: only the stencil changes (colour and depth
// writes, depth test, lighting, fog, culling and the clip plane off).
inline constexpr PassState kScreenStencilOnly = [] {
  PassState s;
  s.colorMask = {false, false, false, false};
  s.depthMask = false;
  s.depthTest = false;
  s.lighting = false;
  s.fog = false;
  s.cullFace = false;
  s.clipPlane0 = false;
  return s;
}();

// Shadow volume counting: stencil only, depth LESS without writes, faces
// culled (the caller picks the front or back faces and the count's ops).
inline constexpr PassState kVolumeCount = [] {
  PassState s;
  s.colorMask = {false, false, false, false};
  s.depthMask = false;
  s.depthTest = true;
  s.depthFunc = GL_LESS;
  s.lighting = false;
  s.blend = false;
  s.cullFace = true;
  return s;
}();

// After a stencil-only pass: colour and depth writes back on.
inline constexpr PassState kWritesOn = [] {
  PassState s;
  s.colorMask = {true, true, true, true};
  s.depthMask = true;
  return s;
}();

}  // namespace passes
}  // namespace mpr
