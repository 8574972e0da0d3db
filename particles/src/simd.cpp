#include "particles/simd.hpp"

namespace fsi::particles {

bool avx512_available() {
#ifdef FSI_HAVE_AVX512
  static const bool ok = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
  return ok;
#else
  return false;
#endif
}

} // namespace fsi::particles
