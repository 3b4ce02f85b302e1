// The trace writer prints the typed calls as script lines that parse and
// dispatch back to the same calls; the GL API checks arity at compile time.
#include <gtest/gtest.h>

#include <string>

#include "script/gl_dispatch.hpp"
#include "pipeline/gl/gl_enums.hpp"
#include "script/gl_script.hpp"
#include "script/gl_trace_writer.hpp"

namespace mpr {
namespace {

// A call with too few arguments does not compile (the old runtime path,
// GLCommandStream::call(GLCall, {strings...}), is gone).
template <class A>
concept TakesShortStencilFunc = requires(A a) { a.stencilFunc(GL_EQUAL, 1); };
template <class A>
concept TakesStringCalls = requires(A a) { a.call(GLCall::Disable, {"GL_DITHER"}); };
static_assert(!TakesShortStencilFunc<GLApi>);
static_assert(!TakesStringCalls<GLApi>);
static_assert(!TakesStringCalls<GLTraceWriter>);

std::string replayed(const std::string& text) {
  const Script s = parseScript(text, "trace.gls");
  GLTraceWriter again;
  for (const ScriptCommand& c : s.commands) dispatch(again, c);
  return again.text();
}

TEST(GLTraceWriter, WritesScriptLines) {
  GLTraceWriter w;
  w.stencilFunc(GL_EQUAL, 3, 0xFF);
  w.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  w.colorMask(GL_FALSE, GL_FALSE, GL_TRUE, GL_TRUE);
  w.blendFunc(GL_ONE, GL_ZERO);
  w.stencilOp(GL_KEEP, GL_ZERO, GL_INVERT);
  w.fogi(GL_FOG_MODE, GL_LINEAR);
  w.fogi(GL_FOG_START, 5);
  w.begin(GL_POINTS);
  w.enable(GL_LIGHT0);
  w.accum(GL_ACCUM, 0.5f);
  const GLfloat pos[4] = {1.0f, 0.1f, -2.5f, 1.0f};
  w.lightfv(GL_LIGHT1, GL_POSITION, pos);
  const GLdouble eq[4] = {0.0, 1.0, 0.0, 0.1};
  w.clipPlane(GL_CLIP_PLANE0, eq);
  w.clearDepth(1.0);
  w.vertex3f(0.1f, 1e-30f, 3.0f);
  EXPECT_EQ(w.text(),
            "glStencilFunc GL_EQUAL 3 255\n"
            "glClear GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT|GL_STENCIL_BUFFER_BIT\n"
            "glColorMask GL_FALSE GL_FALSE GL_TRUE GL_TRUE\n"
            "glBlendFunc GL_ONE GL_ZERO\n"
            "glStencilOp GL_KEEP GL_ZERO GL_INVERT\n"
            "glFogi GL_FOG_MODE GL_LINEAR\n"
            "glFogi GL_FOG_START 5\n"
            "glBegin GL_POINTS\n"
            "glEnable GL_LIGHT0\n"
            "glAccum GL_ACCUM 0.5\n"
            "glLightfv GL_LIGHT1 GL_POSITION 1 0.1 -2.5 1\n"
            "glClipPlane GL_CLIP_PLANE0 0 1 0 0.1\n"
            "glClearDepth 1\n"
            "glVertex3f 0.1 1e-30 3\n");
}

TEST(GLTraceWriter, TextDispatchesBackToTheSameCalls) {
  GLTraceWriter w;
  w.clear(GL_ACCUM_BUFFER_BIT);
  const GLfloat m[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 0.3f};
  w.multMatrixf(m);
  const GLdouble md[16] = {0.1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 1.0 / 3.0};
  w.multMatrixd(md);
  w.lookAt(0.1, 0.2, 0.3, 1, 2, 3, 0, 1, 0);
  w.color4ub(1, 2, 250, 255);
  w.pass("a pass | with text");
  w.windowMap(glm::mat3(1.5f));
  w.windowMap(std::nullopt);
  w.beginFragmentCount();
  w.endFragmentCount();
  EXPECT_EQ(replayed(w.text()), w.text());
}

TEST(GLTraceWriter, EveryNamedEnumReadsBack) {
  for (std::uint32_t v = 0; v < 0x10000; ++v)
    if (const auto name = glEnumName(v)) {
      EXPECT_EQ(glEnumValue(*name), v) << *name;
    }
  for (std::uint32_t mode = 0; mode < 10; ++mode) EXPECT_EQ(glEnumValue(*glPrimitiveName(mode)), mode);
}

TEST(GLTraceWriter, DirectiveErrorsAreLocated) {
  EXPECT_THROW(parseScript("@count_fragments end\n", "x.gls"), ScriptError);
  EXPECT_THROW(parseScript("@count_fragments begin\n@count_fragments begin\n", "x.gls"), ScriptError);
  EXPECT_THROW(parseScript("@window_map 1 2 3\n", "x.gls"), ScriptError);
}

}  // namespace
}  // namespace mpr
