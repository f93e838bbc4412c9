#pragma once
// SHOCKFIELD_SIMD_CLONES before a hot kernel function compiles it twice, for the baseline x86-64
// ISA of the build (SSE2) and for AVX2 (4 doubles per vector), and picks one when the program is
// loaded, by the CPU it runs on (GCC function multiversioning). Only code inlined into the
// function follows its clone. The AVX2 clone leaves out FMA on purpose: without contraction
// both clones round every operation alike, so results do not depend on the machine.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__AVX2__) && \
    !defined(SHOCKFIELD_NO_SIMD_CLONES)
#define SHOCKFIELD_SIMD_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define SHOCKFIELD_SIMD_CLONES
#endif
