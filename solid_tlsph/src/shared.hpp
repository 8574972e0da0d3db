#pragma once
// Shared by the TL-SPH solid's sources (private to solid_tlsph): the no-particle index and the
// monomials of the quadratic gradient correction's fit.
#include <Eigen/Core>
#include <cstddef>
#include <limits>

namespace fsi::tlsph {

/// No particle (an unset index; the neutral element of a first-bad-particle reduction).
inline constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

/// The quadratic fit's monomials of d = (X_b - X_a) / h (build_quadratic).
inline Eigen::Matrix<double, 5, 1> monomials(double dx, double dy) {
  Eigen::Matrix<double, 5, 1> p;
  p << dx, dy, 0.5 * dx * dx, dx * dy, 0.5 * dy * dy;
  return p;
}

} // namespace fsi::tlsph
