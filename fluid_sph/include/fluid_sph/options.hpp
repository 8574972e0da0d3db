#pragma once
// Options of the Riemann-SPH fluid (RKGC paper, eqs. 1-5, 15-24; ../shared/sph-method-notes.md):
// a plain struct filled by the caller, checked by validate() before anything is computed.
#include "fsi/core/options.hpp"
#include "fsi/core/types.hpp"

#include <string>

namespace fsi::sph {

/// none: standard Riemann-SPH (B = I). rkgc: reverse kernel gradient correction on the central
/// pressure term (eqs. 18-20) with the WKGC weighting (eqs. 21-22).
enum class Correction { none, rkgc };

struct SphOptions {
  double rho0 = 1000.0;   ///< reference density, kg/m^3
  double c0 = 0.0;        ///< artificial sound speed of p = c0^2 (rho - rho0) (eq. 2), m/s
  double dp = 0.0;        ///< initial particle spacing, m
  double h_over_dp = 1.3; ///< h = 1.3 dp (method notes, "Kernel and resolution")
  double viscosity = 0.0; ///< kinematic nu, m^2/s (eq. 3's viscous term; 0 skips it)
  Vec2 gravity = Vec2::Zero();
  Correction correction = Correction::rkgc;
  /// true: the low-dissipation limiter of eq. 5, beta = min(3 max(u / c0, 0), 1). false: beta = 1,
  /// the full linearised Riemann dissipation (settling runs: with the limiter a hydrostatic tank
  /// keeps its noise, docs/fluid_sph.md).
  bool riemann_limiter = true;
  double wkgc_alpha = 0.3; ///< alpha of eq. 22 (0: B unweighted), in [0, 1]; one per case
  /// true: free-surface flow, rho = max(rho_sum, rho0) and V = dp^2 at each re-initialisation.
  /// false: internal flow, rho = rho_sum and V = m / rho.
  bool free_surface = true;
  /// Transport-velocity shift once per advection step (eqs. 23-24; internal flows only).
  bool transport_velocity = false;
  double transport_coefficient = 0.2; ///< Delta r = coefficient h^2 (...) (method notes, eq. 24)
  double u_ref = 0.0;          ///< reference speed of the advection criterion, m/s (0: c0 / 10)
  double advection_cfl = 0.25; ///< Dt = advection_cfl h / max(...)
  double acoustic_cfl = 0.6;   ///< dt = acoustic_cfl h / max(...)
  double fixed_dt = 0.0;       ///< > 0: every acoustic step is fixed_dt (Dt a whole number of them)
  /// Domain: periodic directions use it as the period [min, max); otherwise a fluid particle
  /// leaving it is removed and counted.
  Vec2 domain_min = Vec2::Zero(), domain_max = Vec2::Zero();
  bool periodic_x = false, periodic_y = false;
  /// Artificial damping for settling runs (hydrostatic): for t < damping_time the velocities are
  /// damped at rate 20 / T_d (1 - t / T_d) after each acoustic step (0: off).
  double damping_time = 0.0;
  /// Density guard: a RunError names the particle when rho leaves [lo, hi] rho0.
  double rho_min_factor = 0.5, rho_max_factor = 1.5;

  double h() const { return h_over_dp * dp; }
  double mass() const { return rho0 * dp * dp; }
  /// u_ref, or c0 / 10 where it is 0 (c0 = 10 U_ref, method notes).
  double u_advection() const { return u_ref > 0.0 ? u_ref : 0.1 * c0; }
  /// Throws fsi::InputError naming the option, its value and the allowed range.
  void validate() const;
};

std::string to_string(Correction c);

/// The keys a user sets, each once (density, l0 and sound_speed are required;
/// fsi/core/options.hpp).
void visit_options(SphOptions& options, OptionVisitor& visitor);

} // namespace fsi::sph
