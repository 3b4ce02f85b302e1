#include "stepper/gl_state_json.hpp"

#include <GL/gl.h>

#include <sstream>

namespace mpr {

std::string_view compareFuncName(CompareFunc f) {
  static constexpr std::string_view names[] = {"GL_NEVER", "GL_LESS", "GL_EQUAL", "GL_LEQUAL",
                                               "GL_GREATER", "GL_NOTEQUAL", "GL_GEQUAL", "GL_ALWAYS"};
  return names[static_cast<int>(f)];
}

std::string_view stencilOpName(StencilOp op) {
  static constexpr std::string_view names[] = {"GL_KEEP", "GL_ZERO", "GL_REPLACE", "GL_INCR",
                                               "GL_DECR", "GL_INVERT", "GL_INCR_WRAP", "GL_DECR_WRAP"};
  return names[static_cast<int>(op)];
}

std::string_view blendFactorName(BlendFactor f) {
  static constexpr std::string_view names[] = {
      "GL_ZERO", "GL_ONE", "GL_SRC_COLOR", "GL_ONE_MINUS_SRC_COLOR", "GL_DST_COLOR", "GL_ONE_MINUS_DST_COLOR",
      "GL_SRC_ALPHA", "GL_ONE_MINUS_SRC_ALPHA", "GL_DST_ALPHA", "GL_ONE_MINUS_DST_ALPHA", "GL_SRC_ALPHA_SATURATE"};
  return names[static_cast<int>(f)];
}

namespace {

std::string_view faceName(GLenumValue v) {
  switch (v) {
    case GL_FRONT: return "GL_FRONT";
    case GL_BACK: return "GL_BACK";
    case GL_FRONT_AND_BACK: return "GL_FRONT_AND_BACK";
    case GL_CW: return "GL_CW";
    case GL_CCW: return "GL_CCW";
  }
  return "?";
}

const char* b(bool v) { return v ? "true" : "false"; }

void matrix(std::ostringstream& o, const Mat4& m) {
  o << "[";
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) o << (c || r ? ", " : "") << m[c][r];
  o << "]";
}

}  // namespace

std::string glStateJson(const GLContext& gl) {
  const FragmentState& f = gl.fragmentState();
  const FogState& fog = gl.fogState();
  const PixelRect vp = gl.viewportBox(), sc = gl.scissorBox();
  std::ostringstream o;
  o << "{\n";
  o << "  \"viewport\": [" << vp.x0 << ", " << vp.y0 << ", " << vp.x1 - vp.x0 << ", " << vp.y1 - vp.y0 << "],\n";
  o << "  \"scissor\": {\"enabled\": " << b(gl.scissorEnabled()) << ", \"box\": [" << sc.x0 << ", " << sc.y0 << ", "
    << sc.x1 - sc.x0 << ", " << sc.y1 - sc.y0 << "]},\n";
  o << "  \"alpha_test\": {\"enabled\": " << b(f.alpha.enabled) << ", \"func\": \"" << compareFuncName(f.alpha.func)
    << "\", \"ref\": " << f.alpha.ref << "},\n";
  o << "  \"stencil\": {\"enabled\": " << b(f.stencil.enabled) << ", \"func\": \"" << compareFuncName(f.stencil.func)
    << "\", \"ref\": " << f.stencil.ref << ", \"value_mask\": " << f.stencil.valueMask
    << ", \"write_mask\": " << f.stencil.writeMask << ", \"sfail\": \"" << stencilOpName(f.stencil.sfail)
    << "\", \"dpfail\": \"" << stencilOpName(f.stencil.dpfail) << "\", \"dppass\": \"" << stencilOpName(f.stencil.dppass)
    << "\"},\n";
  const auto range = gl.depthRangeValues();
  o << "  \"depth\": {\"enabled\": " << b(f.depth.enabled) << ", \"func\": \"" << compareFuncName(f.depth.func)
    << "\", \"write_mask\": " << b(f.depth.writeMask) << ", \"range\": [" << range[0] << ", " << range[1] << "]},\n";
  o << "  \"blend\": {\"enabled\": " << b(f.blend.enabled) << ", \"src\": \"" << blendFactorName(f.blend.src)
    << "\", \"dst\": \"" << blendFactorName(f.blend.dst) << "\"},\n";
  o << "  \"color_mask\": [" << b(f.colorMask[0]) << ", " << b(f.colorMask[1]) << ", " << b(f.colorMask[2]) << ", "
    << b(f.colorMask[3]) << "],\n";
  o << "  \"cull_face\": {\"enabled\": " << b(gl.isEnabled(GL_CULL_FACE)) << ", \"mode\": \""
    << faceName(gl.cullFaceMode()) << "\", \"front_face\": \"" << faceName(gl.frontFaceMode()) << "\"},\n";
  o << "  \"shade_model\": \"" << (gl.flatShading() ? "GL_FLAT" : "GL_SMOOTH") << "\",\n";
  o << "  \"lighting\": " << b(gl.isEnabled(GL_LIGHTING)) << ",\n";
  static constexpr const char* fogModes[] = {"GL_LINEAR", "GL_EXP", "GL_EXP2"};
  o << "  \"fog\": {\"enabled\": " << b(fog.enabled) << ", \"mode\": \"" << fogModes[static_cast<int>(fog.mode)]
    << "\", \"density\": " << fog.density << ", \"start\": " << fog.start << ", \"end\": " << fog.end
    << ", \"per_fragment\": " << b(fog.perFragment) << "},\n";
  o << "  \"clip_planes\": [";
  for (int i = 0; i < 6; ++i) o << (i ? ", " : "") << b(gl.isEnabled(GL_CLIP_PLANE0 + i));
  o << "],\n  \"modelview\": ";
  matrix(o, gl.modelview());
  o << ",\n  \"projection\": ";
  matrix(o, gl.projection());
  o << "\n}\n";
  return o.str();
}

}  // namespace mpr
