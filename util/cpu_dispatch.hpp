#pragma once
// MPR_CPU_CLONES: compile a hot loop twice, for baseline x86-64 and for
// x86-64-v3 (AVX2, FMA, SSE4.1), and pick one at load time (GCC's
// target_clones, an ifunc). Only exact IEEE operations are used in such
// loops and contraction stays off (-ffp-contract=off), so both clones give
// the same bits: the newer one only does them four lanes at a time and turns
// std::fma into one instruction instead of a libm call. A build whose
// instrumentation cannot run inside an ifunc resolver, which runs before the
// instrumentation's run time has started (-fsanitize=thread), defines
// MPR_NO_CLONES and gets the baseline loop alone.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__linux__) && !defined(MPR_NO_CLONES)
#define MPR_CPU_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define MPR_CPU_CLONES
#endif
