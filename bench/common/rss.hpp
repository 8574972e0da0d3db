#pragma once
// The process's resident set (VmRSS of /proc/self/status), bytes: the benchmarks' memory per
// particle is its growth over the fluid's construction.
#include <fstream>
#include <string>

namespace fsi::bench {

inline double rss_bytes() {
  std::ifstream in("/proc/self/status");
  std::string key;
  while (in >> key) {
    if (key == "VmRSS:") {
      double kb = 0.0;
      in >> kb;
      return kb * 1024.0;
    }
    std::getline(in, key);
  }
  return 0.0;
}

} // namespace fsi::bench
