#include "fsi_app/version.hpp"

namespace fsi::app {
std::string version() {
  return FSI_VERSION;
}
std::string git_revision() {
  return FSI_GIT_REVISION;
}
} // namespace fsi::app
