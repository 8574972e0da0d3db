#pragma once
// The explicit MPS fluid (EMPS) with ERP polygon walls (Mitsume 2023, eqs. 7-27).
//
// One step from t to t + dt (method notes, "EMPS step"):
//   1. v* = v + dt (nu <lap v>^ERP + g),  x* = x + dt v*          (eq. 13, viscous term eq. 24)
//   2. n*_i = sum_j w_ij + z(r_wall,i)  at x*                       (eqs. 9, 20)
//      p_i = c^2 rho / n0 (n*_i - n0), and p_i = 0 where n*_i < beta n0   (eqs. 15, 17)
//   3. v^{n+1} = v* - dt/rho <grad p>^ERP,  x^{n+1} = x* + dt (v^{n+1} - v*)   (eqs. 14, 25-27)
// n0 and lambda0 come from the full initial lattice (eqs. 9, 12), not from each particle.
//
// Walls: the caller owns the WallSet and moves its nodes (rigid motion, FE interface) to their
// state at t + dt before calling advance(); the fluid refits its wall index each step.
//
// Written once for D = 2 and 3 (docs/architecture.md, "Two and three dimensions"): the
// fluid-fluid terms, the time integration, the diagnostics and the state are D-generic; the ERP
// walls are segments (WallSet, WallTerms) in 2-D and triangles (TriangleWallSet, SpaceWallTerms)
// in 3-D (their nodes moved by the caller, as 2-D's); the 3-D wall forces of eq. 52 in slots per
// face, convex piece and viscous face (WallForces3).
#include "fluid_emps/options.hpp"
#include "fluid_emps/pair_sums.hpp"
#include "fluid_emps/particles.hpp"
#include "fluid_emps/space_wall_terms.hpp"
#include "fluid_emps/wall_terms.hpp"
#include "geometry_erp/lattice_spectrum.hpp"
#include "geometry_erp/triangle_locator.hpp"
#include "geometry_erp/triangle_wall_set.hpp"
#include "geometry_erp/wall_locator.hpp"
#include "geometry_erp/wall_set.hpp"
#include "geometry_erp/wall_weight.hpp"
#include "particles/cell_grid.hpp"
#include "particles/decomposition.hpp"
#include "particles/kernels.hpp"
#include "particles/neighbor_list.hpp"
#include "particles/periodic_images.hpp"
#include "particles/setup_block.hpp"

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace fsi {
class StateArchive;
}

