#pragma once
#include <string>

namespace fsi::app {
std::string version();
std::string git_revision(); ///< revision the build was configured at, or "unknown"
} // namespace fsi::app
