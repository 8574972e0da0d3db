// The wall part of pnd (eq. 20) over the faces that act on a particle.
#include "fluid_emps/wall_terms.hpp"

#include <algorithm>

namespace fsi::emps {

// n*_i = sum_j w_ij + z (eqs. 9, 20): z(r_k) of every face, less the lattice that face k shares
// with each face before it (geometry_erp concave_overlap; in the plane at most two faces act), and
// with convex_corners the wedge's correction of the nearest face. WallDensity::scaled counts z
// compressed like the fluid beside it, z max(1, n_i / (n0 - z)).
double WallTerms::pnd(std::size_t i, double fluid_pnd) const {
  double z = 0.0;
  for (std::size_t k = 0; k < erp::max_faces; ++k) {
    const erp::FaceHits& f = hits_.face[k];
    if (f.segment[i] < 0) continue;
    double overlap = 0.0;
    for (std::size_t l = 0; l < k; ++l)
      overlap += erp::concave_overlap(hits_.face[l].n_wall[i], f.n_wall[i], hits_.face[l].r[i],
                                      f.r[i], l0_, r_e_, w_e_);
    z += k == 0 ? z_(f.r[i]) : z_(f.r[i]) - overlap;
  }
  if (o_.convex_corners && hits_.face[0].segment[i] >= 0) z += convex_part(i).dz;
  if (o_.pnd.density == WallDensity::added) return fluid_pnd + z;
  return fluid_pnd + z * std::max(1.0, fluid_pnd / std::max(n0_ - z, 0.25 * n0_));
}

} // namespace fsi::emps