namespace fsi::emps {

/// Per-particle wall force of the last step on one face (eq. 52, wall parts only: the two mirror
/// terms and the repulsive term, times V_i). The structure receives -f at x_wall on `segment`
/// (-1 where the particle has no such face). f = f_pressure + f_contact + f_viscous: f_contact is
/// V times the contact term (eq. 27, with the wall-normal damping of WallContact::damped),
/// f_viscous the viscous mirror term (eq. 24, with wall_approach_viscosity's term); the rest is
/// the pressure mirror term (eqs. 25-26).
struct FaceForces {
  std::vector<int> segment;
  std::vector<double> t; ///< local coordinate of x_wall on the segment
  std::vector<Vec2> x_wall, f, f_contact, f_viscous;
  void resize(std::size_t n) {
    segment.resize(n);
    t.resize(n);
    for (auto* v : {&x_wall, &f, &f_contact, &f_viscous}) v->resize(n);
  }
};

/// The wall forces of every face a particle has (erp::WallHits: face 0 the nearest wall, the
/// others those of a concave corner).
struct WallForces {
  std::array<FaceForces, erp::max_faces> face;
  void resize(std::size_t n) {
    for (FaceForces& f : face) f.resize(n);
  }
  std::size_t size() const { return face[0].segment.size(); }
};

/// The force of the fluid on a set of wall segments (what the walls receive, -sum f), N per m
/// of depth, split by the wall term that carries it (eq. 52).
struct WallForceParts {
  Vec2 pressure = Vec2::Zero();  ///< mirror pressure terms (eqs. 25-26, convex corners incl.)
  Vec2 repulsive = Vec2::Zero(); ///< repulsive term (eq. 27) and wall-normal damping
  Vec2 viscous = Vec2::Zero();   ///< viscous mirror term (eq. 24), approach viscosity
  Vec2 total() const { return pressure + repulsive + viscous; }
};

/// Wall seconds of each part of the step so far, for benchmarks and run.json: each part net of
/// the waits in MPI collectives within it, which are summed in `waited` (0 on one process).
struct StepTimes {
  double neighbours = 0, walls = 0, viscosity = 0, density = 0, pressure_gradient = 0, other = 0;
  double waited = 0;
  /// This process's own work: every part, its waits left out.
  double busy() const {
    return neighbours + walls + viscosity + density + pressure_gradient + other;
  }
};

/// The 2-D fluid's walls: the wall index, its hits, the wall terms and the wall forces.
struct PlaneWalls {
  /// Registers `viscous` in the particles' set.
  PlaneWalls(const FluidOptions& options, double n0, erp::WallSet& walls, Particles& particles,
             const particles::CellGrid& grid);
  std::unique_ptr<erp::WallLocator> locator;
  erp::WallHits hits;
  WallTerms terms; ///< the wall terms over the fluid's particles, grid and `hits`
  WallForces forces;
  /// The viscous wall force of each face, N/m: scratch arrays of the particles' set, so that
  /// they move with the particles between the viscous and the pressure stage of a step.
  std::array<particles::VectorField<2>, erp::max_faces> viscous;
  long hits_layout = -1; ///< the fluid's layout when `hits` were computed (-1: stale)
};

/// The 3-D fluid's walls: triangles (static or moved by the caller, as `walls_move` says from the
/// start), their index, the hits of up to three faces (the nearest triangle, the other planes of
/// a concave edge or corner), the convex pieces, the wall terms and the wall forces (eq. 52, per
/// face and piece: wall_slots3).
struct SpaceWalls {
  SpaceWalls(const FluidOptions3& options, double n0, const erp::TriangleWallSet& walls,
             bool walls_move, const Particles3& particles, const particles::BasicCellGrid<3>& grid);
  SpaceWalls(const SpaceWalls&) = delete; // before's locator points at its walls
  SpaceWalls& operator=(const SpaceWalls&) = delete;
  /// The walls as the step starts (t^n), for the viscous stage at x^n (2-D reuses the last x*
  /// hits, taken with the walls at t^n): `before`'s when the walls move, else `locator`.
  const erp::TriangleLocator& at_step_start() const { return moving() ? before->locator : locator; }
  /// Moving walls: sets `before` to `nodes` (the next step's t^n, restore, a checkpoint) and
  /// refits its index; static walls: nothing (the walls are their own t^n).
  void set_step_start(const erp::TriangleWallNodes& nodes);
  /// A copy of the caller's walls at t^n and its index.
  struct StepStart {
    StepStart(const erp::TriangleWallSet& caller, double r_e)
        : walls(caller), locator(walls, r_e) {}
    erp::TriangleWallSet walls;
    erp::TriangleLocator locator;
  };
  erp::TriangleLocator locator;
  std::optional<StepStart> before; ///< moving walls only
  /// The caller moves the walls' nodes (refit every step), else never.
  bool moving() const { return before.has_value(); }
  SpaceHits hits;
  erp::ConvexFaces convex; ///< the convex edges' and corners' planes (with convex_corners)
  SpaceWallTerms terms;
  WallForces3 forces;
  bool corner_faces, convex_corners;
};

template <int D> using EmpsWalls = std::conditional_t<D == 2, PlaneWalls, SpaceWalls>;

template <int D> class BasicEmpsFluid {
public:
  using Vec = VecD<D>;
  using Options = BasicFluidOptions<D>;
  using ParticleSet = BasicParticles<D>;

  /// Particles start at rest at `positions`. Throws fsi::InputError on invalid options.
  /// `block`: the positions are one process's block of the fill (ids from block.first); with
  /// block.deferred the start (neighbours, initial pnd and pressures) waits for decompose().
  BasicEmpsFluid(const Options& options, const std::vector<Vec>& positions, erp::WallSet& walls,
                 const particles::SetupBlock& block = {}) requires(D == 2);
  /// With triangle walls (3-D), which must outlive the fluid; a caller that moves their nodes
  /// calls walls.update() before advance() (which refits the triangle index), as the coupled
  /// interfaces do (apps: TriangleAdapter). An empty set: no walls. `walls_move` false: the
  /// caller never moves them (the fluid neither refits their index nor keeps them at t^n).
  BasicEmpsFluid(const Options& options, const std::vector<Vec>& positions,
                 const erp::TriangleWallSet& walls, bool walls_move = true,
                 const particles::SetupBlock& block = {}) requires(D == 3);
  /// Initial velocities, one per owned particle in the current order (before the first
  /// advance()).
  void set_velocities(const std::vector<Vec>& v);
  ~BasicEmpsFluid() = default;

  /// Steps from now on decomposed over processes through `decomposition`, which must outlive
  /// the fluid (collective). On entry each process holds its block of the fill, not started
  /// (SetupBlock::deferred: the start follows the first partition), or the same whole fluid
  /// (it keeps its block first, particles/setup_block.hpp). Without it the fluid is serial
  /// (particles::LocalParticles, or with periodic_z particles::PeriodicImages, which refuses
  /// decompose(): InputError). The exchange points of the step are listed in docs/architecture.md
  /// "Processes (MPI)". After read_state (a restart on any process count), the checkpoint is
  /// partitioned as its run was at its last neighbour-list build (scatter_restored). Decomposed,
  /// save() keeps the owned particles and restore() drops the ghosts (the next step migrates and
  /// builds them afresh); the wall forces are this process's particles' (the caller sums them).
  void decompose(particles::Decomposition<D>& decomposition);
  /// The particles this process owns: the first owned() entries of particles(); ghosts follow.
  std::size_t owned() const { return particles_.size() - decomposition_->ghosts(); }

  /// Advances from t to t + dt. Throws fsi::RunError on a non-finite field, a particle behind a
  /// wall or a neighbour-row overflow, naming the particle, the step and the time.
  void advance(double t, double dt);

  /// Largest stable step for a Courant number: C l0 / (c + |v|max), the viscous limit of the
  /// step's forward-Euler viscous update on the rest lattice, 2 / (2d/(lambda0 n0) (nu P_lap +
  /// alpha c l0 P_closing)) (alpha: pair_viscosity_alpha; P: erp::lattice_laplacian_peak,
  /// erp::lattice_closing_peak), and the wall-gap limit of the last step (wall_gap_courant).
  double stable_dt(double courant) const;
  /// Steps whose dt the wall-gap limit set.
  long gap_limited_steps() const { return gap_limited_steps_; }

  const ParticleSet& particles() const { return particles_; }
  const WallForces& wall_forces() const requires(D == 2);
  /// The last step's wall force of each particle on each of its faces (3-D, TriangleForces).
  const WallForces3& triangle_forces() const requires(D == 3);
  /// The last step's force on segments [first, last) of the WallSet, by part (sequential sum:
  /// the same for every thread count).
  WallForceParts wall_force_parts(int first, int last) const requires(D == 2);
  const Options& options() const { return options_; }
  double n0() const { return n0_; }
  double lambda0() const { return lambda0_; }
  long steps() const { return step_; }
  /// Particles removed from this process's set (outside the domain box).
  std::size_t removed() const { return removed_; }
  double mean_neighbours() const { return mean_neighbours_; }
  long neighbour_builds() const { return builds_; }
  const StepTimes& times() const { return times_; }
  double kinetic_energy() const;
  double max_speed() const;

  /// A full copy of the fluid state; restore() returns to it (iterative coupling re-runs steps;
  /// decomposed: the owned particles, to round-off, the list being rebuilt).
  struct State {
    particles::FieldSet::Snapshot particles;
    long step = 0;
    std::size_t removed = 0;
    long layout = 0;
    double gap_dt = 0.0;
    long gap_limited_steps = 0;
    /// The walls at the step's start (3-D, moving walls: SpaceWalls::before; else empty).
    std::conditional_t<D == 3, erp::TriangleWallNodes, std::monostate> walls_before{};
  };
  State save() const;
  void restore(const State& state);

  /// Checkpoint: everything the next advance() reads (particles with ids, counters, the
  /// neighbour list's build positions, the reusable wall hits) under keys `prefix` + name, so
  /// that a run continued from it is bitwise the run that was not interrupted. Decomposed:
  /// collective, the one-process format in id order, whole on process 0 only.
  void write_state(StateArchive& archive, const std::string& prefix) const;
  /// Throws InputError naming the key when the archive does not fit this fluid. Called before
  /// decompose(): every process reads the whole checkpoint.
  void read_state(const StateArchive& archive, const std::string& prefix);

private:
  /// Decomposed over processes (not the periodic images, which are serial).
  bool decomposed() const { return decomposition_ != &local_ && !periodic_; }
  /// The per-particle part of the checkpoint (owned particles); `listed`: with the list's build
  /// positions, `hits`: with the wall hits (2-D).
  void write_rows(StateArchive& archive, const std::string& prefix, bool listed, bool hits) const;
  void read_rows(const StateArchive& archive, const std::string& prefix, bool hits);
  void write_hits(StateArchive& archive, const std::string& prefix, std::size_t n) const
      requires(D == 2);
  void read_hits(const StateArchive& archive, const std::string& prefix) requires(D == 2);
  /// read_rows with periodic_z: appends the images chosen by the stored build positions
  /// `build` and their build positions; returns the set's new size (emps_state.cpp).
  std::size_t restore_images(std::array<std::vector<double>, D>& build);
  /// decompose() after read_state: the partition of a restart (emps_state.cpp).
  void scatter_restored();
  /// Places the particles at `positions` and computes pnd, pressure and the free-surface flags
  /// of the initial state (for output at t = 0).
  /// With block.deferred only the particles and their wall hits (the first partition's loads):
  /// decompose() completes the start.
  void start(const std::vector<Vec>& positions, const particles::SetupBlock& block);
  /// Refreshes the ghosts' arrays `changed` (empty: every array); rebuilds the neighbour list
  /// (its halo build sends every array) when a particle of any process has moved half the skin
  /// (with `allow_reorder`, migrating and reordering the owned particles first). `step` and `t`
  /// name the step in progress in messages.
  void refresh_neighbours(const particles::FieldList& changed, bool allow_reorder, long step,
                          double t);
  /// The wall hits at the particles' positions; `step_start`: with the walls at t^n (3-D's
  /// viscous stage; the caller has moved its walls to t + dt), else with the caller's walls.
  void query_walls(bool step_start = false);
  /// Stops the run naming the first particle behind its nearest wall.
  void check_crossed(long step, double t) const;
  void viscosity();
  void density_and_pressure();
  void pressure_gradient(double dt);
  /// Particle i's neighbour-list row for the pair sums (pair_sums.hpp).
  BasicPairRow<D> pair_row(std::size_t i) const {
    BasicPairRow<D> row{neighbours_.row(i), neighbours_.count(i), {}, re2_, w_e_.inv_re};
    for (int a = 0; a < D; ++a) row.xi[static_cast<std::size_t>(a)] = particles_.position[a][i];
    return row;
  }
  /// The fluid-fluid part of the pressure gradient on particle i (eq. 10).
  VecSum<D> fluid_gradient(std::size_t i, double* shepard) const;
  void check_finite(long step, double t) const;
  void remove_outside();
  double wall_gap_dt() const;
  void damp(double t, double dt);

  Options options_; // validated by the constructors before anything below reads it
  double r_e_ = options_.r_e();
  double n0_ = erp::lattice_n0<D>(options_.l0, r_e_, particles::MpsWeight(r_e_));
  double lambda0_ = erp::lattice_lambda0<D>(options_.l0, r_e_, particles::MpsWeight(r_e_));
  /// The viscous sums' peak rates on the lattice (stable_dt).
  double laplacian_peak_ =
      erp::lattice_laplacian_peak<D>(options_.l0, r_e_, particles::MpsWeight(r_e_));
  double closing_peak_ =
      erp::lattice_closing_peak<D>(options_.l0, r_e_, particles::MpsWeight(r_e_));
  particles::MpsWeight w_e_{r_e_}; ///< w(r) of eq. 8 at r_e
  double re2_ = r_e_ * r_e_;       ///< r_e^2 (the pair loops test r^2 < r_e^2)
  ParticleSet particles_;
  particles::BasicCellGrid<D> grid_{options_.domain_min, options_.domain_max,
                                    r_e_*(1.0 + options_.skin)};
  particles::BasicNeighborList<D> neighbours_;
  particles::LocalParticles<D> local_;
  std::optional<particles::PeriodicImages<D>> periodic_; ///< with periodic_z
  particles::Decomposition<D>* decomposition_ = &local_; ///< the exchange hook
  EmpsWalls<D> walls_;
  std::vector<double> scratch_; // per-particle work array, D values a particle
  std::vector<std::uint8_t> keep_;
  std::size_t capacity_;
  long step_ = 0, layout_ = 0, builds_ = 0;
  bool restored_ = false; ///< read from a checkpoint, not yet decomposed
  bool started_ = true;   ///< false: a deferred block (SetupBlock), until decompose()
  double gap_dt_ = std::numeric_limits<double>::infinity(); // wall-gap limit for the next step
  long gap_limited_steps_ = 0;
  std::size_t removed_ = 0;
  double mean_neighbours_ = 0.0;
  StepTimes times_;
};
using EmpsFluid = BasicEmpsFluid<2>;
using EmpsFluid3 = BasicEmpsFluid<3>;

} // namespace fsi::emps
