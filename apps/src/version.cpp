#include "fsi_app/version.hpp"

#include "fsi_git_revision.hpp" // generated at build time (apps/git_revision.cmake)

namespace fsi::app {
std::string version() {
  return FSI_VERSION;
}
std::string git_revision() {
  return FSI_GIT_REVISION;
}
} // namespace fsi::app
