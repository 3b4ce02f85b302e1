// GLContext: construction, errors, framebuffer state, clears, per-fragment
// state and accumulation. Transform, lighting and drawing live in their own
// files (gl_context_transform.cpp, gl_context_lighting.cpp, gl_context_draw.cpp);
// drawing below glEnd is the draw stage's (pipeline/draw/draw_stage.hpp).
#include "pipeline/gl/gl_context.hpp"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace mpr {
namespace {

std::optional<CompareFunc> compareFuncFromGL(GLenumValue f) {
  switch (f) {
    case GL_NEVER: return CompareFunc::Never;
    case GL_LESS: return CompareFunc::Less;
    case GL_EQUAL: return CompareFunc::Equal;
    case GL_LEQUAL: return CompareFunc::Lequal;
    case GL_GREATER: return CompareFunc::Greater;
    case GL_NOTEQUAL: return CompareFunc::Notequal;
    case GL_GEQUAL: return CompareFunc::Gequal;
    case GL_ALWAYS: return CompareFunc::Always;
  }
  return std::nullopt;
}

std::optional<StencilOp> stencilOpFromGL(GLenumValue op) {
  switch (op) {
    case GL_KEEP: return StencilOp::Keep;
    case GL_ZERO: return StencilOp::Zero;
    case GL_REPLACE: return StencilOp::Replace;
    case GL_INCR: return StencilOp::Incr;
    case GL_DECR: return StencilOp::Decr;
    case GL_INVERT: return StencilOp::Invert;
    case GL_INCR_WRAP: return StencilOp::IncrWrap;
    case GL_DECR_WRAP: return StencilOp::DecrWrap;
  }
  return std::nullopt;
}

std::optional<BlendFactor> blendFactorFromGL(GLenumValue f) {
  switch (f) {
    case GL_ZERO: return BlendFactor::Zero;
    case GL_ONE: return BlendFactor::One;
    case GL_SRC_COLOR: return BlendFactor::SrcColor;
    case GL_ONE_MINUS_SRC_COLOR: return BlendFactor::OneMinusSrcColor;
    case GL_DST_COLOR: return BlendFactor::DstColor;
    case GL_ONE_MINUS_DST_COLOR: return BlendFactor::OneMinusDstColor;
    case GL_SRC_ALPHA: return BlendFactor::SrcAlpha;
    case GL_ONE_MINUS_SRC_ALPHA: return BlendFactor::OneMinusSrcAlpha;
    case GL_DST_ALPHA: return BlendFactor::DstAlpha;
    case GL_ONE_MINUS_DST_ALPHA: return BlendFactor::OneMinusDstAlpha;
    case GL_SRC_ALPHA_SATURATE:
      // GL 1.1 takes it as a source factor only; Mesa's compatibility
      // context (GL 3.3 and later rules) takes it for the destination too,
      // and we follow the reference.
      return BlendFactor::SrcAlphaSaturate;
  }
  return std::nullopt;
}

float clamp01(float v) { return std::clamp(v, 0.0f, 1.0f); }

}  // namespace

GLContext::GLContext(int width, int height, const HardwareProfile& profile)
    : draw_(width, height, profile),
      cullMode_(GL_BACK),
      frontFace_(GL_CCW),
      modelview_(32),
      projection_(32),
      matrixMode_(GL_MODELVIEW),
      colorMaterialFace_(GL_FRONT_AND_BACK),
      colorMaterialMode_(GL_AMBIENT_AND_DIFFUSE) {
  viewport(0, 0, width, height);
  scissorBox_ = {0, 0, width, height};
  setterValues_.scissor = {0, 0, width, height};
  clearValues_.depth = quadClearDepth_ = fb().profile().depthMax();
  // GL's initial masks are all ones; held at the stencil width.
  frag_.stencil.valueMask = frag_.stencil.writeMask = fb().profile().stencilMax();
  lighting_.lights[0].diffuse = Vec4(1, 1, 1, 1);
  lighting_.lights[0].specular = Vec4(1, 1, 1, 1);
}

