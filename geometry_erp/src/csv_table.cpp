#include "geometry_erp/csv_table.hpp"

#include "fsi/core/error.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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

/// At most 60 characters of `s` for a message, control and non-ASCII bytes as \xNN.
std::string excerpt(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size() && out.size() < 60; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    }
  }
  return out.size() < s.size() && out.size() >= 60 ? out + "..." : out;
}

} // namespace

CsvTable read_csv_table(const std::string& path, int columns) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the table (" + std::strerror(errno) + ")");
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
    if (!numeric) throw InputError(where + "not a row of numbers: '" + excerpt(content) + "'");
    if (fields.size() != static_cast<std::size_t>(columns))
      throw InputError(where + "expected " + std::to_string(columns) + " columns, found " +
                       std::to_string(fields.size()));
    if (!table.columns[0].empty() && !(row[0] > table.columns[0].back()))
      throw InputError(where + "time " + trim(fields[0]) + " does not increase");
    for (std::size_t c = 0; c < row.size(); ++c) table.columns[c].push_back(row[c]);
  }
  if (table.columns[0].size() < 2)
    throw InputError(path + ": " + std::to_string(table.columns[0].size()) +
                     " rows of numbers; a table needs at least two");
  return table;
}

} // namespace fsi::erp
