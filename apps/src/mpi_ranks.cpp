#include "fsi_app/mpi_ranks.hpp"

#include "fsi_app/cli.hpp"
#include "parallel/particle_decomposition.hpp"

#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

namespace fsi::app {

std::unique_ptr<particles::Decomposition<2>>
MpiRanks::new_decomposition(std::integral_constant<int, 2>) const {
  return std::make_unique<parallel::ParticleDecomposition<2>>(comm_);
}

std::unique_ptr<particles::Decomposition<3>>
MpiRanks::new_decomposition(std::integral_constant<int, 3>) const {
  return std::make_unique<parallel::ParticleDecomposition<3>>(comm_);
}

Ranks::Agreed MpiRanks::agree(int signal, const std::string& failure) const {
  const auto reduced = comm_.max(static_cast<double>(signal), !failure.empty());
  return {static_cast<int>(reduced.value),
          reduced.failed ? comm_.first_failure(failure, !failure.empty()) : std::string()};
}

void MpiRanks::sum(std::vector<double>& values) const {
  const int n = static_cast<int>(values.size());
  if (rank() == 0)
    MPI_Reduce(MPI_IN_PLACE, values.data(), n, MPI_DOUBLE, MPI_SUM, 0, comm_.comm());
  else
    MPI_Reduce(values.data(), nullptr, n, MPI_DOUBLE, MPI_SUM, 0, comm_.comm());
  broadcast(values);
}

void MpiRanks::broadcast(std::vector<double>& values) const {
  MPI_Bcast(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, 0, comm_.comm());
}

bool started_by_mpi_launcher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) // OpenMPI's mpirun; Hydra, PMI-2
    if (std::getenv(name) != nullptr) return true;
  // A PMIx launcher, but not the environment a singleton MPI program (e.g. pvpython) hands its
  // children: OpenMPI marks that one ess=singleton.
  const char* ess = std::getenv("OMPI_MCA_ess");
  return std::getenv("PMIX_RANK") != nullptr && (ess == nullptr || std::string(ess) != "singleton");
}

int run_cli_ranks(int& argc, char**& argv, const std::vector<std::string>& args, bool terminal) {
  MPI_Init(&argc, &argv);
  int code = 0;
  {
    const MpiRanks ranks;
    // Every rank reads the same scene and takes the same decisions, and a failure found on some
    // ranks is agreed at the step's next reduction (particles::Decomposition::fail, Ranks::agree)
    // with the failing rank's message, so a bad input or a stopped run ends every rank with the
    // same status and message: rank 0 prints it.
    std::ostringstream quiet_out, quiet_err;
    const bool root = ranks.rank() == 0;
    code = run_cli(args, root ? std::cout : quiet_out, root ? std::cerr : quiet_err,
                   terminal && root, ranks);
    if (code == 1) { // unexpected, perhaps on this rank only: the others may wait for it
      if (!root) std::cerr << "rank " << ranks.rank() << ": " << quiet_err.str();
      std::cerr.flush();
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
  }
  MPI_Finalize();
  return code;
}

} // namespace fsi::app
