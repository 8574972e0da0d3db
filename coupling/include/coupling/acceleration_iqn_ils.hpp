#pragma once
// Acceleration "iqn-ils": interface quasi-Newton with an approximation of the inverse Jacobian
// from a least-squares model (Degroote, Bathe & Vierendeels 2009, Comput. Struct. 87:793-801).
//
//   r^i = x~^i - x^i.  Columns (newest first): V = [r^i - r^{i-1}, ...], W = [x~^i - x~^{i-1}, ...]
//   from the current step and from the last `reuse` converged steps.
//   c = argmin ||V c + r^i||  (scaled; QR of V by modified Gram-Schmidt with re-orthogonalisation)
//   x^{i+1} = x~^i + W c.
// With no column yet (first iteration of the first step, or reuse = 0) the update is a constant
// relaxation x^i + omega r^i. Filter (QR2, as in preCICE): a column whose component orthogonal to
// the newer kept columns is below `filter` times its own norm is deleted for good. Columns are
// capped at the vector length (oldest dropped first). Columns of a step that did not converge
// are discarded at end_step(false).
// On a linear map x -> A x + b in R^n (I - A nonsingular) it behaves like GMRES and converges in
// at most n + 1 updates.
#include <deque>

#include "coupling/acceleration.hpp"

namespace fsi::coupling {

class IqnIlsAcceleration final : public Acceleration {
public:
  IqnIlsAcceleration(double omega_init, int reuse, double filter);
  void begin_step(const Eigen::VectorXd& scale) override;
  void update(const Eigen::VectorXd& x, const Eigen::VectorXd& x_tilde,
              Eigen::VectorXd& x_next) override;
  void end_step(bool converged) override;
  void write_state(StateArchive& archive, const std::string& prefix) const override;
  void read_state(const StateArchive& archive, const std::string& prefix) override;
  std::optional<double> relaxation() const override { return relaxation_; }

  /// Columns currently stored (after filtering), for tests and logs.
  std::size_t columns() const { return columns_.size(); }

private:
  struct Column {
    Eigen::VectorXd dr, dx_tilde; // unscaled differences
    long step;                    // coupling step that produced the column
  };
  double omega_init_;
  int reuse_;
  double filter_;
  Eigen::VectorXd scale_;
  std::deque<Column> columns_; // newest first
  Eigen::VectorXd r_prev_, x_tilde_prev_;
  bool has_prev_ = false;
  long step_ = 0;
  std::optional<double> relaxation_;
};

} // namespace fsi::coupling
