#pragma once
// The energy balance of a solid, in J per unit thickness, for either solid solver.
namespace fsi::materials {

struct SolidEnergies {
  double kinetic = 0.0;       ///< v^T M v / 2 (FEM), sum m v^2 / 2 (particles)
  double strain = 0.0;        ///< integral of W(E) over the reference volume
  double gravity_work = 0.0;  ///< work done by gravity, f_g . u
  double external_work = 0.0; ///< integral of the external (interface) loads . du
  /// Conserved by an energy-conserving integrator (Newmark beta = 1/4, gamma = 1/2 to the Newton
  /// tolerance; velocity Verlet to O(dt^2)) without damping.
  double total() const { return kinetic + strain - gravity_work - external_work; }
};

} // namespace fsi::materials