std::array<std::int16_t, 4> GLContext::accumAt(int x, int y) const {
  settle();
  const std::int16_t* a = fb().accum(x, y);
  return {a[0], a[1], a[2], a[3]};
}

void GLContext::setError(GLenumValue e) {
  if (error_ == GL_NO_ERROR) error_ = e;
}

GLenumValue GLContext::getError() {
  const GLenumValue e = error_;
  error_ = GL_NO_ERROR;
  return e;
}

bool GLContext::checkOutsideBeginEnd() {
  if (inBegin_) {
    setError(GL_INVALID_OPERATION);
    return false;
  }
  // No flush here: each setter flushes when it changes state (changing()).
  return true;
}

PixelRect GLContext::drawRegion() const {
  PixelRect r = viewportBox_.intersect(fb().bounds());
  if (scissorEnabled_) r = r.intersect(scissorBox_);
  return r;
}

// --- framebuffer and clears ---------------------------------------------------

namespace {

// x + w for a box's far edge: large origins and sizes saturate at int's
// maximum rather than overflow (the box only ever meets the window).
int saturatingAdd(int x, int w) {
  const long long sum = static_cast<long long>(x) + w;
  return sum > std::numeric_limits<int>::max() ? std::numeric_limits<int>::max() : static_cast<int>(sum);
}

}  // namespace

void GLContext::viewport(int x, int y, int w, int h) {
  if (!checkOutsideBeginEnd()) return;
  if (w < 0 || h < 0) return setError(GL_INVALID_VALUE);
  w = std::min(w, Framebuffer::kMaxSide);
  h = std::min(h, Framebuffer::kMaxSide);
  if (!changing(setterValues_.viewport == std::array<int, 4>{x, y, w, h})) return;
  setterValues_.viewport = {x, y, w, h};
  viewportBox_ = {x, y, saturatingAdd(x, w), saturatingAdd(y, h)};
  // Mesa's viewport: scale = size / 2, translate = origin + size / 2.
  vpScaleX_ = static_cast<float>(w) / 2.0f;
  vpScaleY_ = static_cast<float>(h) / 2.0f;
  vpTransX_ = static_cast<float>(x) + vpScaleX_;
  vpTransY_ = static_cast<float>(y) + vpScaleY_;
}

void GLContext::scissor(int x, int y, int w, int h) {
  if (!checkOutsideBeginEnd()) return;
  if (w < 0 || h < 0) return setError(GL_INVALID_VALUE);
  if (!changing(setterValues_.scissor == std::array<int, 4>{x, y, w, h})) return;
  setterValues_.scissor = {x, y, w, h};
  scissorBox_ = {x, y, saturatingAdd(x, w), saturatingAdd(y, h)};
}

void GLContext::clearColor(float r, float g, float b, float a) {
  if (!checkOutsideBeginEnd()) return;
  clearValues_.color = {floatToUnorm8(clamp01(r)), floatToUnorm8(clamp01(g)), floatToUnorm8(clamp01(b)),
                        floatToUnorm8(clamp01(a))};
}

void GLContext::clearDepth(double d) {
  if (!checkOutsideBeginEnd()) return;
  d = std::isnan(d) ? 0.0 : std::clamp(d, 0.0, 1.0);
  // util_pack_z: round to nearest, 1.0 exactly to the maximum.
  clearValues_.depth = static_cast<std::uint32_t>(std::nearbyint(d * fb().profile().depthMax()));
  // A clear Mesa draws as a quad (clearByQuad) carries the depth as a vertex:
  // st_cb_clear.c clear_with_quad's z = Depth.Clear * 2 - 1 (in double, then
  // a float), cso_set_viewport_dims' z * 0.5 + 0.5, stored as a fragment's
  // depth is (clear_by_quad.gls).
  const float z = static_cast<float>(d * 2.0f - 1.0f);
  quadClearDepth_ = windowDepthToWord(std::fma(z, 0.5f, 0.5f), static_cast<float>(fb().profile().depthMax()));
}

