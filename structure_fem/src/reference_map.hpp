#pragma once
// Private: the isoparametric reference map of an element with N nodes in D dimensions, shared by
// the T6 and T10 elements.
#include <array>
#include <cstddef>

#include <Eigen/Core>

#include "fsi/core/types.hpp"

namespace fsi::fem {

/// The node coordinates as rows (row K = X_K).
template <std::size_t N, int D>
Eigen::Matrix<double, static_cast<int>(N), D> node_coordinates(const std::array<VecD<D>, N>& X) {
  Eigen::Matrix<double, static_cast<int>(N), D> C;
  for (std::size_t k = 0; k < N; ++k) C.row(static_cast<Eigen::Index>(k)) = X[k].transpose();
  return C;
}

/// J(i, j) = dX_j / dxi_i from the shape derivatives dN (row i: d/dxi_i) and the coordinates.
template <int D, int N>
MatD<D> jacobian(const Eigen::Matrix<double, D, N>& dN, const Eigen::Matrix<double, N, D>& C) {
  return dN * C;
}

} // namespace fsi::fem
