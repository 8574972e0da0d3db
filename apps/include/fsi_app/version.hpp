#pragma once
#include <string>

namespace fsi::app {
std::string version();
std::string git_revision(); ///< source revision at build time (+ "-dirty"), or "unknown"
} // namespace fsi::app
