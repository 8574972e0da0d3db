#pragma once
// Options of the Riemann-SPH fluid (RKGC paper, eqs. 1-5, 15-24; ../shared/sph-method-notes.md):
// a plain struct filled by the caller, checked by validate() before anything is computed.
#include "fsi/core/options.hpp"
#include "fsi/core/types.hpp"

#include <array>
#include <string>

namespace fsi::sph {

/// none: standard Riemann-SPH (B = I). rkgc: reverse kernel gradient correction on the central
/// pressure term (eqs. 18-20) with the WKGC weighting (eqs. 21-22).
enum class Correction { none, rkgc };

/// Channel inflow (RKGC paper sec. 3.2, eqs. 25-26, as the reference code runs Turek-Hron FSI2):
/// the domain is periodic in x and the fluid particles in the buffer
/// [domain_min.x, domain_min.x + buffer) get the velocity (U(y, t), 0) after each acoustic step,
/// U = 1.5 Ubar(t) 4 (y - y_min)(y_max - y) / (y_max - y_min)^2 (eq. 25),
/// Ubar = 0.5 U0 (1 - cos(pi t / ramp_time)) for t < ramp_time, else U0 (eq. 26).
/// Particles leaving at domain_max.x come back through the buffer.
struct Inflow {
  double buffer = 0.0;             ///< buffer length, m (0: no inflow)
  double velocity = 0.0;           ///< U0, the mean velocity over the channel height, m/s
  double ramp_time = 0.0;          ///< t_s of eq. 26, s (0: U0 from the start)
  double y_min = 0.0, y_max = 0.0; ///< the channel walls, m

  bool on() const { return buffer > 0.0; }
  /// U(y, t) of eqs. 25-26 (0 outside [y_min, y_max]).
  double profile(double y, double t) const;
};

/// The fluid's options in D = 2 or 3 dimensions (gravity and domain D-vectors; the inflow buffer
/// is 2-D only).
template <int D> struct BasicSphOptions {
  double rho0 = 1000.0;   ///< reference density, kg/m^3
  double c0 = 0.0;        ///< artificial sound speed of p = c0^2 (rho - rho0) (eq. 2), m/s
  double dp = 0.0;        ///< initial particle spacing, m
  double h_over_dp = 1.3; ///< h = 1.3 dp (method notes, "Kernel and resolution")
  double viscosity = 0.0; ///< kinematic nu, m^2/s (eq. 3's viscous term; 0 skips it)
  VecD<D> gravity = VecD<D>::Zero();
  Correction correction = Correction::rkgc;
  /// true: the low-dissipation limiter of eq. 5, beta = min(3 max(u / c0, 0), 1). false: beta = 1,
  /// the full linearised Riemann dissipation (settling runs: with the limiter a hydrostatic tank
  /// keeps its noise, docs/fluid_sph.md).
  bool riemann_limiter = true;
  /// Eq. 5's dissipation between fluid pairs in the momentum equation. false: the central
  /// pressure term alone between fluid pairs, as the reference code runs its viscous internal
  /// flows (Taylor-Green, Turek-Hron FSI2: no Riemann solver in the momentum equation); the walls
  /// keep theirs (eq. 15) and the continuity equation its pressure-difference term.
  bool pair_dissipation = true;
  double wkgc_alpha = 0.3; ///< alpha of eq. 22 (0: B unweighted), in [0, 1]; one per case
  /// true: free-surface flow, rho = max(rho_sum, rho0) and V = dp^2 at each re-initialisation.
  /// false: internal flow, rho = rho_sum and V = m / rho.
  bool free_surface = true;
  /// Transport-velocity shift once per advection step (eqs. 23-24; internal flows only).
  bool transport_velocity = false;
  double transport_coefficient = 0.2; ///< Delta r = coefficient h^2 (...) (method notes, eq. 24)
  double u_ref = 0.0;          ///< reference speed of the advection criterion, m/s (0: c0 / 10)
  double advection_cfl = 0.25; ///< Dt = advection_cfl h / max(...)
  /// Dt <= viscous_number h^2 / nu as well (the explicit viscous term's diffusion number, Morris
  /// et al. 1997's 0.125; 0: off, the reference code's nu / h in the max alone).
  double viscous_number = 0.125;
  double acoustic_cfl = 0.6; ///< dt = acoustic_cfl h / max(...)
  double fixed_dt = 0.0;     ///< > 0: every acoustic step is fixed_dt (Dt a whole number of them)
  /// Domain: periodic directions use it as the period [min, max); otherwise a fluid particle
  /// leaving it is removed and counted.
  VecD<D> domain_min = VecD<D>::Zero(), domain_max = VecD<D>::Zero();
  bool periodic_x = false, periodic_y = false;
  bool periodic_z = false; ///< D = 3 only
  std::array<bool, D> periodic() const {
    if constexpr (D == 2)
      return {periodic_x, periodic_y};
    else
      return {periodic_x, periodic_y, periodic_z};
  }
  /// Artificial damping for settling runs (hydrostatic): for t < damping_time the velocities are
  /// damped at rate 20 / T_d (1 - t / T_d) after each acoustic step (0: off).
  double damping_time = 0.0;
  Inflow inflow{}; ///< channel inflow buffer (needs periodic_x; 2-D only)
  /// Density guard: a RunError names the particle when rho leaves [lo, hi] rho0.
  double rho_min_factor = 0.5, rho_max_factor = 1.5;

  double h() const { return h_over_dp * dp; }
  /// dp^D, a lattice particle's volume.
  double cell_volume() const {
    if constexpr (D == 2)
      return dp * dp;
    else
      return dp * dp * dp;
  }
  double mass() const {
    if constexpr (D == 2)
      return rho0 * dp * dp;
    else
      return rho0 * dp * dp * dp;
  }
  /// u_ref, or c0 / 10 where it is 0 (c0 = 10 U_ref, method notes).
  double u_advection() const { return u_ref > 0.0 ? u_ref : 0.1 * c0; }
  /// Throws fsi::InputError naming the option, its value and the allowed range.
  void validate() const;
};

extern template struct BasicSphOptions<2>;
extern template struct BasicSphOptions<3>;

using SphOptions = BasicSphOptions<2>;
using SphOptions3 = BasicSphOptions<3>;

std::string to_string(Correction c);

/// The keys a user sets, each once (density, l0 and sound_speed are required;
/// fsi/core/options.hpp), the same in 2-D and 3-D.
template <int D> void visit_options(BasicSphOptions<D>& options, OptionVisitor& visitor);
extern template void visit_options<2>(SphOptions&, OptionVisitor&);
extern template void visit_options<3>(SphOptions3&, OptionVisitor&);

} // namespace fsi::sph
