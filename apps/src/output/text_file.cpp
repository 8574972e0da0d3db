#include "fsi_app/output/text_file.hpp"

#include "fsi/core/error.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fsi::app {

void keep_lines(const std::filesystem::path& file, std::size_t lines) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": missing (a restart continues the files of its run)");
  std::string kept, line;
  std::size_t count = 0;
  while (count < lines && std::getline(in, line)) kept += line + '\n', ++count;
  if (count < lines)
    throw InputError(file.string() + ": has " + std::to_string(count) +
                     " lines, the checkpoint needs " + std::to_string(lines));
  write_file_atomically(file, kept);
}

void write_file_atomically(const std::filesystem::path& file, const void* data, std::size_t size,
                           const std::string& prefix, bool sync) {
  const std::filesystem::path tmp = file.string() + ".tmp";
  auto fail = [&](const std::string& what, int error) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    const std::string kept = file.filename().string() + " is left as it was before this write";
    std::string why;
    if (error == ENOSPC || error == EDQUOT)
      why = " (disk full; " + kept + ")";
    else if (error == EFBIG)
      why = " (the file size limit, ulimit -f; " + kept + ")";
    throw RunError(prefix + file.string() + ": " + what + ": " + std::strerror(error) + why);
  };
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("cannot create " + tmp.filename().string(), errno);
  const char* p = static_cast<const char*>(data);
  std::size_t left = size;
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : ENOSPC;
      ::close(fd);
      fail("cannot write", error);
    }
    p += n, left -= static_cast<std::size_t>(n);
  }
  if (sync && ::fsync(fd) != 0) {
    const int error = errno;
    ::close(fd);
    fail("cannot flush to disk", error);
  }
  if (::close(fd) != 0) fail("cannot close", errno);
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) fail("cannot rename " + tmp.filename().string(), ec.value());
}

} // namespace fsi::app