void GLContext::clearStencil(int s) {
  if (!checkOutsideBeginEnd()) return;
  clearValues_.stencil = static_cast<std::uint32_t>(s) & fb().profile().stencilMax();
}

void GLContext::clearAccum(float r, float g, float b, float a) {
  if (!checkOutsideBeginEnd()) return;
  const float v[4] = {r, g, b, a};
  for (int i = 0; i < 4; ++i)
    clearValues_.accum[i] = accumClearWord(std::isnan(v[i]) ? 0.0f : std::clamp(v[i], -1.0f, 1.0f));
}

void GLContext::clear(std::uint32_t mask) {
  if (!checkOutsideBeginEnd()) return;
  constexpr std::uint32_t kAll =
      GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
  if (mask & ~kAll) return setError(GL_INVALID_VALUE);
  // No matrix analysis: _mesa_Clear validates only what a clear reads
  // (measured: a glClear between glMultMatrix and glScalef leaves the
  // modelview to be classified from its entries at the next analysis).
  flushVertices();
  ClearBuffers which;
  which.color = mask & GL_COLOR_BUFFER_BIT;
  which.depth = mask & GL_DEPTH_BUFFER_BIT;
  which.stencil = mask & GL_STENCIL_BUFFER_BIT;
  which.accum = mask & GL_ACCUM_BUFFER_BIT;
  const PixelRect region = scissorEnabled_ ? scissorBox_.intersect(fb().bounds()) : fb().bounds();
  const ClearMasks masks{frag_.colorMask, frag_.depth.writeMask, frag_.stencil.writeMask};
  ClearValues values = clearValues_;
  if (which.depth && clearByQuad(which)) values.depth = quadClearDepth_;
  draw_.forRowBlocks(region, [which, values, masks](Framebuffer& fb, const PixelRect& rows) {
    clearBuffers(fb, rows, which, values, masks);
  });
}

// Whether Mesa's state tracker clears the depth buffer by drawing a quad
// instead of with pipe->clear (st_cb_clear.c st_Clear): a scissor box short
// of the window (llvmpipe has no scissored clear), or a stencil clear under a
// partial write mask, which takes depth along ("always clear depth and
// stencil together"). The other buffers come out the same either way.
bool GLContext::clearByQuad(const ClearBuffers& which) const {
  if (!frag_.depth.writeMask) return false;
  const auto& s = setterValues_.scissor;
  const bool scissorQuad = scissorEnabled_ && (s[0] > 0 || s[1] > 0 || std::int64_t{s[0]} + s[2] < fb().width() ||
                                               std::int64_t{s[1]} + s[3] < fb().height());
  const std::uint32_t stencilMask = frag_.stencil.writeMask & 0xFF;
  const bool stencilQuad = which.stencil && stencilMask != 0 && (scissorQuad || stencilMask != 0xFF);
  return scissorQuad || stencilQuad;
}

void GLContext::colorMask(bool r, bool g, bool b, bool a) {
  if (!checkOutsideBeginEnd()) return;
  if (!changing(frag_.colorMask == std::array<bool, 4>{r, g, b, a})) return;
  frag_.colorMask = {r, g, b, a};
}

void GLContext::depthMask(bool flag) {
  if (!checkOutsideBeginEnd()) return;
  if (!changing(frag_.depth.writeMask == flag)) return;
  frag_.depth.writeMask = flag;
}

void GLContext::stencilMask(std::uint32_t mask) {
  if (!checkOutsideBeginEnd()) return;
  if (!changing(setterValues_.stencilWriteMask == mask)) return;
  setterValues_.stencilWriteMask = mask;
  frag_.stencil.writeMask = mask & fb().profile().stencilMax();
}

// --- per-fragment state ----------------------------------------------------------

