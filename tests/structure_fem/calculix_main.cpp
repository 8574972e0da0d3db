// Main of the CalculiX comparison: exits 77 (CTest SKIP_RETURN_CODE) when ccx is not on PATH,
// so the test shows as skipped rather than passed.
#include <iostream>

#include "../catch_session.hpp"
#include "calculix.hpp"

int main(int argc, char* argv[]) {
  if (!fem_test::ccx_available()) {
    std::cout << "ccx not found on PATH: CalculiX comparison skipped\n";
    return 77;
  }
  return fsi_test::run_catch_session(argc, argv);
}
