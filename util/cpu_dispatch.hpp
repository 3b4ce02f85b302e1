#pragma once
// MPR_CPU_CLONES: compile a hot loop twice, for baseline x86-64 and for
// x86-64-v3 (AVX2, FMA, SSE4.1), and pick one at load time (GCC's
// target_clones, an ifunc). Only exact IEEE operations are used in such
// loops and contraction stays off (-ffp-contract=off), so both clones give
// the same bits: the newer one only does them four lanes at a time and turns
// std::fma into one instruction instead of a libm call.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__linux__)
#define MPR_CPU_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define MPR_CPU_CLONES
#endif
