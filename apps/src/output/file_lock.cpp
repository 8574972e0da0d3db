#include "fsi_app/output/file_lock.hpp"

#include <cerrno>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace fsi::app {

std::string lock_note(const std::filesystem::path& file, bool write) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return "";
  // The lock HDF5 would take, tried without waiting; closing the descriptor releases it.
  const bool held = ::flock(fd, (write ? LOCK_EX : LOCK_SH) | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);
  if (!held) return "";
  return ": it is locked by another process (HDF5 file locking: a program holds it open, e.g. "
         "a viewer, h5py or another fsi run); close it there and try again";
}

} // namespace fsi::app
