#include "algorithms/pass_state.hpp"

namespace mpr {
namespace {

GLboolean b(bool v) { return v ? GL_TRUE : GL_FALSE; }

void capability(GLApi& gl, GLenum cap, bool on) {
  if (on) gl.enable(cap);
  else gl.disable(cap);
}

template <class T>
void over(std::optional<T>& a, const std::optional<T>& b) {
  if (b) a = b;
}

}  // namespace

PassState merged(const PassState& base, const PassState& o) {
  PassState s = base;
  over(s.stencil, o.stencil);
  over(s.colorMask, o.colorMask);
  over(s.depthMask, o.depthMask);
  over(s.depthTest, o.depthTest);
  over(s.depthFunc, o.depthFunc);
  over(s.lighting, o.lighting);
  over(s.fog, o.fog);
  over(s.blend, o.blend);
  over(s.blendFunc, o.blendFunc);
  over(s.cullFace, o.cullFace);
  over(s.clipPlane0, o.clipPlane0);
  return s;
}

PassState withStencil(PassState s, const StencilSetting& stencil) {
  s.stencil = stencil;
  return s;
}

void applyPassState(GLApi& gl, const PassState& s) {
  if (s.stencil) {
    gl.stencilFunc(s.stencil->func, s.stencil->ref, s.stencil->valueMask);
    gl.stencilMask(s.stencil->writeMask);
    if (const auto& o = s.stencil->ops) gl.stencilOp((*o)[0], (*o)[1], (*o)[2]);
  }
  if (const auto& m = s.colorMask) gl.colorMask(b((*m)[0]), b((*m)[1]), b((*m)[2]), b((*m)[3]));
  if (s.depthMask) gl.depthMask(b(*s.depthMask));
  if (s.depthTest) capability(gl, GL_DEPTH_TEST, *s.depthTest);
  if (s.depthFunc) gl.depthFunc(*s.depthFunc);
  if (s.lighting) capability(gl, GL_LIGHTING, *s.lighting);
  if (s.fog) capability(gl, GL_FOG, *s.fog);
  if (s.blend) capability(gl, GL_BLEND, *s.blend);
  if (s.blendFunc) gl.blendFunc(s.blendFunc->first, s.blendFunc->second);
  if (s.cullFace) capability(gl, GL_CULL_FACE, *s.cullFace);
  if (s.clipPlane0) capability(gl, GL_CLIP_PLANE0, *s.clipPlane0);
}

void applyPassStateDifference(GLApi& gl, const PassState& to, PassState& current) {
  PassState d;
  auto diff = [](auto& out, const auto& want, const auto& have) {
    if (want && want != have) out = want;
  };
  diff(d.stencil, to.stencil, current.stencil);
  diff(d.colorMask, to.colorMask, current.colorMask);
  diff(d.depthMask, to.depthMask, current.depthMask);
  diff(d.depthTest, to.depthTest, current.depthTest);
  diff(d.depthFunc, to.depthFunc, current.depthFunc);
  diff(d.lighting, to.lighting, current.lighting);
  diff(d.fog, to.fog, current.fog);
  diff(d.blend, to.blend, current.blend);
  diff(d.blendFunc, to.blendFunc, current.blendFunc);
  diff(d.cullFace, to.cullFace, current.cullFace);
  diff(d.clipPlane0, to.clipPlane0, current.clipPlane0);
  applyPassState(gl, d);
  current = merged(current, to);
}

}  // namespace mpr
