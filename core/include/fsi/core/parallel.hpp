#pragma once
// The one place that spells OpenMP: kernels call parallel_for / parallel_reduce with an index
// lambda. set_sequential(true) runs every loop on the calling thread (tests, debugging).
#include <array>
#include <cassert>
#include <cstddef>
#include <omp.h>

namespace fsi {

namespace detail {
inline bool& sequential_flag() {
  static bool flag = false;
  return flag;
}
} // namespace detail

inline void set_sequential(bool on) { detail::sequential_flag() = on; }
inline bool is_sequential() { return detail::sequential_flag(); }
inline int num_threads() { return is_sequential() ? 1 : omp_get_max_threads(); }

/// f(i) for i in [0, n), static schedule (the same thread sees the same indices every call).
template <class F> void parallel_for(std::size_t n, F&& f) {
  const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static) if (!is_sequential())
  for (std::ptrdiff_t i = 0; i < count; ++i) f(static_cast<std::size_t>(i));
}

/// combine over f(i), i in [0, n). Per-thread partials are combined in thread order, so the
/// result is bitwise reproducible for a given thread count.
template <class T, class F, class Combine>
T parallel_reduce(std::size_t n, T identity, F&& f, Combine&& combine) {
  constexpr int max_threads = 256;
  std::array<T, max_threads> partial;
  partial.fill(identity);
  const auto count = static_cast<std::ptrdiff_t>(n);
  int used = 1;
#pragma omp parallel if (!is_sequential())
  {
    const int t = omp_get_thread_num();
    assert(t < max_threads);
#pragma omp single
    used = omp_get_num_threads();
    T local = identity;
#pragma omp for schedule(static)
    for (std::ptrdiff_t i = 0; i < count; ++i) local = combine(local, f(static_cast<std::size_t>(i)));
    partial[static_cast<std::size_t>(t)] = local;
  }
  T result = identity;
  for (int t = 0; t < used; ++t) result = combine(result, partial[static_cast<std::size_t>(t)]);
  return result;
}

} // namespace fsi
