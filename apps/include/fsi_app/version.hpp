#pragma once
#include <string>

namespace fsi::app {
std::string version();
} // namespace fsi::app
