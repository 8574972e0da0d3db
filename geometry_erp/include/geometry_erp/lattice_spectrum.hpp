#pragma once
// The largest rates of the MPS viscous sums on the rest lattice of spacing l0 (square for D = 2,
// cubic for D = 3), in units of the weight: what the explicit step's viscous limit is computed
// from once, as n0 and lambda0 are (docs/fluid_emps.md, "The time step").
#include "geometry_erp/wall_weight.hpp"

namespace fsi::erp {

/// The Laplacian sum's peak: max over wave vectors k of sum_{j != 0} w(|x_j|) (1 - cos k . x_j),
/// the largest eigenvalue of u -> -sum_j w_ij (u_j - u_i) (eq. 11 without 2d/(lambda0 n0)) on
/// the lattice's modes u_j = exp(i k . x_j) (a coarse grid of k over [0, pi/l0]^D, then a local
/// search; the sum is even in each component of k).
template <int D = 2> double lattice_laplacian_peak(double l0, double r_e, const WeightFunction& w);

/// The closing-pair sum's peak: max over the flip modes k in {0, pi/l0}^D, k != 0, of the
/// largest eigenvalue of sum over the points with k . x_j an odd multiple of pi of
/// w(|x_j|) e_j e_j^T (e_j = x_j / |x_j|). On a flip mode u_j = cos(k . x_j) U = +-U every pair
/// of the projected sum sum_j w ((u_j - u_i) . e) e either closes or opens and exactly one of the
/// pairs +-x_j closes, so its rate is this half of the full projected sum's; reversed by an
/// unstable step, the mode closes the other half, with the same rate.
template <int D = 2> double lattice_closing_peak(double l0, double r_e, const WeightFunction& w);

} // namespace fsi::erp
