#include "geometry_erp/csv_table.hpp"

#include "fsi/core/error.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace fsi::erp {

namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

/// Parses one field as a finite double; false on anything else.
bool parse_number(const std::string& field, double& value) {
  const std::string s = trim(field);
  if (s.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(s.c_str(), &end);
  return errno == 0 && end == s.c_str() + s.size() && std::isfinite(value);
}

} // namespace

CsvTable read_csv_table(const std::string& path, int columns) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ":0: cannot open the motion table");
  CsvTable table;
  table.columns.assign(static_cast<std::size_t>(columns), {});
  std::string line;
  int line_no = 0;
  bool header_allowed = true;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string content = trim(line);
    if (content.empty() || content.front() == '#') continue;
    std::vector<std::string> fields;
    std::stringstream ss(content);
    for (std::string field; std::getline(ss, field, ',');) fields.push_back(field);
    std::vector<double> row(fields.size());
    bool numeric = !fields.empty();
    for (std::size_t c = 0; c < fields.size() && numeric; ++c)
      numeric = parse_number(fields[c], row[c]);
    const auto where = path + ":" + std::to_string(line_no) + ": ";
    if (!numeric && header_allowed) {
      header_allowed = false;
      continue;
    }
    header_allowed = false;
    if (!numeric) throw InputError(where + "not a row of numbers: '" + content + "'");
    if (fields.size() != static_cast<std::size_t>(columns))
      throw InputError(where + "expected " + std::to_string(columns) + " columns, found " +
                       std::to_string(fields.size()));
    if (!table.columns[0].empty() && !(row[0] > table.columns[0].back()))
      throw InputError(where + "time " + trim(fields[0]) + " does not increase");
    for (std::size_t c = 0; c < row.size(); ++c) table.columns[c].push_back(row[c]);
  }
  if (table.columns[0].size() < 2)
    throw InputError(path + ":" + std::to_string(line_no) + ": fewer than two rows");
  return table;
}

} // namespace fsi::erp
