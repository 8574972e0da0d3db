// libFuzzer target FSI_FUZZ_TARGET (scene, override or gmsh), driving the parser
// fsi::fuzz::FSI_FUZZ_INPUT (see inputs.hpp); fuzz/CMakeLists.txt builds one executable per
// target from this file. Any exception but InputError, and any message not of the one-line form,
// is a finding.
#include "inputs.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string message =
      fsi::fuzz::FSI_FUZZ_INPUT(std::string(reinterpret_cast<const char*>(data), size));
  if (fsi::fuzz::well_formed(FSI_FUZZ_TARGET, message)) return 0;
  std::fprintf(stderr, "malformed error message: %s\n", message.c_str());
  std::abort();
}
