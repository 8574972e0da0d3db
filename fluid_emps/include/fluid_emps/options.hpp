#pragma once
// Options of the EMPS fluid (Mitsume 2023, eqs. 7-27): a plain struct, filled by the caller, and
// its keys declared once (visit_options) for readers such as the scene file.
#include "fsi/core/options.hpp"
#include "fsi/core/types.hpp"

#include <algorithm>

namespace fsi::emps {

enum class WallCondition { no_slip, slip };

/// The wall part of pnd. added: n_i + z(r) (eq. 20), z for the rest lattice. scaled: the virtual
/// particles compressed like the fluid next to them, n_i + z max(1, n_i / (n0 - z)): equal to
/// eq. 20 at rest and in expansion (a sparse particle near a wall keeps its wall push), and in
/// compression the fluid part extrapolated over the whole support.
enum class WallDensity { added, scaled };

/// Contact of particles with walls (issue 16).
/// paper: the repulsive term of eq. 27 alone.
/// damped: eq. 27 plus a damper on the wall-normal velocity relative to the wall within l0,
///   rho/dt (1 - exp(-gamma dt)) (u_i - v_wall).n n in the units of grad p, gamma =
///   wall_damping (c / l0) (1 - r / l0); a wall force (sent to the structure with f_rep).
/// viscous: eq. 27 plus the closing-pair viscosity alpha c l0 (alpha = wall_viscosity) on
///   pairs with a particle within r_e of a wall only (fluid-fluid, momentum kept).
enum class WallContact { paper, damped, viscous };

/// p_i' of the mirror pressure terms (eqs. 25-26).
/// own: p_i' = p_i (eq. 26).
/// neighbours: a free-surface particle (p_i = 0) within r_e of a wall takes the Shepard mean of
///   its neighbours' pressure, p_i' = sum_j p_j w_ij / sum_j w_ij: the wall pushes back on a
///   particle pressed against it by the pressure around it (a wall force, sent to the structure).
enum class WallPressure { own, neighbours };

/// The wall model's presets (key wall_model): every wall term and value but alpha_rep (the scene's
/// coefficient of eq. 27, as in the paper), and the artificial viscosity of the fluid beside them.
/// paper: Mitsume 2023 as printed (eqs. 18-27, with the corner faces and convex corners).
/// standard (key "default"): the paper's plus the compressed wall density, the far-side images
/// left out of the mirror sums, the approach viscosity 0.5, the wall-gap step limit 0.5 and the
/// artificial viscosity 0.2 (docs/fluid_emps.md, "The wall model": what each fixes, its evidence
/// so far; it is being validated on every scene).
enum class WallModel { paper, standard };

/// The wall part of pnd (eq. 20).
struct WallPndOptions {
  WallDensity density = WallDensity::added;
};

/// The mirror terms (eqs. 23-26) and the approach viscosity across the wall.
struct MirrorOptions {
  WallCondition condition = WallCondition::no_slip; ///< the mirror velocity of eq. 24
  WallPressure pressure = WallPressure::own;        ///< p_i' of eqs. 25-26
  /// The mirror sums over the real neighbours of x_i' on the particle's side of its wall only,
  /// (x_j - x_wall) . n_wall >= 0. false: every neighbour within r_e, as in the paper, which
  /// across a wall thinner than about 2 r_e reflects the fluid on the far side into the
  /// particle's own side.
  bool same_side = false;
  /// alpha_w of the closing-pair viscosity alpha_w c l0 between a particle and the mirror images
  /// of its neighbours that close in across a wall (a wall force; 0: off).
  double approach_viscosity = 0.0;
};

/// Contact of particles with walls: the repulsive term (eq. 27) and what WallContact adds.
struct WallContactOptions {
  double alpha_rep = 0.0; ///< repulsive coefficient of eq. 27, N/m^3
  WallContact model = WallContact::paper;
  double damping = 1.0;    ///< damped: gamma in units of c / l0
  double viscosity = 0.05; ///< viscous: alpha of the near-wall closing-pair viscosity
};

/// The wall model: which faces act on a particle and the options of each wall term.
struct WallOptions {
  /// The preset the terms below and the artificial viscosity start from (apply_wall_preset);
  /// each key read after it overrides one term.
  WallModel model = WallModel::paper;
  /// At concave corners also apply the other faces (z, mirror terms and repulsion of the nearest
  /// other face, geometry_erp's corner faces). false: the paper's nearest wall only (eq. 18),
  /// which leaks particles into 90-degree tank corners.
  bool corner_faces = true;
  /// At convex corners count the solid's own virtual lattice (a wedge) in pnd and in the wall
  /// pressure term, not the half-plane that eqs. 20 and 25 assume. false: the paper's equations,
  /// which over-count pnd by up to 17 % of n0 beside a right-angle convex corner and drive a jet
  /// away from it.
  bool convex_corners = true;
  WallPndOptions pnd;
  MirrorOptions mirror;
  WallContactOptions contact;
  /// C_gap: a step closes at most C_gap of any particle's gap to a wall it approaches,
  /// dt <= C_gap r / (-(v - v_wall) . n_wall) (0: off, the Courant and viscous limits alone).
  double gap_courant = 0.0;
};

template <int D> struct BasicFluidOptions {
  double density = 1000.0;  ///< rho, kg/m^3
  double viscosity = 0.0;   ///< kinematic nu, m^2/s; 0 skips the viscous loop entirely
  double l0 = 0.0;          ///< initial particle spacing, m
  double re_over_l0 = 3.1;  ///< effective radius r_e / l0
  double sound_speed = 0.0; ///< c of eq. 15, m/s
  double beta = 1.0;        ///< free-surface threshold n* < beta n0 (eq. 17)
  /// alpha of an artificial viscosity alpha c l0 on closing pairs (not in the paper; 0: off).
  double artificial_viscosity = 0.0;
  WallOptions wall;
  VecD<D> gravity = VecD<D>::Zero();
  double damping_time = 0.0; ///< T_d: velocities damped at rate 20/T_d (1 - t/T_d) for t < T_d
  VecD<D> domain_min = VecD<D>::Zero(), domain_max = VecD<D>::Zero(); ///< outside: removed
  /// (D = 3) The particles wrap along z over the domain's z range, the period (no particle is
  /// removed along z): particles::PeriodicImages. The caller gives walls that run through it.
  bool periodic_z = false;
  int reorder_interval = 1;   ///< neighbour-list builds between reorderings of particles by cell
  double skin = 0.15;         ///< neighbour-list margin, fraction of r_e
  bool vector_kernels = true; ///< AVX-512 pair sums and list build where the CPU has them

  double r_e() const { return re_over_l0 * l0; }
  /// V_i = l0^d (eq. 43)
  double volume() const {
    if constexpr (D == 2)
      return l0 * l0;
    else
      return l0 * l0 * l0;
  }
  /// The largest alpha of a closing pair's viscosity alpha c l0: a fluid pair's artificial one
  /// (with the near-wall contact's added on pairs near a wall), a pair across a wall's approach
  /// one. The viscous time-step limit takes every closing pair at it (stable_dt).
  double pair_viscosity_alpha() const {
    const double contact =
        wall.contact.model == WallContact::viscous ? wall.contact.viscosity : 0.0;
    return std::max(artificial_viscosity + contact, wall.mirror.approach_viscosity);
  }
  /// Whether the step runs its viscous loop (eqs. 11, 24, and the closing-pair viscosities).
  bool viscous_loop() const { return viscosity > 0 || pair_viscosity_alpha() > 0; }
};
using FluidOptions = BasicFluidOptions<2>;
using FluidOptions3 = BasicFluidOptions<3>;

/// The options a user sets, each once: key, member, range, doc; the member's initial value is the
/// default (density, l0 and sound_speed have none). Gravity, domain, periodic_z, reordering, the
/// list skin and the vector kernels are set by the caller. A visitor that changes `wall_model` (a
/// reader) sets its preset (apply_wall_preset) before it visits the keys the preset covers, which
/// override it.
template <int D> void visit_options(BasicFluidOptions<D>& options, OptionVisitor& visitor);
/// Sets every wall term but alpha_rep, and the artificial viscosity, to the preset `model`'s.
template <int D> void apply_wall_preset(BasicFluidOptions<D>& options, WallModel model);

} // namespace fsi::emps
