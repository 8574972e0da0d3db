#pragma once
// Numbers in messages: `digits` significant digits, as an ostream prints them.
#include <sstream>
#include <string>

namespace fsi {

inline std::string significant(double v, int digits) {
  std::ostringstream out;
  out.precision(digits);
  out << v;
  return out.str();
}

} // namespace fsi
