#pragma once
// The `fsi` command line. Exit status: 0 success, 2 bad input (scene, mesh, command line),
// 3 a run that stopped (instability, solver failure), 1 anything unexpected.
#include "fsi_app/ranks.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace fsi::app {

/// `ranks`: the processes of the run (one by default; the MPI ranks under mpirun, which write
/// their files and print on rank 0 only).
int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
            bool terminal, const Ranks& ranks = OneProcess());

} // namespace fsi::app
