#pragma once
// Newmark-beta time integration (eqs. 40-41).
#include "structure_fem/types.hpp"

namespace fsi::fem {

struct NewmarkOptions {
  /// beta_NB > 0. Unconditionally stable for beta >= (gamma + 1/2)^2 / 4; the paper's default
  /// 0.3025 = (0.6 + 0.5)^2 / 4 with gamma = 0.6 damps high frequencies. 1/4 with gamma = 1/2 is
  /// the energy-conserving trapezoidal rule.
  double beta = 0.3025;
  /// gamma_NB >= 1/2 (gamma > 1/2 adds numerical damping).
  double gamma = 0.6;
};

/// Throws InputError naming the field, its value and the allowed range.
void validate(const NewmarkOptions& options);

/// The Newmark relations for one step of size dt from (u, v, a) at t^n.
struct Newmark {
  double beta, gamma, dt;

  /// d a^{n+1} / d u^{n+1} = 1 / (beta dt^2): the mass factor in the effective tangent.
  double mass_factor() const { return 1.0 / (beta * dt * dt); }
  /// a^{n+1} from u^{n+1}: eq. (40) solved for a^{n+1}.
  Vector acceleration(const Vector& u_next, const Vector& u, const Vector& v,
                      const Vector& a) const {
    return (u_next - u - dt * v - (0.5 - beta) * dt * dt * a) / (beta * dt * dt);
  }
  /// v^{n+1}, eq. (41).
  Vector velocity(const Vector& a_next, const Vector& v, const Vector& a) const {
    return v + (1.0 - gamma) * dt * a + gamma * dt * a_next;
  }
};

} // namespace fsi::fem
