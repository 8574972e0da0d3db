#include "fsi_app/cli.hpp"

#include <iostream>
#include <unistd.h>

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  return fsi::app::run_cli(args, std::cout, std::cerr, isatty(STDERR_FILENO) != 0);
}
