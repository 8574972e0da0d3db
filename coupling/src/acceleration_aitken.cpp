#include "coupling/acceleration_aitken.hpp"

#include "coupling/reduction.hpp"

#include "fsi/core/state_archive.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::coupling {

AitkenRelaxation::AitkenRelaxation(double omega_init, double omega_max)
    : Acceleration("aitken"), omega_init_(omega_init), omega_max_(omega_max), omega_(omega_init) {}

void AitkenRelaxation::begin_step(const Eigen::VectorXd& scale) {
  scale_ = scale;
  iteration_ = 0;
}

void AitkenRelaxation::update(const Eigen::VectorXd& x, const Eigen::VectorXd& x_tilde,
                              Eigen::VectorXd& x_next) {
  const Eigen::VectorXd r = x_tilde - x;
  Eigen::VectorXd rs = r;
  if (scale_.size() == r.size()) rs = r.cwiseProduct(scale_);

  if (iteration_ == 0) {
    // First factor of the step: the previous step's last factor, bounded by the initial one.
    omega_ = std::copysign(std::min(omega_init_, std::abs(omega_)), omega_);
  } else {
    const Eigen::VectorXd d = rs - r_prev_;
    const double den = squared_norm(d);
    if (den > 0.0) {
      const double w = -omega_ * dot(r_prev_, d) / den; // Kuettler & Wall 2008, eq. (44)
      omega_ = std::isfinite(w) && w != 0.0 ? w : omega_init_;
    }
  }
  if (std::abs(omega_) > omega_max_) omega_ = std::copysign(omega_max_, omega_);

  x_next = x + omega_ * r;
  r_prev_ = rs;
  ++iteration_;
}

// Only the last factor carries over (it bounds the next step's first factor); r_prev_ and the
// iteration count restart with every step.
void AitkenRelaxation::write_state(StateArchive& archive, const std::string& prefix) const {
  archive.put_real(prefix + "omega", omega_);
}

void AitkenRelaxation::read_state(const StateArchive& archive, const std::string& prefix) {
  omega_ = archive.real(prefix + "omega");
}

} // namespace fsi::coupling
