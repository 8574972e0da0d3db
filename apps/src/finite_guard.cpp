#include "fsi_app/finite_guard.hpp"

#include <sstream>

namespace fsi::app {

std::optional<std::string> non_finite_point(const std::string& what, const Vec2& x, const Vec2& v) {
  if (x.allFinite() && v.allFinite()) return std::nullopt;
  std::ostringstream s;
  s << what << " at (" << x.x() << ", " << x.y() << ") m, velocity (" << v.x() << ", " << v.y()
    << ") m/s is not finite";
  return s.str();
}

} // namespace fsi::app
