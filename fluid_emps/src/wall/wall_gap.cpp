// The wall-gap step limit (WallOptions::gap_courant).
#include "contact_law.hpp"
#include "fluid_emps/wall_terms.hpp"

#include <algorithm>
#include <limits>

namespace fsi::emps {

// dt <= C_gap r / (-(v - v_wall) . n) on every face particle i approaches, r its gap at x^{n+1}
// to first order: the hit's r at x* plus the correction (dx, dy) along n_wall, floored as
// repulsion() floors it.
double WallTerms::gap_dt(std::size_t i, double dx, double dy) const {
  double dt = std::numeric_limits<double>::infinity();
  for (const erp::FaceHits& f : hits_.face) {
    if (f.segment[i] < 0) continue;
    const Vec2& n = f.n_wall[i];
    const double approach = -(Vec2(p_.vx[i], p_.vy[i]) - f.v_wall[i]).dot(n);
    if (approach <= 0) continue;
    const double gap = f.r[i] + dx * n.x() + dy * n.y();
    dt = std::min(dt, gap_limit(gap, approach, l0_, o_.gap_courant));
  }
  return dt;
}

} // namespace fsi::emps
