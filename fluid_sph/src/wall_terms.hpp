#pragma once
// The one copy of the wall terms of eqs. 15-17 for a fluid particle i and a wall particle a: the
// fluid's step (first_half) adds them to i, the tracked walls' reaction takes them off a.
#include "shared.hpp"

#include <algorithm>
#include <array>

namespace fsi::sph {

/// Low-dissipation limiter (eq. 5, reference code's argument): beta = min(3 max(u / c0, 0), 1)
/// with u = (v_i - v_j) . e_ij, positive when the pair separates; beta = 1 when it is off.
inline double limiter(double u, double inv_c0, bool on) {
  return on ? std::min(3.0 * std::max(u * inv_c0, 0.0), 1.0) : 1.0;
}

/// The dummy wall particle's pressure jump p_d - p_i = rho_i r (a_prior - a_w) . (-e_ia) (eq. 16),
/// extrapolated towards every dummy: the reference code's max(0, .) leaves p_d = p_i above the
/// particle, a vertical force on the side-wall columns that no pressure field balances (it drove a
/// circulation along the side walls, docs/fluid_sph.md).
template <int D, class A, class E>
inline double dummy_jump(double rho_i, double r, const A& da, const E& e) {
  return -rho_i * r * dot<D>(da, e);
}

/// The no-slip viscous wall term (eq. 15) of a pair (i, a) is 2 mu V_i (v_i - v_d) this: with the
/// dummy velocity v_d = 2 v_w - v_i (eq. 17, code form) v_i - v_d = 2 (v_i - v_w), as the
/// reference code has it; dW V_a / (r + 0.01 h) as the fluid pairs.
inline double wall_viscous_weight(double dW, double V_a, double r, double reg) {
  return 2.0 * dW * V_a / (r + reg);
}

/// What the wall term of a pair (i, a) needs.
template <int D> struct WallPair {
  double p_i, rho_i, r;     ///< pressure and density of i, distance r_ia
  std::array<double, D> da; ///< a_prior,i - a_w
  std::array<double, D> e;  ///< e_ia
  double dWV;               ///< dW V_a
  const double* b;          ///< B_i (eq. 18), upper triangle (sym)
  std::array<double, D> dv; ///< v_i - v_w
  std::array<double, D> n;  ///< wall normal
  double rho0c0, inv_c0;
  bool limiter_on;
};

/// The force per unit volume on i from wall particle a: the dummy pressure (eq. 16), pushing only,
/// and the Riemann dissipation along the wall normal with u = 2 (v_i - v_w) . n_w (eqs. 15, 17).
template <int D> inline std::array<double, D> wall_term(const WallPair<D>& w) {
  const double p_d = w.p_i + dummy_jump<D>(w.rho_i, w.r, w.da, w.e);
  // A wall pushes, never pulls: p_i + p_d >= 0 (p_d < 0 above a particle near the surface).
  std::array<double, D> g;
  for (int c = 0; c < D; ++c) g[c] = w.dWV * w.e[c];
  const double ps = std::max(w.p_i + p_d, 0.0);
  const double u = 2.0 * dot<D>(w.dv, w.n);
  const double d = w.rho0c0 * limiter(u, w.inv_c0, w.limiter_on) * u * w.dWV;
  std::array<double, D> t;
  for (int c = 0; c < D; ++c) t[c] = -ps * sym_row<D>(w.b, c, g) + d * w.n[c];
  return t;
}

} // namespace fsi::sph
