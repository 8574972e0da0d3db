#pragma once
// What the benchmarks share: the thread count taken from a benchmark argument, and the sweep of
// problem sizes on 1 and 2 threads (the machine's cores), timed in wall-clock milliseconds.
#include "fsi/core/parallel.hpp"

#include <benchmark/benchmark.h>

namespace fsi::bench {

/// The following parallel loops run on state.range(index) threads.
inline void use_threads(const benchmark::State& state, int index) {
  set_num_threads(static_cast<int>(state.range(index)));
}

/// Args {size, threads} for each of `sizes` on 1 and 2 threads, in ms of real time; use with
/// ->Apply(sizes_on_1_and_2_threads<...>).
template <int... sizes> void sizes_on_1_and_2_threads(benchmark::internal::Benchmark* b) {
  for (const int size : {sizes...})
    for (const int threads : {1, 2}) b->Args({size, threads});
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}

} // namespace fsi::bench
