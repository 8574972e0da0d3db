#pragma once
// A thin wrapper of an MPI communicator: rank, size and the global reductions of a step (time
// step, probes, energies, removed counts) for doubles and integers. Not owning: the caller keeps
// the MPI_Comm alive (MPI_COMM_WORLD between MPI_Init and MPI_Finalize).
#include <chrono>
#include <cstdint>
#include <mpi.h>
#include <string>
#include <vector>

namespace fsi::parallel {

/// Wall seconds this process has spent inside the MPI collectives of Communicator and
/// FieldExchange, waiting for the slowest rank included: ranks with less work wait longer, so the
/// spread of this figure over the ranks is the step's load imbalance (run.json `ranks`).
double collective_seconds();

/// Adds the wall time from its construction to its destruction to collective_seconds().
class CollectiveTimer {
public:
  CollectiveTimer() : start_(std::chrono::steady_clock::now()) {}
  ~CollectiveTimer();
  CollectiveTimer(const CollectiveTimer&) = delete;
  CollectiveTimer& operator=(const CollectiveTimer&) = delete;

private:
  std::chrono::steady_clock::time_point start_;
};

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

  /// The same reductions carrying a failure flag in the same message (one MPI_Allreduce of two
  /// values): the reduced value and whether any rank passed `failed`.
  struct Flagged {
    double value;
    bool failed;
  };
  Flagged sum(double v, bool failed) const;
  Flagged min(double v, bool failed) const;
  Flagged max(double v, bool failed) const;
  /// `values` summed entry by entry in place, the flag in the same message; returns whether
  /// any rank passed `failed`.
  bool sum(std::vector<double>& values, bool failed) const;
  /// After a flagged reduction reported a failure (collective, on that path only): the message
  /// of the lowest failing rank, followed by " (rank r of P)".
  std::string first_failure(const std::string& message, bool failed) const;
  /// Collective, on every path: the message of the lowest rank passing `failed`, as given (every
  /// rank the same text), empty if none did.
  std::string first_message(const std::string& message, bool failed) const;
  /// Every rank's `local`, concatenated in rank order, into `all` on rank 0 (emptied on the
  /// others): frames and checkpoints gathered for the files rank 0 writes.
  void gather(const std::vector<double>& local, std::vector<double>& all) const;
  /// All to all (MPI_Alltoallv): `send`'s consecutive parts of counts[r] values go to rank r;
  /// `received` holds what every rank sent here, in rank order.
  void exchange(const std::vector<double>& send, const std::vector<int>& counts,
                std::vector<double>& received) const;

private:
  /// Rank `from`'s message on every rank.
  std::string broadcast_text(const std::string& message, int from) const;

  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
};

} // namespace fsi::parallel
