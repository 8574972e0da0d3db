#include "fsi_app/output/probes_csv.hpp"

#include "fsi/core/error.hpp"
#include "fsi_app/output/text_file.hpp"

#include <cassert>
#include <iomanip>

namespace fsi::app {

namespace {
std::string header(const std::vector<std::string>& names) {
  std::string h = "time";
  for (const auto& n : names) h += ',' + n;
  return h;
}
} // namespace

ProbesCsv::ProbesCsv(const std::filesystem::path& file, const std::vector<std::string>& names)
    : path_(file), out_(file), columns_(names.size()) {
  if (!out_) throw RunError("output: " + file.string() + ": cannot create");
  out_ << header(names) << '\n' << std::flush;
  out_ << std::setprecision(10);
}

ProbesCsv::ProbesCsv(const std::filesystem::path& file, const std::vector<std::string>& names,
                     std::size_t rows)
    : path_(file), columns_(names.size()) {
  keep_lines(file, 1 + rows);
  std::string first;
  {
    std::ifstream in(file);
    std::getline(in, first);
  }
  if (first != header(names))
    throw InputError(file.string() + ": header '" + first + "' is not this scene's '" +
                     header(names) + "'");
  out_.open(file, std::ios::app);
  if (!out_) throw RunError("output: " + file.string() + ": cannot append");
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
