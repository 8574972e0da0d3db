#pragma once
// What the AVX-512 kernels of the particle solvers share: whether this CPU runs them (checked once
// at run time) and the attribute that compiles a function for them in a portable build.
#if defined(__x86_64__) && defined(__GNUC__)
#define FSI_HAVE_AVX512 1
#define FSI_TARGET_AVX512 __attribute__((target("avx512f,avx512vl")))
#endif

namespace fsi::particles {

/// True if this CPU runs AVX-512F and AVX-512VL (the vector kernels need both).
bool avx512_available();

} // namespace fsi::particles
