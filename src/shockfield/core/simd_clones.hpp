#pragma once
// SHOCKFIELD_SIMD_CLONES before a hot kernel function compiles it three times, for the baseline
// x86-64 ISA of the build (SSE2, 2 doubles per vector), for x86-64-v3 (AVX2, 4 doubles per
// vector, and FMA) and for x86-64-v4 (AVX-512, 8 doubles per vector where the file is compiled
// with -mprefer-vector-width=512, see CMakeLists.txt), and picks one when the program is loaded,
// by the CPU it runs on (GCC function multiversioning). Only code inlined into the function
// follows its clone. The clones differ at round-off only: FMA contracts a·b + c with a single
// rounding (the v3 and v4 clones both use it). A run on one machine is
// reproducible and independent of the thread count; SHOCKFIELD_NO_SIMD_CLONES (or a build with
// -march=...) compiles one version only.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__AVX2__) && \
    !defined(SHOCKFIELD_NO_SIMD_CLONES)
#define SHOCKFIELD_SIMD_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define SHOCKFIELD_SIMD_CLONES
#endif