void GLContext::setCapability(GLenumValue cap, bool on) {
  if (!checkOutsideBeginEnd()) return;
  bool* flag = nullptr;
  if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + kMaxLights) flag = &lighting_.lights[cap - GL_LIGHT0].enabled;
  else if (cap >= GL_CLIP_PLANE0 && cap < GL_CLIP_PLANE0 + 6) flag = &clipPlaneEnabled_[cap - GL_CLIP_PLANE0];
  else
    switch (cap) {
      case GL_STENCIL_TEST: flag = &frag_.stencil.enabled; break;
      case GL_DEPTH_TEST: flag = &frag_.depth.enabled; break;
      case GL_BLEND: flag = &frag_.blend.enabled; break;
      case GL_ALPHA_TEST: flag = &frag_.alpha.enabled; break;
      case GL_SCISSOR_TEST: flag = &scissorEnabled_; break;
      case GL_CULL_FACE: flag = &cullEnabled_; break;
      case GL_FOG: flag = &fog_.enabled; break;
      case GL_LIGHTING: flag = &lightingEnabled_; break;
      case GL_NORMALIZE: flag = &normalize_; break;
      case GL_DITHER: flag = &ditherEnabled_; break;
      case GL_COLOR_MATERIAL: flag = &colorMaterialEnabled_; break;
    }
  if (!flag) return setError(GL_INVALID_ENUM);
  // _mesa_set_enable: every capability returns early when already so.
  if (!changing(*flag == on)) return;
  if (cap == GL_COLOR_MATERIAL) copyToCurrent();  // FLUSH_CURRENT, before the flag changes
  *flag = on;
  if (cap == GL_COLOR_MATERIAL && on) applyColorMaterial();
  // Enabling a clip plane takes it into clip space by the projection's
  // inverse, analysed first.
  if (cap >= GL_CLIP_PLANE0 && cap < GL_CLIP_PLANE0 + 6 && on) analyseMatrices(false, true);
}

bool GLContext::isEnabled(GLenumValue cap) const {
  if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + kMaxLights) return lighting_.lights[cap - GL_LIGHT0].enabled;
  if (cap >= GL_CLIP_PLANE0 && cap < GL_CLIP_PLANE0 + 6) return clipPlaneEnabled_[cap - GL_CLIP_PLANE0];
  switch (cap) {
    case GL_STENCIL_TEST: return frag_.stencil.enabled;
    case GL_DEPTH_TEST: return frag_.depth.enabled;
    case GL_BLEND: return frag_.blend.enabled;
    case GL_ALPHA_TEST: return frag_.alpha.enabled;
    case GL_SCISSOR_TEST: return scissorEnabled_;
    case GL_CULL_FACE: return cullEnabled_;
    case GL_FOG: return fog_.enabled;
    case GL_LIGHTING: return lightingEnabled_;
    case GL_NORMALIZE: return normalize_;
    case GL_DITHER: return ditherEnabled_;
    case GL_COLOR_MATERIAL: return colorMaterialEnabled_;
  }
  return false;
}

void GLContext::stencilFunc(GLenumValue func, int ref, std::uint32_t mask) {
  if (!checkOutsideBeginEnd()) return;
  const auto f = compareFuncFromGL(func);
  if (!f) return setError(GL_INVALID_ENUM);
  // Mesa compares the raw reference and mask (stencil_func).
  if (!changing(frag_.stencil.func == *f && setterValues_.stencilRef == ref && setterValues_.stencilValueMask == mask))
    return;
  setterValues_.stencilRef = ref;
  setterValues_.stencilValueMask = mask;
  frag_.stencil.func = *f;
  // GL: "ref is clamped to the range [0, 2^s - 1]".
  frag_.stencil.ref = static_cast<std::uint32_t>(std::clamp<int>(ref, 0, fb().profile().stencilMax()));
  frag_.stencil.valueMask = mask & fb().profile().stencilMax();
}

