// Main of the CalculiX comparison: exits 77 (CTest SKIP_RETURN_CODE) when ccx is not on PATH,
// so the test shows as skipped rather than passed.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <iostream>

#include "calculix.hpp"

int main(int argc, char* argv[]) {
  if (!fem_test::ccx_available()) {
    std::cout << "ccx not found on PATH: CalculiX comparison skipped\n";
    return 77;
  }
  return Catch::Session().run(argc, argv);
}
