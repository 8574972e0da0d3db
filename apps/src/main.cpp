#include "fsi_app/cli.hpp"
#ifdef FSI_HAVE_MPI
#include "fsi_app/mpi_ranks.hpp"
#endif

#include <iostream>
#include <unistd.h>

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  const bool terminal = isatty(STDERR_FILENO) != 0;
#ifdef FSI_HAVE_MPI
  if (fsi::app::started_by_mpi_launcher())
    return fsi::app::run_cli_ranks(argc, argv, args, terminal);
#endif
  return fsi::app::run_cli(args, std::cout, std::cerr, terminal);
}
