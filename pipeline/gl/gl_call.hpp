#pragma once
// The calls of the spec's call set, generated from pipeline/gl_calls.def:
// the GLCall enum, every call in table order, and each call's C name and
// script argument kinds.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace mpr {

enum class GLCall : std::uint8_t {
#define MPR_GL_CALL(Enum, ...) Enum,
#include "pipeline/gl/gl_calls.def"
};

// Every call, in the table's order (for coverage lists and look-ups).
inline constexpr GLCall kGLCalls[] = {
#define MPR_GL_CALL(Enum, ...) GLCall::Enum,
#include "pipeline/gl/gl_calls.def"
};
inline constexpr std::size_t kGLCallCount = sizeof kGLCalls / sizeof kGLCalls[0];

struct GLCallInfo {
  std::string_view name;   // "glStencilFunc"
  std::string_view kinds;  // the script's argument kinds (gl_calls.def)
};

inline constexpr GLCallInfo kGLCallInfo[] = {
#define MPR_GL_CALL(Enum, method, cFunction, kinds, params, args) {#cFunction, kinds},
#include "pipeline/gl/gl_calls.def"
};

constexpr const GLCallInfo& glCallInfo(GLCall c) { return kGLCallInfo[static_cast<std::size_t>(c)]; }
// The C name of a call ("glStencilFunc").
constexpr std::string_view glCallName(GLCall c) { return glCallInfo(c).name; }

// The number of values a ...v call takes for its pname, or 0 for a pname the
// function does not take (GL rejects it; a script may give 1 to 4 values).
int glVectorCount(GLCall call, std::uint32_t pname);

}  // namespace mpr
