#pragma once
// Seeded generators of random GL scripts for conformance runs, in families.
// The default family: random per-fragment state (stencil, depth, blend,
// alpha, masks, scissor), random clears, random triangles and rectangles with
// dyadic coordinates under an orthographic projection (so coverage must match
// Mesa exactly). The other families (randomFamilies()) use arbitrary float
// coordinates under perspective and orthographic views and each stresses one
// part of the pipeline: `perspective`, `matrices`, `primitives`, `lighting`,
// `fog`, `clip_planes`, `accumulation`, `mixed` (all of them) and
// `fragment_ops` (every per-fragment value at once). Every
// script uses only the call set of the spec and clears every buffer it reads.
// The same seed and family always give the same script.
#include <cstdint>
#include <string>
#include <vector>

namespace mpr {

// The enumerant names the generators draw from, in a fixed order (the
// scripts of a seed depend on it): the eight comparison functions, the eight
// stencil operations, and the ten blend factors both sides take.
const std::vector<std::string>& compareFunctionNames();
const std::vector<std::string>& stencilOperationNames();
const std::vector<std::string>& blendFactorNames();

std::string randomConformanceScript(std::uint64_t seed, int width = 48, int height = 40, int steps = 40);

// The family names accepted by randomFamilyScript ("default" first).
const std::vector<std::string>& randomFamilies();

// A script of the named family; "default" is randomConformanceScript(seed).
// Throws std::invalid_argument for an unknown family.
std::string randomFamilyScript(const std::string& family, std::uint64_t seed);

}  // namespace mpr
