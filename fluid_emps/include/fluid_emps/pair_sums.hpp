#pragma once
// The sums over one particle's neighbour-list row that the EMPS pair loops spend their time in,
// each in a scalar form and an AVX-512 form (eight pairs at once: gathered neighbours, masked
// r < r_e). The two give the same sums up to the order of addition (round-off). `vector` asks for
// the AVX-512 form; it runs where particles::avx512_available(), the scalar form elsewhere.
#include <cstdint>

namespace fsi::emps {

/// One particle's view of the neighbour list and of the fields the sums read.
struct PairRow {
  const std::uint32_t* j; ///< neighbour indices
  std::uint32_t count;
  double xi, yi;      ///< the particle's position
  double re2, inv_re; ///< r_e^2 and 1 / r_e of w(r) = (1 - r/r_e)^2 (eq. 8)
};

struct PndSum {
  double pnd = 0;           ///< sum_j w_ij (eq. 9)
  std::uint32_t within = 0; ///< neighbours with r_ij < r_e
};

struct VecSum {
  double x = 0, y = 0;
};

/// sum_j w_ij over r_ij < r_e (eq. 9).
PndSum pnd_sum(const PairRow& row, const double* x, const double* y, bool vector);
/// sum_j (p_j + p_i) (x_j - x_i) / r_ij^2 w_ij over 0 < r_ij < r_e (eq. 10 without d/n0).
VecSum gradient_sum(const PairRow& row, const double* x, const double* y, const double* p,
                    double p_i, bool vector);
/// sum_j (v_j - v_i) w_ij over r_ij < r_e (eq. 11 without 2d/(lambda0 n0)).
VecSum laplacian_sum(const PairRow& row, const double* x, const double* y, const double* vx,
                     const double* vy, double vxi, double vyi, bool vector);

/// laplacian_sum's sum, and over the closing pairs ((v_j - v_i) . (x_j - x_i) < 0, 0 < r_ij < r_e)
/// sum_j ((v_j - v_i) . e_ij) e_ij w_ij, e_ij the unit vector from i to j (the artificial
/// viscosity's pair sum, EmpsFluid::viscosity).
struct ViscousSum {
  VecSum laplacian, closing;
};
ViscousSum viscous_sum(const PairRow& row, const double* x, const double* y, const double* vx,
                       const double* vy, double vxi, double vyi, bool vector);

} // namespace fsi::emps
