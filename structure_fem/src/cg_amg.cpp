#include "cg_amg.hpp"

#include <sstream>

#include "fsi/core/error.hpp"
#include "structure_fem/smoothed_aggregation.hpp"

namespace fsi::fem {

namespace {

SmoothedAggregationOptions amg_options(const LinearSolverOptions& o) {
  SmoothedAggregationOptions a;
  a.coarse_size = o.amg_coarse_size;
  return a;
}

/// Preconditioned CG (Hestenes & Stiefel 1952; Saad, Iterative Methods, alg. 9.1) with the
/// V-cycle as M^-1, stopped at ||b - K x|| <= tolerance ||b|| as Eigen's ConjugateGradient.
class CgAmg final : public LinearSolver {
public:
  explicit CgAmg(const LinearSolverOptions& o)
      : tolerance_(o.cg_tolerance), max_iterations_(o.cg_max_iterations),
        rebuild_ratio_(o.amg_rebuild_ratio), amg_(amg_options(o)) {}
  void analyze(const SparseMatrix&) override {}
  void set_near_null_space(const NearNullSpace& b) override {
    modes_ = b;
    fresh_iterations_ = 0; // rebuild at the next factorize
  }
  void factorize(const SparseMatrix& K) override {
    if (modes_.node.size() != static_cast<std::size_t>(K.rows()))
      throw RunError("linear solver cg_amg: the rigid-body modes are for " +
                     std::to_string(modes_.node.size()) + " dofs, K has " +
                     std::to_string(K.rows()) + " (set_near_null_space before factorize)");
    K_ = &K;
    // A lagged hierarchy while the last solve on it stayed within rebuild_ratio_ of its first.
    if (fresh_iterations_ > 0 && K.rows() == r_.size()) {
      amg_.refresh(K, modes_);
      return;
    }
    amg_.setup(K, modes_);
    ++setups_;
    fresh_iterations_ = -1; // the next solve's count is the hierarchy's reference
    r_ = z_ = p_ = q_ = Vector::Zero(K.rows());
  }
  Vector solve(const Vector& b) override {
    const SparseMatrix& K = *K_;
    Vector x = Vector::Zero(b.size());
    const double b_norm = b.norm();
    const int max_iterations =
        max_iterations_ > 0 ? max_iterations_ : 2 * static_cast<int>(b.size());
    r_ = b;
    iterations_ = 0;
    double residual = b_norm;
    if (b_norm == 0.0) return x;
    amg_.apply(r_, z_);
    p_ = z_;
    double rz = r_.dot(z_);
    while (iterations_ < max_iterations) {
      q_.noalias() = K * p_;
      const double alpha = rz / p_.dot(q_);
      x += alpha * p_;
      r_ -= alpha * q_;
      ++iterations_;
      residual = r_.norm();
      if (residual <= tolerance_ * b_norm) {
        judge_hierarchy();
        return x;
      }
      amg_.apply(r_, z_);
      const double rz_next = r_.dot(z_);
      p_ = z_ + (rz_next / rz) * p_;
      rz = rz_next;
    }
    fresh_iterations_ = 0; // a retry starts from a new hierarchy
    std::ostringstream s;
    s << "linear solver cg_amg: no convergence after " << iterations_
      << " iterations (relative residual " << residual / b_norm << ", tolerance " << tolerance_
      << ")";
    throw RunError(s.str());
  }
  int iterations() const override { return iterations_; }
  long setups() const override { return setups_; }

private:
  /// The first solve on a new hierarchy sets the reference count; a later one above
  /// rebuild_ratio_ times it (or any, with ratio 0) has the next factorize() rebuild.
  void judge_hierarchy() {
    if (fresh_iterations_ < 0)
      fresh_iterations_ = rebuild_ratio_ > 0.0 ? iterations_ : 0;
    else if (iterations_ > rebuild_ratio_ * fresh_iterations_)
      fresh_iterations_ = 0;
  }

  double tolerance_;
  int max_iterations_;
  double rebuild_ratio_;
  NearNullSpace modes_;
  const SparseMatrix* K_ = nullptr;
  SmoothedAggregation amg_;
  Vector r_, z_, p_, q_;
  int iterations_ = 0;
  long setups_ = 0;
  /// Iterations of the first solve on the current hierarchy; -1: none yet, 0: rebuild.
  int fresh_iterations_ = 0;
};

} // namespace

std::unique_ptr<LinearSolver> make_cg_amg(const LinearSolverOptions& options) {
  return std::make_unique<CgAmg>(options);
}

} // namespace fsi::fem
