#pragma once
// A seeded generator of random GL scripts for conformance runs: random
// per-fragment state (stencil, depth, blend, alpha, masks, scissor), random
// clears, random triangles and rectangles with dyadic coordinates under an
// orthographic projection (so coverage must match Mesa exactly), and random
// accumulation operations. The same seed always gives the same script.
#include <cstdint>
#include <string>

namespace mpr {

std::string randomConformanceScript(std::uint64_t seed, int width = 48, int height = 40, int steps = 40);

}  // namespace mpr
