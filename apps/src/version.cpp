#include "fsi_app/version.hpp"

namespace fsi::app {
std::string version() { return "0.1.0"; }
} // namespace fsi::app