void GLContext::stencilOp(GLenumValue sfail, GLenumValue dpfail, GLenumValue dppass) {
  if (!checkOutsideBeginEnd()) return;
  const auto a = stencilOpFromGL(sfail), b = stencilOpFromGL(dpfail), c = stencilOpFromGL(dppass);
  if (!a || !b || !c) return setError(GL_INVALID_ENUM);
  if (!changing(frag_.stencil.sfail == *a && frag_.stencil.dpfail == *b && frag_.stencil.dppass == *c)) return;
  frag_.stencil.sfail = *a;
  frag_.stencil.dpfail = *b;
  frag_.stencil.dppass = *c;
}

void GLContext::depthFunc(GLenumValue func) {
  if (!checkOutsideBeginEnd()) return;
  const auto f = compareFuncFromGL(func);
  if (!f) return setError(GL_INVALID_ENUM);
  if (!changing(frag_.depth.func == *f)) return;
  frag_.depth.func = *f;
}

void GLContext::depthRange(double n, double f) {
  if (!checkOutsideBeginEnd()) return;
  // Mesa keeps the range in single precision (gl_viewport_attrib), so the
  // window z scale and offset llvmpipe uses come from the float values:
  // measured, a range such as [0.99140067, 0.994552] otherwise moves depths
  // near 1 by a unit (depth_coincident_zfight.gls).
  // Mesa compares the call's values with the stored, clamped ones.
  if (!changing(depthNear_ == n && depthFar_ == f)) return;
  depthNear_ = static_cast<float>(std::isnan(n) ? 0.0 : std::clamp(n, 0.0, 1.0));
  depthFar_ = static_cast<float>(std::isnan(f) ? 0.0 : std::clamp(f, 0.0, 1.0));
}

void GLContext::blendFunc(GLenumValue src, GLenumValue dst) {
  if (!checkOutsideBeginEnd()) return;
  const auto s = blendFactorFromGL(src), d = blendFactorFromGL(dst);
  if (!s || !d) return setError(GL_INVALID_ENUM);
  if (!changing(frag_.blend.src == *s && frag_.blend.dst == *d)) return;
  frag_.blend.src = *s;
  frag_.blend.dst = *d;
}

void GLContext::alphaFunc(GLenumValue func, float ref) {
  if (!checkOutsideBeginEnd()) return;
  const auto f = compareFuncFromGL(func);
  if (!f) return setError(GL_INVALID_ENUM);
  if (!changing(frag_.alpha.func == *f && setterValues_.alphaRef == ref)) return;  // AlphaRefUnclamped
  setterValues_.alphaRef = ref;
  frag_.alpha.func = *f;
  frag_.alpha.ref = std::isnan(ref) ? 0.0f : clamp01(ref);
}

void GLContext::cullFace(GLenumValue mode) {
  if (!checkOutsideBeginEnd()) return;
  if (mode != GL_FRONT && mode != GL_BACK && mode != GL_FRONT_AND_BACK) return setError(GL_INVALID_ENUM);
  if (!changing(cullMode_ == mode)) return;
  cullMode_ = mode;
}

void GLContext::frontFace(GLenumValue mode) {
  if (!checkOutsideBeginEnd()) return;
  if (mode != GL_CW && mode != GL_CCW) return setError(GL_INVALID_ENUM);
  if (!changing(frontFace_ == mode)) return;
  frontFace_ = mode;
}

void GLContext::shadeModel(GLenumValue mode) {
  if (!checkOutsideBeginEnd()) return;
  if (mode != GL_FLAT && mode != GL_SMOOTH) return setError(GL_INVALID_ENUM);
  if (!changing(flatShading_ == (mode == GL_FLAT))) return;
  flatShading_ = mode == GL_FLAT;
}

