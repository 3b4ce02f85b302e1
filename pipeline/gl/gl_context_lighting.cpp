// GLContext: lights, light model, materials, colour material, current colour
// and normal.
#include <GL/gl.h>

#include <algorithm>

#include "pipeline/gl/gl_context.hpp"
#include "pipeline/draw/mesa_matrix_inverse.hpp"

namespace mpr {
namespace {
Vec4 vec4From(const float* p) { return Vec4(p[0], p[1], p[2], p[3]); }
// A material's colour parameters in vbo_Materialfv's attribute order
// (emission, ambient, diffuse, specular; shininess is the fifth,
// kShininessSlot): a
// parameter's index is its offset among a side's vbo material slots.
constexpr Vec4 Material::*kMaterialColours[4] = {&Material::emission, &Material::ambient, &Material::diffuse,
                                                 &Material::specular};

int expectedCount(GLenumValue pname) {
  switch (pname) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_POSITION: case GL_EMISSION:
    case GL_AMBIENT_AND_DIFFUSE: case GL_LIGHT_MODEL_AMBIENT:
      return 4;
    case GL_SPOT_DIRECTION: case GL_COLOR_INDEXES:
      return 3;
    default:
      return 1;
  }
}
}  // namespace

void GLContext::lightf(GLenumValue light, GLenumValue pname, float param) {
  if (expectedCount(pname) != 1 && (departures_ & kScalarCallVectorParam)) {
    const float v[4] = {param, 0, 0, 0};
    return lightfv(light, pname, v, 4);
  }
  if (expectedCount(pname) != 1) {
    // glLightf only takes the scalar parameters.
    if (!checkOutsideBeginEnd()) return;
    return setError(GL_INVALID_ENUM);
  }
  const float p[4] = {param, 0, 0, 0};
  lightfv(light, pname, p, 1);
}

void GLContext::lightfv(GLenumValue light, GLenumValue pname, const float* p, int count) {
  if (!checkOutsideBeginEnd()) return;
  if (light < GL_LIGHT0 || light >= GL_LIGHT0 + kMaxLights) return setError(GL_INVALID_ENUM);
  if (count < expectedCount(pname)) return setError(GL_INVALID_VALUE);
  LightSource& l = lighting_.lights[light - GL_LIGHT0];
  const Mat4& mv = modelview_.top();
  // _mesa_light compares the value (positions and directions once in eye
  // space) with the stored one and flushes only on a change.
  switch (pname) {
    case GL_AMBIENT: return setIfChanged(l.ambient, vec4From(p));
    case GL_DIFFUSE: return setIfChanged(l.diffuse, vec4From(p));
    case GL_SPECULAR: return setIfChanged(l.specular, vec4From(p));
    case GL_POSITION: {
      // Eye space at specification (TRANSFORM_POINT).
      return setIfChanged(l.position, mesaTransformPoint(mv, vec4From(p)));
    }
    case GL_SPOT_DIRECTION:
      analyseMatrices(true, false);  // _mesa_Lightfv analyses the modelview first
      return setIfChanged(l.spotDirection, glm::mat3(mv) * Vec3(p[0], p[1], p[2]));
    case GL_SPOT_EXPONENT:
      if (p[0] < 0.0f || p[0] > 128.0f) return setError(GL_INVALID_VALUE);
      return setIfChanged(l.spotExponent, p[0]);
    case GL_SPOT_CUTOFF:
      if ((p[0] < 0.0f || p[0] > 90.0f) && p[0] != 180.0f) return setError(GL_INVALID_VALUE);
      return setIfChanged(l.spotCutoff, p[0]);
    case GL_CONSTANT_ATTENUATION:
    case GL_LINEAR_ATTENUATION:
    case GL_QUADRATIC_ATTENUATION:
      if (p[0] < 0.0f) return setError(GL_INVALID_VALUE);
      return setIfChanged(pname == GL_CONSTANT_ATTENUATION ? l.constantAttenuation
                          : pname == GL_LINEAR_ATTENUATION ? l.linearAttenuation
                                                           : l.quadraticAttenuation,
                          p[0]);
  }
  setError(GL_INVALID_ENUM);
}

