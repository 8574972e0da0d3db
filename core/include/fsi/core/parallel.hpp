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

inline void set_sequential(bool on) {
  detail::sequential_flag() = on;
}
inline bool is_sequential() {
  return detail::sequential_flag();
}
inline int num_threads() {
  return is_sequential() ? 1 : omp_get_max_threads();
}
/// Processors this process may run on (its CPU affinity mask), the most threads worth asking for.
inline int available_processors() {
  return omp_get_num_procs();
}
/// Threads of the following parallel loops (n >= 1).
inline void set_num_threads(int n) {
  omp_set_num_threads(n);
}
/// Wall-clock seconds since an arbitrary origin, for step timers (the OpenMP clock).
inline double wall_time() {
  return omp_get_wtime();
}

/// f(i) for i in [0, n), static schedule (the same thread sees the same indices every call).
template <class F> void parallel_for(std::size_t n, F&& f) {
  const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static) if (!is_sequential())
  for (std::ptrdiff_t i = 0; i < count; ++i) f(static_cast<std::size_t>(i));
}

/// f(i) for i in [0, n), threads taking chunks of `chunk` indices as they finish: for loops whose
/// iterations cost unequal work (particles with many or few neighbours). Each index is computed
/// by one call, so results do not depend on the schedule.
template <class F> void parallel_for_balanced(std::size_t n, F&& f, int chunk = 256) {
  const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(dynamic, chunk) if (!is_sequential())
  for (std::ptrdiff_t i = 0; i < count; ++i) f(static_cast<std::size_t>(i));
}

namespace detail {
template <bool Balanced, class T, class F, class Combine>
T reduce(std::size_t n, T identity, F&& f, Combine&& combine, int chunk) {
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
    if constexpr (Balanced) {
#pragma omp for schedule(dynamic, chunk)
      for (std::ptrdiff_t i = 0; i < count; ++i)
        local = combine(local, f(static_cast<std::size_t>(i)));
    } else {
#pragma omp for schedule(static)
      for (std::ptrdiff_t i = 0; i < count; ++i)
        local = combine(local, f(static_cast<std::size_t>(i)));
    }
    partial[static_cast<std::size_t>(t)] = local;
  }
  T result = identity;
  for (int t = 0; t < used; ++t) result = combine(result, partial[static_cast<std::size_t>(t)]);
  return result;
}
} // namespace detail

/// combine over f(i), i in [0, n). Per-thread partials are combined in thread order, so the
/// result is bitwise reproducible for a given thread count.
template <class T, class F, class Combine>
T parallel_reduce(std::size_t n, T identity, F&& f, Combine&& combine) {
  return detail::reduce<false>(n, identity, f, combine, 0);
}

/// parallel_reduce with the schedule of parallel_for_balanced. Which indices a thread combines
/// varies from run to run, so `combine` must be exact (integer sums, min, max) for the result to
/// be reproducible.
template <class T, class F, class Combine>
T parallel_reduce_balanced(std::size_t n, T identity, F&& f, Combine&& combine, int chunk = 256) {
  return detail::reduce<true>(n, identity, f, combine, chunk);
}

} // namespace fsi
