#pragma once
// probes.csv: header `time,<probe names...>`, one row per output interval, SI units. Each row is
// flushed as written, so an interrupted run keeps every finished row.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fsi::app {

class ProbesCsv {
public:
  ProbesCsv(const std::filesystem::path& file, const std::vector<std::string>& names);
  void row(double time, const std::vector<double>& values);

private:
  std::filesystem::path path_;
  std::ofstream out_;
  std::size_t columns_;
};

} // namespace fsi::app
