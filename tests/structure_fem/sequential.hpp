#pragma once
// Runs fsi::parallel_for sequentially while in scope: on tiny meshes thread start-up would
// dominate (and spin on a loaded machine).
#include "fsi/core/parallel.hpp"

namespace fem_test {

struct Sequential {
  Sequential() { fsi::set_sequential(true); }
  ~Sequential() { fsi::set_sequential(false); }
};

} // namespace fem_test