void GLContext::fogf(GLenumValue pname, float param) {
  if (!checkOutsideBeginEnd()) return;
  switch (pname) {
    case GL_FOG_MODE: {
      // Mesa: (GLenum)(GLint) param, so 9729.5 truncates to GL_LINEAR. A
      // value outside int's range (inf, NaN, 1e30) names no mode (and would
      // be undefined behaviour to convert).
      if (!(param > -2147483648.0f && param < 2147483648.0f)) return setError(GL_INVALID_ENUM);
      const auto m = static_cast<GLenumValue>(static_cast<std::int32_t>(param));
      FogMode mode;
      if (m == GL_LINEAR) mode = FogMode::Linear;
      else if (m == GL_EXP) mode = FogMode::Exp;
      else if (m == GL_EXP2) mode = FogMode::Exp2;
      else return setError(GL_INVALID_ENUM);
      return setIfChanged(fog_.mode, mode);
    }
    case GL_FOG_DENSITY:
      if (param < 0.0f) return setError(GL_INVALID_VALUE);
      return setIfChanged(fog_.density, param);
    case GL_FOG_COLOR:
      if (departures_ & kScalarCallVectorParam) {
        return setIfChanged(fog_.color, Vec4(clamp01(param), 0, 0, 0));
      }
      break;
    case GL_FOG_START: return setIfChanged(fog_.start, param);
    case GL_FOG_END: return setIfChanged(fog_.end, param);
    case GL_FOG_INDEX: return setIfChanged(setterValues_.fogIndex, param);  // colour-index only; Mesa stores it
  }
  setError(GL_INVALID_ENUM);
}

void GLContext::fogfv(GLenumValue pname, const float* p, int count) {
  if (!checkOutsideBeginEnd()) return;
  if (pname == GL_FOG_COLOR) {
    if (count < 4) return setError(GL_INVALID_VALUE);
    // Compared clamped: a colour that clamps to the stored one flushes
    // nothing (measured against llvmpipe).
    return setIfChanged(fog_.color, Vec4(clamp01(p[0]), clamp01(p[1]), clamp01(p[2]), clamp01(p[3])));
  }
  if (count < 1) return setError(GL_INVALID_VALUE);
  fogf(pname, p[0]);
}

void GLContext::hint(GLenumValue target, GLenumValue mode) {
  if (!checkOutsideBeginEnd()) return;
  if (mode != GL_FASTEST && mode != GL_NICEST && mode != GL_DONT_CARE) return setError(GL_INVALID_ENUM);
  std::size_t slot;
  switch (target) {
    case GL_FOG_HINT: slot = 0; break;
    case GL_PERSPECTIVE_CORRECTION_HINT: slot = 1; break;  // this pipeline always interpolates perspective-correctly
    case GL_POINT_SMOOTH_HINT: slot = 2; break;
    case GL_LINE_SMOOTH_HINT: slot = 3; break;
    case GL_POLYGON_SMOOTH_HINT: slot = 4; break;
    default: return setError(GL_INVALID_ENUM);
  }
  if (!changing(setterValues_.hints[slot] == mode)) return;
  setterValues_.hints[slot] = mode;
  // GL_FASTEST: fog per vertex; otherwise per fragment, as Mesa does.
  if (target == GL_FOG_HINT) fog_.perFragment = mode != GL_FASTEST || (departures_ & kFogHintIgnored);
}

// --- accumulation ---------------------------------------------------------------

void GLContext::accum(GLenumValue op, float value) {
  if (!checkOutsideBeginEnd()) return;
  AccumOp a;
  switch (op) {
    case GL_ACCUM: a = AccumOp::Accum; break;
    case GL_LOAD: a = AccumOp::Load; break;
    case GL_RETURN: a = AccumOp::Return; break;
    case GL_MULT: a = AccumOp::Mult; break;
    case GL_ADD: a = AccumOp::Add; break;
    default: return setError(GL_INVALID_ENUM);
  }
  flushVertices();
  analyseMatrices(true, true);  // _mesa_Accum validates the state
  // Accumulation works on the scissored window, like a clear.
  const PixelRect region = scissorEnabled_ ? scissorBox_.intersect(fb().bounds()) : fb().bounds();
  draw_.forRowBlocks(region, [a, value, mask = frag_.colorMask](Framebuffer& fb, const PixelRect& rows) {
    accumulate(fb, rows, a, value, mask);
  });
}

}  // namespace mpr
