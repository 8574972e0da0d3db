#pragma once
// A thin wrapper of an MPI communicator: rank, size and the global reductions of a step (time
// step, probes, energies, removed counts) for doubles and integers. Not owning: the caller keeps
// the MPI_Comm alive (MPI_COMM_WORLD between MPI_Init and MPI_Finalize).
#include <cstdint>
#include <mpi.h>

namespace fsi::parallel {

class Communicator {
public:
  explicit Communicator(MPI_Comm comm = MPI_COMM_WORLD);

  int rank() const { return rank_; }
  int size() const { return size_; }
  MPI_Comm comm() const { return comm_; }

  /// MPI_Allreduce over every rank; the same value on each. A sum of doubles depends on the
  /// rank count (summation order), min and max do not.
  double sum(double v) const;
  double min(double v) const;
  double max(double v) const;
  std::int64_t sum(std::int64_t v) const;
  std::int64_t min(std::int64_t v) const;
  std::int64_t max(std::int64_t v) const;
  /// True on every rank iff `v` is true on every rank.
  bool all(bool v) const;

private:
  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
};

} // namespace fsi::parallel
