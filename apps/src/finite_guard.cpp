#include "fsi_app/finite_guard.hpp"

#include <sstream>

namespace fsi::app {

namespace {
template <int D> void write_point(std::ostream& s, const VecD<D>& p) {
  s << '(';
  for (int i = 0; i < D; ++i) s << (i ? ", " : "") << p[i];
  s << ')';
}

template <int D>
std::optional<std::string> non_finite(const std::string& what, const VecD<D>& x, const VecD<D>& v) {
  if (x.allFinite() && v.allFinite()) return std::nullopt;
  std::ostringstream s;
  s << what << " at ";
  write_point<D>(s, x);
  s << " m, velocity ";
  write_point<D>(s, v);
  s << " m/s is not finite";
  return s.str();
}
} // namespace

std::optional<std::string> non_finite_point(const std::string& what, const Vec2& x, const Vec2& v) {
  return non_finite<2>(what, x, v);
}

std::optional<std::string> non_finite_point3(const std::string& what, const Vec3& x,
                                             const Vec3& v) {
  return non_finite<3>(what, x, v);
}

} // namespace fsi::app
