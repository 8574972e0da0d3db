#pragma once
// A time table read from a CSV file: a time column followed by value columns.
#include <string>
#include <vector>

namespace fsi::erp {

/// Columns of a numeric CSV table; column 0 is time, strictly increasing.
struct CsvTable {
  std::vector<std::vector<double>> columns;
};

/// Reads `path`: comma-separated numbers, `columns` per line. Blank lines and lines starting with
/// '#' are skipped; the first other line may be a header (text that is not a number). At least two
/// rows. Throws fsi::InputError "PATH:LINE: what" on a bad or short line or a time that does not
/// increase, "PATH: what" on an unreadable file or fewer than two rows (never line 0).
CsvTable read_csv_table(const std::string& path, int columns);

} // namespace fsi::erp
