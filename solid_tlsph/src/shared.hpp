#pragma once
// Shared by the TL-SPH solid's sources (private to solid_tlsph): the no-particle index and the
// monomials of the quadratic gradient correction's fit.
#include <Eigen/Core>
#include <cstddef>
#include <limits>

#include "fsi/core/types.hpp"

namespace fsi::tlsph {

/// No particle (an unset index; the neutral element of a first-bad-particle reduction).
inline constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

/// The number of monomials of the quadratic fit: D linear and D (D + 1) / 2 quadratic (5, 9).
template <int D> inline constexpr int monomial_count = D + D*(D + 1) / 2;

template <int D> using Monomials = Eigen::Matrix<double, monomial_count<D>, 1>;

/// The quadratic fit's monomials of d = (X_b - X_a) / h (build_quadratic): d_i, then
/// d_i d_j / (1 + delta_ij) for i <= j; 2-D: (d_x, d_y, d_x^2 / 2, d_x d_y, d_y^2 / 2).
template <int D> Monomials<D> monomials(const VecD<D>& d) {
  Monomials<D> p;
  int m = D;
  for (int i = 0; i < D; ++i) {
    p(i) = d(i);
    for (int j = i; j < D; ++j) p(m++) = i == j ? 0.5 * d(i) * d(i) : d(i) * d(j);
  }
  return p;
}

} // namespace fsi::tlsph
