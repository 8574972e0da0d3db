// Catch2's implementation (CATCH_CONFIG_RUNNER: everything but main), compiled once for every
// test program: the heaviest file of the tests (43-50 CPU s under the sanitizers).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "catch_session.hpp"

namespace fsi_test {

int run_catch_session(int argc, char* argv[], const char* output_file) {
  Catch::Session session;
  if (output_file) session.configData().outputFilename = output_file;
  return session.run(argc, argv);
}

} // namespace fsi_test
