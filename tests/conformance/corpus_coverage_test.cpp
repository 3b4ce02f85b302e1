// The conformance corpus exercises every call of the spec's call set and
// every enumerant those calls take in the emulated subset.
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "script/gl_script.hpp"

#ifndef MPR_SOURCE_DIR
#error "MPR_SOURCE_DIR must point at the source tree"
#endif

namespace mpr {
namespace {

struct Corpus {
  std::set<GLCall> calls;
  std::set<std::uint32_t> enums;  // every enumerant argument seen
};

Corpus loadCorpus() {
  Corpus c;
  const std::filesystem::path dir = std::filesystem::path(MPR_SOURCE_DIR) / "tests" / "conformance";
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".gls") continue;
    const Script s = loadScript(entry.path().string());
    std::vector<std::string_view> lines;  // the text's lines, the first at [0]
    for (std::string_view rest = s.text;;) {
      const std::size_t end = rest.find('\n');
      lines.push_back(rest.substr(0, end));
      if (end == std::string_view::npos) break;
      rest.remove_prefix(end + 1);
    }
    for (const ScriptCommand& cmd : s.commands) {
      if (cmd.kind != ScriptCommand::Kind::Call) continue;
      c.calls.insert(cmd.call);
      // An argument written as a GL_ name (lines and columns count from 1).
      const std::string_view line = lines.at(static_cast<std::size_t>(cmd.line - 1));
      for (const ScriptArg& a : cmd.args)
        if (line.substr(static_cast<std::size_t>(a.column - 1)).starts_with("GL_")) c.enums.insert(a.bits);
    }
  }
  return c;
}

TEST(ConformanceCorpus, CoversEveryCall) {
  const Corpus c = loadCorpus();
  // Every call of the generated table (pipeline/gl_calls.def), so a call
  // added to the table is covered or this test fails.
  for (const GLCall call : kGLCalls) {
    EXPECT_TRUE(c.calls.count(call)) << glCallName(call) << " is not exercised by tests/conformance";
  }
}

TEST(ConformanceCorpus, CoversEveryEnumOfTheSubset) {
  const Corpus c = loadCorpus();
  const std::uint32_t required[] = {
      GL_STENCIL_TEST, GL_DEPTH_TEST, GL_BLEND, GL_ALPHA_TEST, GL_SCISSOR_TEST, GL_CULL_FACE, GL_FOG,
      GL_LIGHTING, GL_LIGHT0, GL_LIGHT1, GL_CLIP_PLANE0, GL_CLIP_PLANE1, GL_NORMALIZE, GL_COLOR_MATERIAL,
      GL_DITHER, GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS,
      GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP, GL_ONE,
      GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR, GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA,
      GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_SRC_ALPHA_SATURATE, GL_FRONT, GL_BACK,
      GL_FRONT_AND_BACK, GL_CW, GL_CCW, GL_FLAT, GL_SMOOTH, GL_LINEAR, GL_EXP, GL_EXP2, GL_FOG_MODE,
      GL_FOG_DENSITY, GL_FOG_START, GL_FOG_END, GL_FOG_COLOR, GL_FOG_HINT, GL_FASTEST, GL_NICEST,
      GL_MODELVIEW, GL_PROJECTION, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION, GL_SPOT_DIRECTION,
      GL_SPOT_EXPONENT, GL_SPOT_CUTOFF, GL_LINEAR_ATTENUATION, GL_LIGHT_MODEL_AMBIENT,
      GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE, GL_SHININESS, GL_AMBIENT_AND_DIFFUSE,
      GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON, GL_ACCUM,
      GL_LOAD, GL_RETURN, GL_MULT, GL_ADD, GL_COLOR_BUFFER_BIT, GL_DEPTH_BUFFER_BIT, GL_STENCIL_BUFFER_BIT,
      GL_ACCUM_BUFFER_BIT, GL_TRUE, GL_FALSE, GL_EMISSION, GL_CONSTANT_ATTENUATION, GL_QUADRATIC_ATTENUATION,
  };
  for (std::uint32_t e : required) EXPECT_TRUE(c.enums.count(e)) << "enumerant 0x" << std::hex << e << " unused";
}

}  // namespace
}  // namespace mpr
