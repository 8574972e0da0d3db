#pragma once
// The MPI ranks of `mpirun -np N fsi run` (built only with FSI_HAVE_MPI; issue 47). fsi runs
// decomposed when an MPI launcher started it (its environment names the rank count), so a plain
// `fsi run` never initialises MPI and behaves as a build without it.
#include "fsi_app/ranks.hpp"
#include "parallel/communicator.hpp"

#include <string>

namespace fsi::app {

class MpiRanks final : public Ranks {
public:
  MpiRanks() = default; // MPI_COMM_WORLD, after MPI_Init
  int rank() const override { return comm_.rank(); }
  int size() const override { return comm_.size(); }
  bool decomposed() const override { return true; }
  bool all(bool v) const override { return comm_.all(v); }
  Agreed agree(int signal, const std::string& failure) const override;
  std::string first(const std::string& failure) const override {
    return comm_.first_message(failure, !failure.empty());
  }
  void gather(const std::vector<double>& local, std::vector<double>& all) const override {
    comm_.gather(local, all);
  }
  void exchange(const std::vector<double>& send, const std::vector<int>& counts,
                std::vector<double>& received) const override {
    comm_.exchange(send, counts, received);
  }
  /// MPI_Reduce to rank 0 and MPI_Bcast, not MPI_Allreduce: the same bits on every rank.
  void sum(std::vector<double>& values) const override;
  void broadcast(std::vector<double>& values) const override;

private:
  std::unique_ptr<particles::Decomposition<2>>
      new_decomposition(std::integral_constant<int, 2>) const override;
  std::unique_ptr<particles::Decomposition<3>>
      new_decomposition(std::integral_constant<int, 3>) const override;

  parallel::Communicator comm_;
};

/// Whether an MPI launcher started this process (OpenMPI's, or a PMI/PMIx one's, environment).
bool started_by_mpi_launcher();

/// `fsi ARGS` on the ranks of MPI_COMM_WORLD: MPI_Init, the command, MPI_Finalize. Rank 0 prints
/// (a stopped run's message names the rank that stopped it); an internal error (exit 1) on any
/// rank prints there and ends every rank (MPI_Abort).
int run_cli_ranks(int& argc, char**& argv, const std::vector<std::string>& args, bool terminal);

} // namespace fsi::app
