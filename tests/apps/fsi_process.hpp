#pragma once
// Test helpers for running the real `fsi` executable and reading what it wrote: scratch folders,
// whole files, a child process with its output in files, its exit status as a shell sees it, and
// the check that every dataset an XDMF index names is readable in fields.h5.
#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <hdf5.h>
#include <iterator>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace fsi_test {

/// An empty folder fsi_test_<prefix>_<name> in the temporary directory.
inline std::filesystem::path fresh_dir(const std::string& prefix, const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("fsi_test_" + prefix + "_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// The whole file, byte for byte ("" if it cannot be read).
inline std::string slurp(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Starts `exe ARGS...` with stdout and stderr to stdout.txt and stderr.txt in `logs`;
/// `in_child` (if any) runs in the child just before the exec.
inline pid_t spawn(const std::string& exe, const std::vector<std::string>& args,
                   const std::filesystem::path& logs, const std::function<void()>& in_child = {}) {
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    const int out = open((logs / "stdout.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = open((logs / "stderr.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(out, STDOUT_FILENO);
    dup2(err, STDERR_FILENO);
    if (in_child) in_child();
    std::vector<char*> argv{const_cast<char*>(exe.c_str())};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(exe.c_str(), argv.data());
    _exit(127);
  }
  return pid;
}

/// The exit status as a shell reports it (128 + signal for a killed process); a process still
/// running after `timeout_s` is killed and counts as 124 (a hang).
inline int wait_status(pid_t pid, double timeout_s = std::numeric_limits<double>::infinity()) {
  int status = 0;
  if (!(timeout_s < std::numeric_limits<double>::infinity())) {
    waitpid(pid, &status, 0);
  } else {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (waitpid(pid, &status, WNOHANG) == 0) {
      if (std::chrono::steady_clock::now() > until) {
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        return 124;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/// Frames listed in an XDMF index.
inline std::size_t frames_in(const std::filesystem::path& xmf) {
  const std::string text = slurp(xmf);
  const std::regex time("<Time ");
  return static_cast<std::size_t>(
      std::distance(std::sregex_iterator(text.begin(), text.end(), time), std::sregex_iterator()));
}

/// Every HDF5 dataset that dir/fields.xmf names opens in dir/fields.h5 with the dimensions the
/// index states, and reads; returns the number of datasets named.
inline int check_indexed_datasets(const std::filesystem::path& dir) {
  const std::string xmf = slurp(dir / "fields.xmf");
  REQUIRE(xmf.find("</Xdmf>") != std::string::npos); // whole
  const std::regex item(
      R"re(<DataItem Dimensions="([0-9 ]+)"[^>]*>fields\.h5:([^<]+)</DataItem>)re");
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fopen((dir / "fields.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  int items = 0;
  for (auto it = std::sregex_iterator(xmf.begin(), xmf.end(), item); it != std::sregex_iterator();
       ++it, ++items) {
    const std::string path = (*it)[2];
    INFO(path);
    const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
    REQUIRE(set >= 0);
    const hid_t space = H5Dget_space(set);
    hsize_t dims[2] = {0, 0};
    const int rank = H5Sget_simple_extent_dims(space, dims, nullptr);
    std::string stated;
    for (int k = 0; k < rank; ++k) {
      if (k > 0) stated += ' ';
      stated += std::to_string(dims[k]);
    }
    CHECK(stated == (*it)[1].str());
    std::vector<double> values(dims[0] * (rank > 1 ? dims[1] : 1));
    CHECK(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0);
    H5Sclose(space);
    H5Dclose(set);
  }
  H5Fclose(file);
  return items;
}

} // namespace fsi_test
