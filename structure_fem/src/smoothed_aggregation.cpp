#include "structure_fem/smoothed_aggregation.hpp"

#include <cmath>
#include <random>

#include "fsi/core/error.hpp"
#include "structure_fem/aggregation.hpp"

namespace fsi::fem {

namespace {

Vector inverse_diagonal(const SparseMatrix& A) {
  Vector d = A.diagonal();
  for (Eigen::Index i = 0; i < d.size(); ++i)
    if (!(d[i] > 0.0))
      throw RunError("linear solver cg_amg: diagonal entry " + std::to_string(i) + " of " +
                     std::to_string(d.size()) + " is not positive");
  return d.cwiseInverse();
}

/// rho(D^-1 A) by power iterations on the similar SPD D^-1/2 A D^-1/2, from a fixed start.
double spectral_radius(const SparseMatrix& A, const Vector& inv_diagonal, int iterations) {
  const Vector s = inv_diagonal.cwiseSqrt();
  std::mt19937 generator(44);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Vector v = Vector::NullaryExpr(A.rows(), [&]() { return uniform(generator); });
  Vector w(v.size());
  double rho = 0.0;
  for (int k = 0; k < iterations; ++k) {
    v /= v.norm();
    w.noalias() = A * s.cwiseProduct(v);
    v = s.cwiseProduct(w);
    rho = v.norm();
  }
  return rho;
}

/// One symmetric Gauss-Seidel sweep on A x = b (forward, then backward). A is symmetric and
/// column-major: column i is row i.
void symmetric_gauss_seidel(const SparseMatrix& A, const Vector& inv_diagonal, const Vector& b,
                            Vector& x) {
  auto relax = [&](Eigen::Index i) {
    double s = b[i];
    for (SparseMatrix::InnerIterator it(A, i); it; ++it) s -= it.value() * x[it.index()];
    x[i] += s * inv_diagonal[i];
  };
  for (Eigen::Index i = 0; i < A.cols(); ++i) relax(i);
  for (Eigen::Index i = A.cols() - 1; i >= 0; --i) relax(i);
}

} // namespace

void SmoothedAggregation::setup(const SparseMatrix& A, const NearNullSpace& near_null_space) {
  A0_ = &A;
  levels_.assign(1, Level{});
  NearNullSpace B = near_null_space;
  double theta = options_.theta;
  for (std::size_t l = 0;; ++l) {
    const SparseMatrix& Al = op(l);
    Level& L = levels_[l];
    const Eigen::Index n = Al.rows();
    L.inv_diagonal = inverse_diagonal(Al);
    L.x = L.b = L.r = Vector::Zero(n);
    if (n <= options_.coarse_size || static_cast<int>(l) + 1 >= options_.max_levels) break;
    std::vector<int> aggregate_of_node;
    const int aggregates = aggregate(strength_graph(Al, B.node, theta), aggregate_of_node);
    NearNullSpace coarse;
    const SparseMatrix P0 = tentative_prolongator(B, aggregate_of_node, aggregates, coarse);
    if (P0.cols() >= n) break; // no coarsening left
    // Prolongator smoothing (Vanek et al., eq. 4.3): P = (I - omega D^-1 A) P0,
    // omega = 4/3 / rho(D^-1 A).
    const double omega = 4.0 / 3.0 / spectral_radius(Al, L.inv_diagonal, options_.power_iterations);
    const SparseMatrix AP0 = Al * P0;
    L.P = P0 - (omega * L.inv_diagonal).asDiagonal() * AP0;
    L.R = L.P.transpose();
    const SparseMatrix Ac = L.R * (Al * L.P); // Galerkin, P^T A P
    const SparseMatrix At = Ac.transpose();
    Level next;
    next.A = 0.5 * (Ac + At); // symmetric to round-off: the V-cycle is then symmetric
    B = std::move(coarse);
    theta *= 0.5;
    levels_.push_back(std::move(next)); // L and Al are not used past here
  }
  coarsest_.compute(op(levels_.size() - 1));
  if (coarsest_.info() != Eigen::Success)
    throw RunError("linear solver cg_amg: the coarsest level's factorisation failed (" +
                   std::to_string(op(levels_.size() - 1).rows()) + " dofs)");
}

void SmoothedAggregation::refresh(const SparseMatrix& A, const NearNullSpace& near_null_space) {
  if (levels_.size() < 2 || A.rows() != op(0).rows()) return setup(A, near_null_space);
  A0_ = &A;
  levels_[0].inv_diagonal = inverse_diagonal(A);
}

void SmoothedAggregation::cycle(std::size_t l) {
  Level& L = levels_[l];
  if (l + 1 == levels_.size()) {
    L.x = coarsest_.solve(L.b);
    return;
  }
  const SparseMatrix& A = op(l);
  L.x.setZero();
  symmetric_gauss_seidel(A, L.inv_diagonal, L.b, L.x);
  L.r = L.b;
  L.r.noalias() -= A * L.x;
  levels_[l + 1].b.noalias() = L.R * L.r;
  cycle(l + 1);
  L.x.noalias() += L.P * levels_[l + 1].x;
  symmetric_gauss_seidel(A, L.inv_diagonal, L.b, L.x);
}

void SmoothedAggregation::apply(const Vector& r, Vector& z) {
  levels_[0].b = r;
  cycle(0);
  z = levels_[0].x;
}

std::vector<Eigen::Index> SmoothedAggregation::level_sizes() const {
  std::vector<Eigen::Index> sizes;
  for (std::size_t l = 0; l < levels_.size(); ++l) sizes.push_back(op(l).rows());
  return sizes;
}

double SmoothedAggregation::operator_complexity() const {
  double nonzeros = 0.0;
  for (std::size_t l = 0; l < levels_.size(); ++l)
    nonzeros += static_cast<double>(op(l).nonZeros());
  return nonzeros / static_cast<double>(op(0).nonZeros());
}

} // namespace fsi::fem
