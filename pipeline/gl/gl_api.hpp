#pragma once
// The typed GL API (pbrt-v4's ParserTarget for MPR's call set): one method per
// call of pipeline/gl_calls.def, with the C signature, so arity and argument
// types are checked at compile time; plus MPR's directives, the parts of the
// stream that are not GL calls (docs/gl-script-directives.md).
//
// Implemented by the emulator (GLEmulator), the trace writer (GLTraceWriter),
// the algorithms' tee (GLCommandStream) and the Mesa replayer; a parsed script
// drives any of them through dispatch() (pipeline/gl_dispatch.hpp).
#include <GL/gl.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>

#include "pipeline/gl/gl_call.hpp"
#include "util/vecmath.hpp"

namespace mpr {

class GLApi {
 public:
  virtual ~GLApi() = default;

#define MPR_GL_CALL(Enum, method, cFunction, kinds, params, args) virtual void method params = 0;
#include "pipeline/gl/gl_calls.def"

  // @pass LABEL: a pass boundary (no effect on the buffers).
  virtual void pass(std::string_view label) = 0;
  // @window_map: the end-of-pipeline 3x3 map after the perspective divide
  // (GLContext::setWindowMap; the 1994 paper's wished-for stage), or off.
  virtual void windowMap(const std::optional<glm::mat3>& map) = 0;
  // @count_fragments begin / end: the fragments written between the two (an
  // occlusion query's part); end returns the count (0 where nothing executes).
  virtual void beginFragmentCount() = 0;
  virtual std::uint64_t endFragmentCount() = 0;
};

// The values of a ...fv call, all single precision already: a double would be
// rounded here silently, so it does not compile.
template <class... T>
std::array<GLfloat, sizeof...(T)> glFloats(T... v) {
  static_assert((std::is_same_v<T, GLfloat> && ...), "glFloats takes floats only");
  return {v...};
}

}  // namespace mpr
