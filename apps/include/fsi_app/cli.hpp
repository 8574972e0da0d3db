#pragma once
// The `fsi` command line. Exit status: 0 success, 2 bad input (scene, mesh, command line),
// 3 a run that stopped (instability, solver failure), 1 anything unexpected.
#include <ostream>
#include <string>
#include <vector>

namespace fsi::app {

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
            bool terminal);

} // namespace fsi::app
