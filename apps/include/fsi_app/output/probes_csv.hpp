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
  /// Creates the file with its header.
  ProbesCsv(const std::filesystem::path& file, const std::vector<std::string>& names);
  /// Continues an existing file after its first `rows` rows (a restart); throws InputError when
  /// its header names other probes or it has fewer rows.
  ProbesCsv(const std::filesystem::path& file, const std::vector<std::string>& names,
            std::size_t rows);
  void row(double time, const std::vector<double>& values);

private:
  std::filesystem::path path_;
  std::ofstream out_;
  std::size_t columns_;
};

} // namespace fsi::app
