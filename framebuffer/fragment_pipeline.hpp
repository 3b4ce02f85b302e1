#pragma once
// The per-fragment operations specialised from the state once per draw, as
// softpipe's choose_depth_test (sp_quad_depth_test.c) installs a function
// for the current depth and stencil state: the tests and writes a state
// disables are compiled out, so a stencil-only pass (colour writes off) does
// no colour work. Every variant does exactly what processFragment does.
#include "framebuffer/fragment_ops.hpp"

namespace mpr {

using FragmentFunction = FragmentFate (*)(const FragmentState& s, Framebuffer& fb, const Fragment& f);

// The variant of processFragment for `s` (alpha test, stencil test, depth
// test, blending on or off; colour writes none, all or some channels).
FragmentFunction chooseFragmentFunction(const FragmentState& s);

}  // namespace mpr
