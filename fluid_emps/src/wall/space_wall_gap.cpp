// The wall-gap step limit in 3-D (WallOptions::gap_courant).
#include "contact_law.hpp"
#include "fluid_emps/space_wall_terms.hpp"

#include <algorithm>
#include <limits>

namespace fsi::emps {

// dt <= C_gap r / (-(v - v_wall) . n) on every face particle i approaches, r its gap at x^{n+1}
// to first order (the hit's r at x* plus the correction dx along n_wall), floored at l0/2000.
double SpaceWallTerms::gap_dt(std::size_t i, const Vec3& dx) const {
  double dt = std::numeric_limits<double>::infinity();
  for (const erp::TriangleHits& f : hits_) {
    if (f.triangle[i] < 0) continue;
    const Vec3& n = f.n_wall[i];
    const double approach = -(velocity(i) - f.v_wall[i]).dot(n);
    if (approach <= 0) continue;
    const double gap = f.r[i] + dx.dot(n);
    dt = std::min(dt, gap_limit(gap, approach, l0_, o_.gap_courant));
  }
  return dt;
}

} // namespace fsi::emps
