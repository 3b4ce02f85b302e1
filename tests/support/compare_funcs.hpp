#pragma once
// The eight comparison functions in GL's order, with their GL names, for
// tests that loop over all of them.
#include <array>

#include "framebuffer/compare_func.hpp"

namespace mpr::test {

inline constexpr std::array<CompareFunc, 8> kFuncs = {CompareFunc::Never,   CompareFunc::Less,
                                                      CompareFunc::Equal,   CompareFunc::Lequal,
                                                      CompareFunc::Greater, CompareFunc::Notequal,
                                                      CompareFunc::Gequal,  CompareFunc::Always};
inline constexpr std::array<const char*, 8> kFuncNames = {"NEVER",   "LESS",     "EQUAL",  "LEQUAL",
                                                          "GREATER", "NOTEQUAL", "GEQUAL", "ALWAYS"};

}  // namespace mpr::test
