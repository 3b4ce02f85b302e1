#pragma once
// The per-fragment operations specialised from the state once per draw, as
// softpipe's choose_depth_test (sp_quad_depth_test.c) installs a function
// for the current depth and stencil state: the tests and writes a state
// disables are compiled out, so a stencil-only pass (colour writes off) does
// no colour work. Every variant does exactly what processFragment does.
#include "framebuffer/fragment_ops.hpp"

namespace mpr {

using FragmentFunction = FragmentFate (*)(const FragmentState& s, Framebuffer& fb, const Fragment& f);

// Up to kCapacity fragments of one row at consecutive x (x, x + 1, ...), as
// arrays: the rasterizer fills a span, the pipeline runs it in one call.
// Every lane is defined, also those past count (zero, or a previous span's
// values): the span functions compute over whole vectors of lanes and
// count and write only the first `count`.
struct FragmentSpan {
  static constexpr int kCapacity = 64;
  int x = 0, y = 0, count = 0;
  std::array<std::uint32_t, kCapacity> depth{};
  std::array<Rgba8, kCapacity> color{};
  std::array<float, kCapacity> alpha{};
};

// The lanes the span loops run over for a span of `count`: the count rounded
// up to whole vectors of 8 (a short span would otherwise end each loop in a
// scalar remainder), never past the capacity.
constexpr int paddedLanes(int count) { return (count + 7) & ~7; }
static_assert(FragmentSpan::kCapacity % 8 == 0);

// Runs the span's fragments in order, exactly as the FragmentFunction would
// one by one; returns how many were written.
using SpanFunction = std::uint32_t (*)(const FragmentState& s, Framebuffer& fb, const FragmentSpan& span);

// The stencil test of `count` (at most kCapacity) fragments at x, x + 1, ...
// of row y, taken before they are shaded: when every one fails it, their
// stencil-fail writes are done and it returns true (each is tested and none
// written; its depth and colour could change nothing); otherwise it writes
// nothing and returns false.
using StencilRejectFunction = bool (*)(const FragmentState& s, Framebuffer& fb, int x, int y, int count);

struct FragmentPipeline {
  FragmentFunction fragment;
  SpanFunction span;
  // Null where the stencil test is not the first test (stencil off, or the
  // alpha test before it, which needs the shaded alpha).
  StencilRejectFunction stencilRejectsAll = nullptr;
};

// The variant of processFragment for `s` (alpha test, stencil test, depth
// test, blending on or off; colour writes none, all or some channels), for
// one fragment and for a span.
FragmentPipeline chooseFragmentPipeline(const FragmentState& s);

}  // namespace mpr
