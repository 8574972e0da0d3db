#pragma once
// The two error channels for conditions a user can cause. Programmer invariants are asserts.
#include <stdexcept>
#include <string>

namespace fsi {

/// Bad user input (scene, mesh, command line), detected before any computation.
/// The message is one line, `FILE:LINE: KEY: what is wrong` where a file is known. Exit status 2.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A run that cannot go on (NaN, particle through a wall, Newton or coupling failure).
/// The message says what, where (particle, node, element) and when (step, time). Exit status 3.
struct RunError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

} // namespace fsi
