#pragma once
// Mirror-particle helpers of the ERP wall (eqs. 21-24), for D = 2 and 3. n is the unit wall normal
// n_wall of eq. 19, x_wall and v_wall the nearest wall point and its velocity.
#include "fsi/core/types.hpp"

namespace fsi::erp {

/// R_ref = I - 2 n (x) n: reflection across the wall line (plane in 3-D) (eq. 21).
template <int D> MatD<D> R_ref(const VecD<D>& n) {
  return MatD<D>::Identity() - 2.0 * n * n.transpose();
}

/// R_inv = -I (eq. 22).
template <int D = 2> MatD<D> R_inv() {
  return -MatD<D>::Identity();
}

/// x_i' = x_i + 2 (x_wall - x_i) (eq. 23).
template <int D> VecD<D> mirror_position(const VecD<D>& x_i, const VecD<D>& x_wall) {
  return x_i + 2.0 * (x_wall - x_i);
}

/// No-slip mirror velocity v_i' = R_inv [v_i - 2 {v_wall - (n . v_wall) n}] (eq. 24), i.e. the
/// ghost value 2 v_wall,t - v_i: (v_i + v_i')/2 is the wall's tangential velocity. The mirror
/// Laplacian term is R_inv <lap v>_i'.
template <int D>
VecD<D> mirror_velocity_no_slip(const VecD<D>& v_i, const VecD<D>& v_wall, const VecD<D>& n) {
  return R_inv<D>() * (v_i - 2.0 * (v_wall - n.dot(v_wall) * n));
}

/// Slip mirror velocity v_i' = R_ref v_i + 2 (n . v_wall) n: the ghost reflects the velocity
/// relative to the wall's normal motion, so (v_i + v_i')/2 keeps v_i's tangential part and has the
/// wall's normal velocity. The mirror Laplacian term is then R_ref <lap v>_i' (not R_inv).
template <int D>
VecD<D> mirror_velocity_slip(const VecD<D>& v_i, const VecD<D>& v_wall, const VecD<D>& n) {
  return R_ref<D>(n) * v_i + 2.0 * n.dot(v_wall) * n;
}

} // namespace fsi::erp
