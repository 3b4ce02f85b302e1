// Fragment throughput of the emulated pipeline, reported as fragments per
// second (items_per_second): the stencil-only path the multi-pass algorithms
// lean on (apply_stencil, shadow volumes), apply_stencil's blended full-screen
// rectangle and the lit, depth-tested path of an ordinary rendering pass.
#include <GL/gl.h>
#include <benchmark/benchmark.h>

#include "pipeline/gl/gl_context.hpp"

namespace {

constexpr int kSize = 512;

mpr::GLContext makeContext() {
  mpr::GLContext gl(kSize, kSize, mpr::indigoProfile());
  gl.matrixMode(GL_PROJECTION);
  gl.ortho(0, kSize, 0, kSize, -1, 1);
  gl.matrixMode(GL_MODELVIEW);
  return gl;
}

void BM_StencilOnlyFill(benchmark::State& state) {
  mpr::GLContext gl = makeContext();
  gl.colorMask(false, false, false, false);
  gl.depthMask(false);
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_ALWAYS, 0, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_INCR_WRAP);
  for (auto _ : state) {
    gl.rectf(0, 0, kSize, kSize);
    benchmark::DoNotOptimize(gl.stencilAt(1, 1));
  }
  state.SetItemsProcessed(static_cast<int64_t>(gl.counters().fragmentsTested));
}
BENCHMARK(BM_StencilOnlyFill)->Unit(benchmark::kMillisecond);

// The 1997 paper's apply_stencil as bench/table1_workload writes it: a
// flat rectangle over the window, stencil GL_EQUAL 0 and GL_ZERO where it
// passes (so it stays 0 and every fragment passes), added to the colour
// (GL_ONE, GL_ONE).
void BM_BlendedStencilFill(benchmark::State& state) {
  mpr::GLContext gl = makeContext();
  gl.enable(GL_STENCIL_TEST);
  gl.stencilFunc(GL_EQUAL, 0, 0xFF);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_ZERO);
  gl.enable(GL_BLEND);
  gl.blendFunc(GL_ONE, GL_ONE);
  gl.color4f(0.05f, 0.2f, 0.22f, 1.0f);
  for (auto _ : state) {
    gl.rectf(0, 0, kSize, kSize);
    benchmark::DoNotOptimize(gl.colorAt(1, 1));
  }
  state.SetItemsProcessed(static_cast<int64_t>(gl.counters().fragmentsWritten));
}
BENCHMARK(BM_BlendedStencilFill)->Unit(benchmark::kMillisecond);

void BM_LitDepthTestedFill(benchmark::State& state) {
  mpr::GLContext gl = makeContext();
  gl.enable(GL_DEPTH_TEST);
  gl.depthFunc(GL_LEQUAL);
  gl.enable(GL_LIGHTING);
  gl.enable(GL_LIGHT0);
  const float pos[4] = {100, 300, 200, 1};
  gl.lightfv(GL_LIGHT0, GL_POSITION, pos, 4);
  gl.enable(GL_COLOR_MATERIAL);
  gl.color4f(0.8f, 0.5f, 0.3f, 1.0f);
  for (auto _ : state) {
    gl.begin(GL_TRIANGLE_STRIP);  // a tessellated lit sheet across the window
    for (int i = 0; i <= 16; ++i) {
      const float x = static_cast<float>(i) * kSize / 16.0f;
      gl.normal3f(0.3f, 0.2f, 1.0f);
      gl.vertex4f(x, 0, 0.1f, 1);
      gl.normal3f(-0.2f, 0.3f, 1.0f);
      gl.vertex4f(x, kSize, 0.1f, 1);
    }
    gl.end();
    benchmark::DoNotOptimize(gl.colorAt(1, 1));
  }
  state.SetItemsProcessed(static_cast<int64_t>(gl.counters().fragmentsTested));
}
BENCHMARK(BM_LitDepthTestedFill)->Unit(benchmark::kMillisecond);

}  // namespace
