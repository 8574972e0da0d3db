#pragma once
// The sums over one particle's neighbour-list row that the EMPS pair loops spend their time in,
// for D = 2 and 3. In 2-D each has a scalar form and an AVX-512 form (eight pairs at once:
// gathered neighbours, masked r < r_e); the two give the same sums up to the order of addition
// (round-off). `vector` asks for the AVX-512 form; it runs in 2-D where
// particles::avx512_available(), the scalar form elsewhere (3-D: scalar only, for now).
#include "particles/cell_binning.hpp"

#include <array>
#include <cstdint>

namespace fsi::emps {

/// One particle's view of the neighbour list and of the fields the sums read.
template <int D> struct BasicPairRow {
  const std::uint32_t* j; ///< neighbour indices
  std::uint32_t count;
  std::array<double, D> xi; ///< the particle's position
  double re2, inv_re;       ///< r_e^2 and 1 / r_e of w(r) = (1 - r/r_e)^2 (eq. 8)
};
using PairRow = BasicPairRow<2>;

/// A D-vector sum, zero-initialised.
template <int D> using VecSum = std::array<double, D>;
/// The component arrays of a vector field (positions, velocities).
template <int D> using Coords = particles::Coords<D>;

struct PndSum {
  double pnd = 0;           ///< sum_j w_ij (eq. 9)
  std::uint32_t within = 0; ///< neighbours with r_ij < r_e
};

/// sum_j w_ij over r_ij < r_e (eq. 9).
template <int D> PndSum pnd_sum(const BasicPairRow<D>& row, const Coords<D>& x, bool vector);
/// sum_j (p_j + p_i) (x_j - x_i) / r_ij^2 w_ij over 0 < r_ij < r_e (eq. 10 without d/n0).
template <int D>
VecSum<D> gradient_sum(const BasicPairRow<D>& row, const Coords<D>& x, const double* p, double p_i,
                       bool vector);
/// sum_j (v_j - v_i) w_ij over r_ij < r_e (eq. 11 without 2d/(lambda0 n0)).
template <int D>
VecSum<D> laplacian_sum(const BasicPairRow<D>& row, const Coords<D>& x, const Coords<D>& v,
                        const VecSum<D>& v_i, bool vector);

/// laplacian_sum's sum, and over the closing pairs ((v_j - v_i) . (x_j - x_i) < 0, 0 < r_ij < r_e)
/// sum_j ((v_j - v_i) . e_ij) e_ij w_ij, e_ij the unit vector from i to j (the artificial
/// viscosity's pair sum, BasicEmpsFluid::viscosity).
template <int D> struct ViscousSum { VecSum<D> laplacian{}, closing{}; };
template <int D>
ViscousSum<D> viscous_sum(const BasicPairRow<D>& row, const Coords<D>& x, const Coords<D>& v,
                          const VecSum<D>& v_i, bool vector);

} // namespace fsi::emps
