#include "algorithms/apply_stencil.hpp"

#include <stdexcept>

#include "algorithms/pass_state.hpp"

namespace mpr {

GLStencilSetting translateStencil(const PaperStencil& s, const StencilLevels& l) {
  if (s.compare == PaperCompare::Equal) {
    if (s.pass == PaperPass::Keep) return {GL_EQUAL, s.compareValue, l.max, l.max, GL_KEEP};
    // INVERT through the mask A ^ B turns A into B and touches nothing else:
    // only pixels holding A pass the test.
    return {GL_EQUAL, s.compareValue, l.max, s.compareValue ^ s.passValue, GL_INVERT};
  }
  if (s.compare == PaperCompare::Greater && s.compareValue == l.shadMin && s.pass == PaperPass::Replace) {
    if (s.passValue == l.zero) return {GL_LESS, l.shadMin, l.max, l.max, GL_ZERO};
    if (s.passValue == l.shadZero)
      return {GL_LEQUAL, l.shadZero, l.shadMin, l.max, GL_REPLACE};
  }
  throw std::logic_error("stencil notation not used by Figure 4: " + paperStencilText(s, l));
}

namespace {

std::string valueName(std::uint32_t v, const StencilLevels& l) {
  if (v == l.shadZero) return "SHAD_ZERO";
  if (v == l.shadMin) return "SHAD_MIN";
  if (v == l.zero) return "ZERO";
  return std::to_string(v);
}

PassState stencilOnly(const GLStencilSetting& g) {
  PassState s;
  s.stencil = StencilSetting{g.func, static_cast<GLint>(g.ref), g.valueMask, g.writeMask, {{GL_KEEP, GL_KEEP, g.zpass}}};
  return s;
}

}  // namespace

std::string paperStencilText(const PaperStencil& s, const StencilLevels& l) {
  return std::string(s.compare == PaperCompare::Equal ? "EQUAL, " : "GREATER, ") + valueName(s.compareValue, l) +
         (s.pass == PaperPass::Keep ? ", KEEP, " : ", REPLACE, ") + valueName(s.passValue, l);
}

void stencil(GLApi& gl, const PaperStencil& s, const StencilLevels& l) {
  applyPassState(gl, stencilOnly(translateStencil(s, l)));
}

void apply_stencil(GLApi& gl, const PaperStencil& s, const StencilLevels& l) {
  apply_to_screen(gl, translateStencil(s, l));
}

void apply_to_screen(GLApi& gl, const GLStencilSetting& g) {
  gl.windowMap(std::nullopt);  // the whole screen, not a refracted view's image
  applyPassState(gl, merged(passes::kScreenStencilOnly, stencilOnly(g)));
  gl.matrixMode(GL_PROJECTION);
  gl.pushMatrix();
  gl.loadIdentity();
  gl.matrixMode(GL_MODELVIEW);
  gl.pushMatrix();
  gl.loadIdentity();
  gl.rectf(-1.0f, -1.0f, 1.0f, 1.0f);
  gl.popMatrix();
  gl.matrixMode(GL_PROJECTION);
  gl.popMatrix();
  gl.matrixMode(GL_MODELVIEW);
  applyPassState(gl, passes::kWritesOn);
}

}  // namespace mpr