void GLContext::lightModelf(GLenumValue pname, float param) {
  if (pname == GL_LIGHT_MODEL_AMBIENT && (departures_ & kScalarCallVectorParam)) {
    const float v[4] = {param, 0, 0, 0};
    return lightModelfv(pname, v, 4);
  }
  if (pname == GL_LIGHT_MODEL_AMBIENT) {
    if (!checkOutsideBeginEnd()) return;
    return setError(GL_INVALID_ENUM);
  }
  const float p[4] = {param, 0, 0, 0};
  lightModelfv(pname, p, 1);
}

void GLContext::lightModelfv(GLenumValue pname, const float* p, int count) {
  if (!checkOutsideBeginEnd()) return;
  if (count < expectedCount(pname)) return setError(GL_INVALID_VALUE);
  switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT: return setIfChanged(lighting_.model.ambient, vec4From(p));
    case GL_LIGHT_MODEL_LOCAL_VIEWER: return setIfChanged(lighting_.model.localViewer, p[0] != 0.0f);
    case GL_LIGHT_MODEL_TWO_SIDE: return setIfChanged(lighting_.model.twoSide, p[0] != 0.0f);
  }
  setError(GL_INVALID_ENUM);
}

void GLContext::materialf(GLenumValue face, GLenumValue pname, float param) {
  if (pname != GL_SHININESS && expectedCount(pname) == 4 && (departures_ & kScalarCallVectorParam)) {
    const float v[4] = {param, 0, 0, 0};
    return materialfv(face, pname, v, 4);
  }
  if (pname != GL_SHININESS) {
    if (!checkOutsideBeginEnd()) return;  // (materials are legal inside glBegin)
    return setError(GL_INVALID_ENUM);
  }
  const float p[4] = {param, 0, 0, 0};
  materialfv(face, pname, p, 1);
}

void GLContext::materialfv(GLenumValue face, GLenumValue pname, const float* p, int count) {
  // glMaterial is one of the calls GL allows between glBegin and glEnd.
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) return setError(GL_INVALID_ENUM);
  if (count < expectedCount(pname)) return setError(GL_INVALID_VALUE);
  if (pname == GL_SHININESS && (p[0] < 0.0f || p[0] > 128.0f)) return setError(GL_INVALID_VALUE);
  switch (pname) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_EMISSION: case GL_AMBIENT_AND_DIFFUSE:
    case GL_SHININESS: case GL_COLOR_INDEXES: break;
    default: return setError(GL_INVALID_ENUM);
  }
  for (int side = 0; side < 2; ++side) {
    if ((side == 0 && face == GL_BACK) || (side == 1 && face == GL_FRONT)) continue;
    // A parameter that tracks the current colour tracks it "at all times"
    // (glColorMaterial): a glMaterial of it is without effect while
    // GL_COLOR_MATERIAL is enabled, as Mesa's vbo_Materialfv skips it
    // (_ColorMaterialBitmask); GL 1.1 section 2.13.3 does not say otherwise.
    const bool sideTracked = colorMaterialEnabled_ && !settingTrackedMaterial_ &&
                             !((side == 0 && colorMaterialFace_ == GL_BACK) ||
                               (side == 1 && colorMaterialFace_ == GL_FRONT));
    auto tracked = [&](GLenumValue parameter) {
      return sideTracked && (colorMaterialMode_ == parameter ||
                             (colorMaterialMode_ == GL_AMBIENT_AND_DIFFUSE &&
                              (parameter == GL_AMBIENT || parameter == GL_DIFFUSE)));
    };
    Material& m = lighting_.material[side];
    const Vec4 v = pname == GL_SHININESS || pname == GL_COLOR_INDEXES ? Vec4(0.0f) : vec4From(p);
    // Each material parameter the call sets is a vbo attribute (MAT_ATTR),
    // in vbo_Materialfv's order: emission, ambient, diffuse, specular,
    // shininess.
    Material& held = vboMaterial_[static_cast<std::size_t>(side)];
    auto set = [&](int property, GLenumValue parameter) {
      if (tracked(parameter)) return;
      Vec4 Material::*field = kMaterialColours[property];
      if (!settingTrackedMaterial_) {
        vboAttribute(kVboMaterial + side * 5 + property, 4);
        held.*field = v;
      }
      m.*field = v;
    };
    if (pname == GL_EMISSION) set(0, GL_EMISSION);
    if (pname == GL_AMBIENT || pname == GL_AMBIENT_AND_DIFFUSE) set(1, GL_AMBIENT);
    if (pname == GL_DIFFUSE || pname == GL_AMBIENT_AND_DIFFUSE) set(2, GL_DIFFUSE);
    if (pname == GL_SPECULAR) set(3, GL_SPECULAR);
    if (pname == GL_SHININESS) {
      vboAttribute(kVboMaterial + side * 5 + kShininessSlot, 1);
      m.shininess = held.shininess = p[0];
    }
  }
  // Inside glBegin/glEnd the change applies to the vertices that follow
  // (GL 1.1 section 2.6.3): the block keeps each set of materials a vertex
  // was given with.
  if (inBegin_) {
    if (blockMaterialUsed_) blockMaterials_.push_back(lighting_.material);
    else blockMaterials_.back() = lighting_.material;
    blockMaterialUsed_ = false;
  }
}

