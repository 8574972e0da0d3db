#include "fsi_app/output/probes_csv.hpp"

#include "fsi/core/error.hpp"

#include <cassert>
#include <iomanip>

namespace fsi::app {

ProbesCsv::ProbesCsv(const std::filesystem::path& file, const std::vector<std::string>& names)
    : path_(file), out_(file), columns_(names.size()) {
  if (!out_) throw RunError("output: " + file.string() + ": cannot create");
  out_ << "time";
  for (const auto& n : names) out_ << ',' << n;
  out_ << '\n' << std::flush;
  out_ << std::setprecision(10);
}

void ProbesCsv::row(double time, const std::vector<double>& values) {
  assert(values.size() == columns_);
  out_ << time;
  for (double v : values) out_ << ',' << v;
  out_ << '\n' << std::flush;
  if (!out_) throw RunError("output: " + path_.string() + ": write failed");
}

} // namespace fsi::app
