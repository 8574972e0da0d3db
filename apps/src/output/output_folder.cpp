#include "fsi_app/output/output_folder.hpp"

#include "fsi/core/error.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <vector>

namespace fsi::app {

bool is_run_file(const std::string& name) {
  static const std::vector<std::string> files = {"fields.h5",      "fields.xmf",   "probes.csv",
                                                 "run.json",       "coupling.csv", "interface.h5",
                                                 "failed_state.h5"};
  std::string base = name;
  if (base.ends_with(".tmp")) base.resize(base.size() - 4);
  if (std::find(files.begin(), files.end(), base) != files.end()) return true;
  long step = 0;
  char tail[8] = {};
  return std::sscanf(base.c_str(), "checkpoint_%ld%7s", &step, tail) == 2 &&
         std::string(tail) == ".h5";
}

std::filesystem::path checkpoint_path(const std::filesystem::path& out, long step) {
  char name[48];
  std::snprintf(name, sizeof name, "checkpoint_%09ld.h5", step);
  return out / name;
}

void prune_checkpoints(const std::filesystem::path& out, long step, int keep) {
  std::vector<std::pair<long, std::filesystem::path>> found;
  for (const auto& entry : std::filesystem::directory_iterator(out)) {
    const std::string name = entry.path().filename().string();
    long s = 0;
    char tail[8] = {};
    if (std::sscanf(name.c_str(), "checkpoint_%ld%7s", &s, tail) == 2 &&
        std::string(tail) == ".h5" && s <= step)
      found.emplace_back(s, entry.path());
  }
  std::sort(found.begin(), found.end());
  for (std::size_t i = 0; i + static_cast<std::size_t>(keep) < found.size(); ++i)
    std::filesystem::remove(found[i].second);
}

OutputLock::OutputLock(const std::filesystem::path& out, bool fresh, bool overwrite) {
  namespace fs = std::filesystem;
  const std::string dir = out.string();
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec))
    throw InputError(dir + ": --out: exists and is not a folder; give a folder");
  fs::create_directories(out, ec);
  if (ec) throw InputError(dir + ": --out: cannot create the folder (" + ec.message() + ")");
  const fs::path lock = out / ".lock";
  fd_ = open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw InputError(dir + ": --out: cannot write in this folder (" + std::strerror(errno) + ")");
  if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    close(fd_);
    throw InputError(dir + ": --out: another fsi run is writing to this folder (it holds " +
                     lock.string() + "); give another --out");
  }
  if (!fresh) return;
  std::vector<fs::path> found;
  for (const auto& entry : fs::directory_iterator(out, ec))
    if (is_run_file(entry.path().filename().string())) found.push_back(entry.path());
  std::sort(found.begin(), found.end());
  if (!found.empty() && !overwrite) {
    close(fd_);
    std::string names;
    for (std::size_t i = 0; i < found.size() && i < 4; ++i)
      names += (i ? ", " : "") + found[i].filename().string();
    if (found.size() > 4) names += ", ...";
    throw InputError(dir + ": --out holds the files of an earlier run (" + names +
                     "); give another folder, --restart from one of its checkpoints, or "
                     "--overwrite to delete them");
  }
  for (const auto& f : found) {
    fs::remove(f, ec);
    if (ec) {
      close(fd_);
      throw InputError(f.string() + ": --overwrite: cannot delete (" + ec.message() + ")");
    }
  }
}

OutputLock::~OutputLock() {
  close(fd_);
}

} // namespace fsi::app