void GLContext::colorMaterial(GLenumValue face, GLenumValue mode) {
  if (!checkOutsideBeginEnd()) return;
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) return setError(GL_INVALID_ENUM);
  if (mode != GL_EMISSION && mode != GL_AMBIENT && mode != GL_DIFFUSE && mode != GL_SPECULAR &&
      mode != GL_AMBIENT_AND_DIFFUSE)
    return setError(GL_INVALID_ENUM);
  if (!changing(colorMaterialFace_ == face && colorMaterialMode_ == mode)) return;
  colorMaterialFace_ = face;
  colorMaterialMode_ = mode;
  if (colorMaterialEnabled_) {
    copyToCurrent();  // FLUSH_CURRENT, then the tracked parameter from the current colour
    applyColorMaterial();
  }
}

void GLContext::copyToCurrent() {
  // vbo_exec_copy_to_current: each attribute the vbo holds is copied to
  // GL's current values where it differs from them. A glMaterial outside
  // glBegin/glEnd is such an attribute: enabling GL_COLOR_MATERIAL sets the
  // tracked parameter from the colour, and the next copy (a glBegin, a
  // flush) puts the glMaterial's value back. The tracked parameter follows
  // the colour again only where the copied colour changed.
  for (std::size_t side = 0; side < 2; ++side) {
    Material& m = lighting_.material[side];
    const Material& held = vboMaterial_[side];
    const std::size_t base = kVboMaterial + side * 5;
    for (std::size_t property = 0; property < 4; ++property)
      if (vboSize_[base + property]) m.*kMaterialColours[property] = held.*kMaterialColours[property];
    if (vboSize_[base + kShininessSlot]) m.shininess = held.shininess;
  }
  if (vboSize_[kVboColor] && currentColor_ != copiedColor_) {
    copiedColor_ = currentColor_;
    if (colorMaterialEnabled_) applyColorMaterial();
  }
}

void GLContext::copyAndResetFormat() {
  copyToCurrent();
  vboSize_.fill(0);
}

void GLContext::applyColorMaterial() {
  // While GL_COLOR_MATERIAL is enabled the selected material parameter tracks
  // the current colour (GL 1.1 section 2.13.3).
  const float c[4] = {currentColor_.r, currentColor_.g, currentColor_.b, currentColor_.a};
  const bool wasInBegin = inBegin_;
  settingTrackedMaterial_ = true;
  materialfv(colorMaterialFace_, colorMaterialMode_, c, 4);
  settingTrackedMaterial_ = false;
  inBegin_ = wasInBegin;
}

void GLContext::color3f(float r, float g, float b) {
  vboAttribute(kVboColor, 3);
  setCurrentColor(Vec4(r, g, b, (departures_ & kColor3KeepsAlpha) ? currentColor_.a : 1.0f));
}

void GLContext::color4f(float r, float g, float b, float a) {
  vboAttribute(kVboColor, 4);
  setCurrentColor(Vec4(r, g, b, a));
}

void GLContext::setCurrentColor(const Vec4& c) {
  currentColor_ = c;
  if (colorMaterialEnabled_) applyColorMaterial();
}

void GLContext::color4ub(std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a) {
  color4f(r / 255.0f, g / 255.0f, b / 255.0f, a / 255.0f);
}

void GLContext::normal3f(float x, float y, float z) {
  vboAttribute(kVboNormal, 3);
  currentNormal_ = Vec3(x, y, z);
}

}  // namespace mpr
