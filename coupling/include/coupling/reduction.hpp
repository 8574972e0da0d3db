#pragma once
// The one place where schemes, accelerations and convergence measures reduce over interface
// vectors: every dot product and norm goes through these, so a distributed run can later sum
// the per-rank parts here and nowhere else.
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "fsi/core/types.hpp"

namespace fsi::coupling {

template <class A, class B>
double dot(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  return a.dot(b);
}
template <class A> double squared_norm(const Eigen::MatrixBase<A>& a) {
  return a.squaredNorm();
}
template <class A> double norm(const Eigen::MatrixBase<A>& a) {
  return a.norm();
}

/// Q^T r: the dot products of every column of Q with r, as one vector.
template <class Q, class R>
Eigen::VectorXd transposed_product(const Eigen::MatrixBase<Q>& q, const Eigen::MatrixBase<R>& r) {
  return q.transpose() * r;
}

/// sqrt(sum_k |a_k|^2) over interface nodes.
template <int D> double norm(const std::vector<VecD<D>>& a) {
  double sum = 0.0;
  for (const VecD<D>& x : a) sum += x.squaredNorm();
  return std::sqrt(sum);
}

/// sqrt(sum_k |a_k - b_k|^2) over interface nodes (a and b of equal size).
template <int D>
double norm_of_difference(const std::vector<VecD<D>>& a, const std::vector<VecD<D>>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]).squaredNorm();
  return std::sqrt(sum);
}

} // namespace fsi::coupling
