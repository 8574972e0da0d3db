// The cost of one of a decomposed step's reductions (issue 47): MPI_Allreduce of one double (a
// plain Communicator::max) against the failure-carrying reduction every reduction of the step
// makes (Communicator::Flagged, two doubles in one message). A plain MPI program with a fixed
// iteration count (every rank must make the same calls); rank 0 prints the slowest rank's mean.
//   mpirun --oversubscribe --allow-run-as-root -np 4 build/bench/parallel/bench_step_reductions
#include "parallel/communicator.hpp"

#include <chrono>
#include <cstdio>
#include <functional>

namespace {

/// Mean seconds a call over `calls` calls, the slowest rank's.
double mean_seconds(const fsi::parallel::Communicator& comm, int calls,
                    const std::function<void(int)>& call) {
  for (int k = 0; k < calls / 10; ++k) call(k); // warm-up
  MPI_Barrier(comm.comm());
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < calls; ++k) call(k);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return comm.max(seconds / calls);
}

} // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  {
    const fsi::parallel::Communicator comm;
    constexpr int calls = 20000;
    double sink = 0.0;
    const double plain = mean_seconds(comm, calls, [&](int k) { sink += comm.max(1.0 * k); });
    const double flagged =
        mean_seconds(comm, calls, [&](int k) { sink += comm.max(1.0 * k, false).value; });
    if (comm.rank() == 0)
      std::printf("ranks %d: %d reductions each; plain (1 double) %.2f us, flagged (2 doubles) "
                  "%.2f us a reduction (checksum %.0f)\n",
                  comm.size(), calls, 1e6 * plain, 1e6 * flagged, sink);
  }
  MPI_Finalize();
  return 0;
}
