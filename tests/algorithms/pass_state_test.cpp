// Pass states are values: a named state is always the same calls, and a
// difference against the current state sets only what changed.
#include <gtest/gtest.h>

#include "algorithms/pass_state.hpp"
#include "script/gl_trace_writer.hpp"

namespace mpr {
namespace {

std::string callsOf(const PassState& s) {
  GLTraceWriter w;
  applyPassState(w, s);
  return w.text();
}

TEST(PassState, ScreenStencilOnlyIsApplyStencilsState) {
  const PassState s =
      withStencil(passes::kScreenStencilOnly, {GL_EQUAL, 3, 0xFF, 0x05, {{GL_KEEP, GL_KEEP, GL_INVERT}}});
  EXPECT_EQ(callsOf(s),
            "glStencilFunc GL_EQUAL 3 255\nglStencilMask 5\nglStencilOp GL_KEEP GL_KEEP GL_INVERT\n"
            "glColorMask GL_FALSE GL_FALSE GL_FALSE GL_FALSE\nglDepthMask GL_FALSE\nglDisable GL_DEPTH_TEST\n"
            "glDisable GL_LIGHTING\nglDisable GL_FOG\nglDisable GL_CULL_FACE\nglDisable GL_CLIP_PLANE0\n");
}

TEST(PassState, VolumeCountLeavesTheStencilOpsToTheCaller) {
  const PassState s = withStencil(passes::kVolumeCount, {GL_LEQUAL, 128, 128, 255, std::nullopt});
  EXPECT_EQ(callsOf(s),
            "glStencilFunc GL_LEQUAL 128 128\nglStencilMask 255\nglColorMask GL_FALSE GL_FALSE GL_FALSE GL_FALSE\n"
            "glDepthMask GL_FALSE\nglEnable GL_DEPTH_TEST\nglDepthFunc GL_LESS\nglDisable GL_LIGHTING\n"
            "glDisable GL_BLEND\nglEnable GL_CULL_FACE\n");
}

TEST(PassState, DifferenceSetsOnlyWhatChanged) {
  PassState current;
  GLTraceWriter w;
  applyPassStateDifference(w, passes::kVolumeCount, current);
  EXPECT_EQ(w.text(), callsOf(passes::kVolumeCount));  // nothing known: everything set
  EXPECT_EQ(current, passes::kVolumeCount);
  GLTraceWriter again;
  applyPassStateDifference(again, passes::kVolumeCount, current);
  EXPECT_EQ(again.text(), "");
  GLTraceWriter writes;
  applyPassStateDifference(writes, passes::kWritesOn, current);
  EXPECT_EQ(writes.text(), "glColorMask GL_TRUE GL_TRUE GL_TRUE GL_TRUE\nglDepthMask GL_TRUE\n");
  EXPECT_EQ(current, merged(passes::kVolumeCount, passes::kWritesOn));
}

}  // namespace
}  // namespace mpr
