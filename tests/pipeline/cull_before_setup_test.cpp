// Culling decided before llvmpipe's set-up (DrawStage::culledBeforeSetUp):
// a back face is dropped exactly where the full path drops it. Culling
// changes neither count of triangles (drawTriangle counts a triangle as
// drawn before its facing test, on the unclipped path and on llvmpipe's
// fans alike), and every fragment belongs to a front or a back face: so
// with culling off, each pixel's count of fragments (the stencil, GL_INCR
// on every one) is the sum of the counts with GL_BACK and with GL_FRONT
// culled, and so is the number of fragments tested. Random triangles of
// every kind the path tells apart: inside the view volume, across it
// (llvmpipe's fans), behind the eye (w < 0), wholly outside, degenerate,
// a hair in front of the eye (w = 1e-7: its window position is so far out
// that the facing test's products would overflow, which the sanitizer
// build makes fatal), cut by a user clip plane, wound either way, with
// either front face.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "framebuffer/profile.hpp"
#include "pipeline/gl/gl_context.hpp"
#include "script/gl_script.hpp"
#include "script/gl_script_runner.hpp"
#include "util/number_text.hpp"

namespace mpr {
namespace {

struct Counted {
  std::vector<std::uint8_t> stencil;
  PipelineCounters counters;
};

Counted run(const std::string& text) {
  const Script script = parseScript(text, "cull.gls");
  GLContext gl(script.width, script.height, mesaProfile());
  runScript(script, gl);
  return {gl.framebuffer().stencilData(), gl.counters()};
}

TEST(CullBeforeSetUp, CullingEachFaceSplitsTheFragmentsOfNoCulling) {
  std::mt19937 random(1994);
  std::uniform_real_distribution<float> inside(-0.9f, 0.9f), across(-2.5f, 2.5f), w(0.2f, 3.0f);
  std::uint64_t frontAndBack = 0, tested = 0;
  for (int trial = 0; trial < 24; ++trial) {
    std::string draw = "glBegin GL_TRIANGLES\n";
    for (int t = 0; t < 70; ++t) {
      const int kind = t % 7;  // 0-1 inside, 2 across, 3 behind, 4 outside, 5 degenerate, 6 near the eye
      float x[3], y[3], z[3], ww[3];
      for (int v = 0; v < 3; ++v) {
        ww[v] = w(random);
        auto& xy = kind == 2 ? across : inside;
        x[v] = xy(random) * ww[v];
        y[v] = xy(random) * ww[v];
        z[v] = inside(random) * ww[v];
        if (kind == 3 && v == 0) ww[v] = -ww[v];
        if (kind == 4) x[v] += 3.0f * ww[v];
        if (kind == 6 && v == 0) ww[v] = 1e-7f;
      }
      if (kind == 5) {
        x[2] = x[0];
        y[2] = y[0];
        z[2] = z[0];
        ww[2] = ww[0];
      }
      for (int v = 0; v < 3; ++v)
        // Each float exactly (std::to_string would write 1e-7 as 0.000000).
        draw += "glVertex4f " + shortestText(x[v]) + " " + shortestText(y[v]) + " " + shortestText(z[v]) + " " +
                shortestText(ww[v]) + "\n";
    }
    draw += "glEnd\n";
    std::string head =
        "@framebuffer 40 32\n@profile mesa\nglClear GL_STENCIL_BUFFER_BIT\nglEnable GL_STENCIL_TEST\n"
        "glStencilFunc GL_ALWAYS 0 255\nglStencilOp GL_KEEP GL_KEEP GL_INCR\n";
    if (trial % 2 == 1) head += "glClipPlane GL_CLIP_PLANE0 1 0.5 0 0.2\nglEnable GL_CLIP_PLANE0\n";
    if (trial % 4 >= 2) head += "glFrontFace GL_CW\n";
    const Counted none = run(head + draw);
    const Counted back = run(head + "glEnable GL_CULL_FACE\nglCullFace GL_BACK\n" + draw);
    const Counted front = run(head + "glEnable GL_CULL_FACE\nglCullFace GL_FRONT\n" + draw);
    const Counted both = run(head + "glEnable GL_CULL_FACE\nglCullFace GL_FRONT_AND_BACK\n" + draw);
    for (const Counted* c : {&back, &front, &both}) {
      EXPECT_EQ(c->counters.triangles, none.counters.triangles) << "trial " << trial;
      EXPECT_EQ(c->counters.trianglesDrawn, none.counters.trianglesDrawn) << "trial " << trial;
    }
    EXPECT_EQ(back.counters.fragmentsTested + front.counters.fragmentsTested, none.counters.fragmentsTested)
        << "trial " << trial;
    EXPECT_EQ(both.counters.fragmentsTested, 0u) << "trial " << trial;
    for (std::size_t i = 0; i < none.stencil.size(); ++i) {
      ASSERT_LT(none.stencil[i], 255) << "trial " << trial;  // no count saturated
      ASSERT_EQ(back.stencil[i] + front.stencil[i], none.stencil[i]) << "trial " << trial << " pixel " << i;
    }
    frontAndBack += back.counters.fragmentsTested > 0 && front.counters.fragmentsTested > 0;
    tested += none.counters.fragmentsTested;
  }
  EXPECT_EQ(frontAndBack, 24u);  // both faces drawn in every trial
  EXPECT_GT(tested, 100000u);
}

}  // namespace
}  // namespace mpr
