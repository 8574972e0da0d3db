#include "coupling/acceleration_iqn_ils.hpp"

#include "coupling/reduction.hpp"

#include "fsi/core/state_archive.hpp"

#include <cassert>
#include <vector>

namespace fsi::coupling {

IqnIlsAcceleration::IqnIlsAcceleration(double omega_init, int reuse, double filter)
    : Acceleration("iqn-ils"), omega_init_(omega_init), reuse_(reuse), filter_(filter) {}

void IqnIlsAcceleration::begin_step(const Eigen::VectorXd& scale) {
  scale_ = scale;
  has_prev_ = false;
  relaxation_.reset();
}

void IqnIlsAcceleration::update(const Eigen::VectorXd& x, const Eigen::VectorXd& x_tilde,
                                Eigen::VectorXd& x_next) {
  const Eigen::Index n = x.size();
  const Eigen::VectorXd r = x_tilde - x;
  if (has_prev_) columns_.push_front(Column{r - r_prev_, x_tilde - x_tilde_prev_, step_});
  r_prev_ = r;
  x_tilde_prev_ = x_tilde;
  has_prev_ = true;
  while (static_cast<Eigen::Index>(columns_.size()) > n) columns_.pop_back();

  const bool scaled = scale_.size() == n;
  auto scale = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
    return scaled ? Eigen::VectorXd(v.cwiseProduct(scale_)) : v;
  };

  // QR of the scaled V by modified Gram-Schmidt (two passes), newest column first; QR2 filter.
  const auto k_max = static_cast<Eigen::Index>(columns_.size());
  Eigen::MatrixXd q(n, k_max), rr = Eigen::MatrixXd::Zero(k_max, k_max);
  std::vector<std::size_t> kept;
  std::vector<bool> erase(columns_.size(), false);
  for (std::size_t j = 0; j < columns_.size(); ++j) {
    Eigen::VectorXd v = scale(columns_[j].dr);
    const double norm0 = norm(v);
    if (!(norm0 > 0.0)) {
      erase[j] = true;
      continue;
    }
    const auto kk = static_cast<Eigen::Index>(kept.size());
    Eigen::VectorXd h = Eigen::VectorXd::Zero(kk);
    for (int pass = 0; pass < 2; ++pass) {
      for (Eigen::Index i = 0; i < kk; ++i) {
        const double hij = dot(q.col(i), v);
        h(i) += hij;
        v -= hij * q.col(i);
      }
    }
    const double norm_v = norm(v);
    if (!(norm_v >= filter_ * norm0) || norm_v == 0.0) {
      erase[j] = true;
      continue;
    }
    q.col(kk) = v / norm_v;
    rr.block(0, kk, kk, 1) = h;
    rr(kk, kk) = norm_v;
    kept.push_back(j);
  }
  // Delete filtered columns for good (keeps the relative order of the others).
  std::deque<Column> remaining;
  for (std::size_t j = 0; j < columns_.size(); ++j)
    if (!erase[j]) remaining.push_back(std::move(columns_[j]));
  columns_ = std::move(remaining);

  if (kept.empty()) {
    x_next = x + omega_init_ * r;
    relaxation_ = omega_init_;
    return;
  }
  const auto k = static_cast<Eigen::Index>(kept.size());
  // c = argmin ||V c + r||: R c = -Q^T r.
  const Eigen::VectorXd rhs = -transposed_product(q.leftCols(k), scale(r));
  const Eigen::VectorXd c = rr.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(rhs);
  x_next = x_tilde;
  for (Eigen::Index i = 0; i < k; ++i)
    x_next += c(i) * columns_[static_cast<std::size_t>(i)].dx_tilde;
  relaxation_.reset();
}

void IqnIlsAcceleration::end_step(bool converged) {
  if (!converged) std::erase_if(columns_, [&](const Column& c) { return c.step == step_; });
  ++step_;
  // The next step (index step_) reuses steps step_ - reuse .. step_ - 1.
  std::erase_if(columns_, [&](const Column& c) { return c.step < step_ - reuse_; });
  has_prev_ = false;
}

// The reused columns V, W of past steps (newest first, with their step) and the step counter;
// the current step's r_prev_ / x_tilde_prev_ restart with every step.
void IqnIlsAcceleration::write_state(StateArchive& archive, const std::string& prefix) const {
  std::vector<double> dr, dx;
  std::vector<std::int64_t> steps;
  for (const Column& c : columns_) {
    dr.insert(dr.end(), c.dr.data(), c.dr.data() + c.dr.size());
    dx.insert(dx.end(), c.dx_tilde.data(), c.dx_tilde.data() + c.dx_tilde.size());
    steps.push_back(c.step);
  }
  archive.put(prefix + "V", std::move(dr));
  archive.put(prefix + "W", std::move(dx));
  archive.put(prefix + "column_steps", std::move(steps));
  archive.put_integer(prefix + "step", step_);
}

void IqnIlsAcceleration::read_state(const StateArchive& archive, const std::string& prefix) {
  const auto& steps = archive.integers(prefix + "column_steps");
  const auto& dr = archive.reals(prefix + "V");
  const auto& dx = archive.reals(prefix + "W", dr.size());
  if (steps.empty() ? !dr.empty() : dr.size() % steps.size() != 0)
    throw InputError("checkpoint: '" + prefix + "V' does not split into its columns");
  const auto n = static_cast<Eigen::Index>(steps.empty() ? 0 : dr.size() / steps.size());
  columns_.clear();
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const auto offset = static_cast<std::ptrdiff_t>(k) * n;
    columns_.push_back({Eigen::Map<const Eigen::VectorXd>(dr.data() + offset, n),
                        Eigen::Map<const Eigen::VectorXd>(dx.data() + offset, n), steps[k]});
  }
  step_ = archive.integer(prefix + "step");
  has_prev_ = false;
}

} // namespace fsi::coupling
