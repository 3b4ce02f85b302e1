#include "script/call_set.hpp"

#include <GL/gl.h>

#include <set>
#include <unordered_map>

#include "util/spelling.hpp"

namespace mpr {
namespace {

constexpr CallSpec kCalls[] = {
#define MPR_GL_CALL(Enum, method, cFunction, kinds, params, args) {#cFunction, GLCall::Enum, kinds},
#include "pipeline/gl/gl_calls.def"
};

// Capabilities and modes that GL accepts but the emulated Iris subset does not
// implement: a script using them is outside the call set (a script error),
// not a GL error, since real GL would act on them.
const std::set<std::uint32_t>& unsupportedCapabilities() {
  static const std::set<std::uint32_t> caps = {
      GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R,
      GL_TEXTURE_GEN_Q, GL_LINE_SMOOTH, GL_LINE_STIPPLE, GL_POINT_SMOOTH, GL_POLYGON_SMOOTH,
      GL_POLYGON_STIPPLE, GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT,
      GL_COLOR_LOGIC_OP, GL_INDEX_LOGIC_OP, GL_AUTO_NORMAL, GL_MAP1_VERTEX_3, GL_MAP2_VERTEX_3,
      GL_RESCALE_NORMAL, GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_TEXTURE_3D,
      GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_COLOR_SUM, GL_DEPTH_CLAMP, GL_STENCIL_TEST_TWO_SIDE_EXT,
  };
  return caps;
}

}  // namespace

const CallSpec* findCall(std::string_view name) {
  static const std::unordered_map<std::string_view, const CallSpec*> byName = [] {
    std::unordered_map<std::string_view, const CallSpec*> m;
    for (const CallSpec& c : kCalls) m.emplace(c.name, &c);
    return m;
  }();
  const auto it = byName.find(name);
  return it == byName.end() ? nullptr : it->second;
}



std::string closestCallName(std::string_view name) {
  std::vector<std::string_view> names;
  for (const CallSpec& c : kCalls) names.push_back(c.name);
  return closestMatch(name, names, 4, true);
}

void checkCallSet(const std::string& file, const CallSpec& spec, const ScriptCommand& cmd,
                  const std::vector<ScriptToken>& toks, int line) {
  auto outside = [&](const ScriptArg& a, const std::string& what) {
    // The argument as written: its token (a checking pass keeps no text).
    std::string_view written;
    for (const ScriptToken& t : toks)
      if (t.column == a.column) written = t.text;
    throw ScriptError(file, line, a.column, std::string(written) + " is valid GL but outside the emulated call set (" + what + ")");
  };
  switch (spec.call) {
    case GLCall::Enable:
    case GLCall::Disable:
      if (unsupportedCapabilities().count(cmd.args[0].bits)) outside(cmd.args[0], "see docs/reference/gl-script.md for the capabilities");
      break;
    case GLCall::Begin:
      switch (cmd.args[0].bits) {
        case GL_POINTS: case GL_LINES: case GL_LINE_STRIP: case GL_LINE_LOOP:
          outside(cmd.args[0], "only polygon primitives are emulated");
      }
      break;
    case GLCall::MatrixMode:
      if (cmd.args[0].bits == GL_TEXTURE) outside(cmd.args[0], "no texturing");
      break;
    case GLCall::LightModeli:
    case GLCall::LightModelf:
      if (cmd.args[0].bits == GL_LIGHT_MODEL_COLOR_CONTROL) outside(cmd.args[0], "no separate specular colour");
      break;
    default: break;
  }
}

}  // namespace mpr
