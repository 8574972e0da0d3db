#pragma once
// Weakly compressible Riemann-SPH fluid with reverse kernel gradient correction (RKGC paper,
// eqs. 1-5, 15-24; ../shared/sph-method-notes.md gives the reference code's forms and signs),
// written once for D = 2 and 3 (docs/architecture.md, "Two and three dimensions").
//
// Dual-criteria time stepping (method notes, "Fluid step"). An advection step Dt holds several
// acoustic steps dt; pair data (neighbours, e_ij, dW_ij), the correction matrices B_i, the prior
// acceleration (gravity + viscous) and V_i are frozen over one Dt. Per acoustic step:
//   first half:  rho += drho dt/2, p = c0^2 (rho - rho0), x += v dt/2, v += (F_p/m + a_prior) dt
//   second half: x += v dt/2, drho = continuity (eq. 3), rho += drho dt/2.
// When an acoustic step fills Dt: wrap periodic positions, remove escaped particles, sort by cell,
// rebuild pairs, re-initialise density, B (eqs. 19, 21-22), viscous force, transport-velocity shift
// (eq. 24) and the next Dt.
//
// Pair conventions: e_ij = (r_i - r_j) / r_ij, grad_i W_ij = dW_ij e_ij with dW <= 0.
// Walls: in 2-D polylines with the fluid on the LEFT of each directed segment a -> b, filled with
// 4 layers of dummy particles at dp; in both dimensions wall particles given directly (WallPoint;
// box_walls for a box tank); one-sided Riemann wall (eqs. 15-17, method notes' dummy state).
// What stays 2-D (members requires(D == 2)): polylines, rigid wall motions, the inflow buffer and
// the interface boundary of a 2-D interface mesh (fluid_sph/interface_boundary.hpp).
#include "fluid_sph/options.hpp"
#include "particles/decomposition.hpp"
#include "particles/field_set.hpp"
#include "particles/kernels.hpp"
#include "particles/periodic_grid.hpp"
#include "particles/setup_block.hpp"
#include "particles/vector_field.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace fsi {
class StateArchive;
}

namespace fsi::sph {

/// A rigid wall: points in order (fluid on the left of each segment), open or closed, and a
/// motion group (walls of one group move together; group 0 without a motion is static). 2-D.
struct WallPolyline {
  std::vector<Vec2> points;
  bool closed = false;
  int group = 0;
};

/// Rigid motion of a wall group at time t: a material point X (reference position) is at
/// x = X_c + d + R(theta) (X - X_c), with velocity v_c + omega x r and acceleration
/// a_c + alpha x r - omega^2 r, r = R(theta) (X - X_c). 2-D.
struct RigidMotion {
  Vec2 centre = Vec2::Zero(); ///< X_c, reference
  Vec2 d = Vec2::Zero(), v = Vec2::Zero(), a = Vec2::Zero();
  double theta = 0.0, omega = 0.0, alpha = 0.0;
};
using WallMotion = std::function<RigidMotion(double t)>;

/// The signed distance of a point to a wall group's surface, > 0 on the fluid's side (the caller's
/// exact geometry, e.g. a structure's interface polyline as it is now).
template <int D> using BasicWallDistance = std::function<double(const VecD<D>& x)>;
using WallDistance = BasicWallDistance<2>;

/// A wall particle given directly (e.g. a boundary point of a structure's interface,
/// fluid_sph/interface_boundary.hpp, or a box tank's dummy, box_walls): reference position, unit
/// normal into the fluid, group, depth behind the wall surface along n (>= 0) and, on the bisector
/// of a convex corner of the solid, the sine of half the angle between its faces' normals (0
/// elsewhere; < 1): the through-a-wall guard's geometry; its volume V_a (0: dp^D, a wall dummy's).
template <int D> struct BasicWallPoint {
  VecD<D> x = VecD<D>::Zero(), n = VecD<D>::Zero();
  int group = 0;
  double depth = 0.0, corner = 0.0, vol = 0.0;
};
using WallPoint = BasicWallPoint<2>;
using WallPoint3 = BasicWallPoint<3>;

/// The stored entries of a symmetric D x D matrix, its upper triangle row by row: 3 in 2-D
/// (b00, b01, b11), 6 in 3-D (b00, b01, b02, b11, b12, b22).
template <int D> inline constexpr int symmetric_count = D*(D + 1) / 2;

/// The reals prefix + rc of a symmetric matrix's upper triangle (r <= c) in `fields`.
template <int D>
std::array<std::vector<double>*, symmetric_count<D>> add_symmetric(particles::FieldSet& fields,
                                                                   const std::string& prefix) {
  std::array<std::vector<double>*, symmetric_count<D>> m{};
  std::size_t k = 0;
  for (int r = 0; r < D; ++r)
    for (int c = r; c < D; ++c)
      m[k++] = &fields.add_real(prefix + std::to_string(r) + std::to_string(c));
  return m;
}

/// The fluid's struct-of-arrays particles (registered in one FieldSet; the 2-D names x, y, vx, vy
/// of the vectors, so 2-D checkpoints are unchanged).
template <int D> struct BasicFluidParticles {
  particles::FieldSet fields;
  std::vector<std::uint32_t>& id = fields.add_index("id");
  particles::VectorField<D> x = particles::add_vector<D>(fields, "");
  particles::VectorField<D> v = particles::add_vector<D>(fields, "v");
  std::vector<double>& rho = fields.add_real("rho");
  std::vector<double>& drho = fields.add_real("drho");
  std::vector<double>& vol = fields.add_real("vol");
  /// Symmetric correction matrix B~ (eq. 21), upper triangle (symmetric_count).
  std::array<std::vector<double>*, symmetric_count<D>> b = add_symmetric<D>(fields, "b");
  /// Prior acceleration: gravity + viscous, per Dt.
  particles::VectorField<D> ap = particles::add_vector<D>(fields, "ap");
  /// Total acceleration of the last acoustic step.
  particles::VectorField<D> a = particles::add_vector<D>(fields, "a");
  /// Positions at the last pair build.
  particles::VectorField<D> xb = particles::add_vector<D>(fields, "", true, "b");
  /// Scratch (not state): pressure; |A_i| (the WKGC indicator).
  std::vector<double>& p = fields.add_real("p", false);
  std::vector<double>& det_a = fields.add_real("det_a", false);
  std::size_t size() const { return fields.size(); }
};
using FluidParticles = BasicFluidParticles<2>;

/// Wall particles: dummies (4 layers at dp) and points given directly.
template <int D> struct BasicWallParticles {
  particles::FieldSet fields;
  std::vector<std::uint32_t>& group = fields.add_index("group");
  /// Current and reference positions.
  particles::VectorField<D> x = particles::add_vector<D>(fields, "");
  particles::VectorField<D> x0 = particles::add_vector<D>(fields, "", true, "0");
  /// Unit normal into the fluid, current and reference.
  particles::VectorField<D> n = particles::add_vector<D>(fields, "n");
  particles::VectorField<D> n0 = particles::add_vector<D>(fields, "n", true, "0");
  /// Velocity and acceleration averaged over the step.
  particles::VectorField<D> v = particles::add_vector<D>(fields, "v");
  particles::VectorField<D> a = particles::add_vector<D>(fields, "a");
  /// Positions at the last pair build.
  particles::VectorField<D> xb = particles::add_vector<D>(fields, "", true, "b");
  /// Tracked walls: the viscous force of the fluid on them, per Dt.
  particles::VectorField<D> fv = particles::add_vector<D>(fields, "fv");
  /// Depth behind the wall surface along the normal and, on a convex corner's bisector, the sine
  /// of half the angle between the faces' normals (WallPoint): reference geometry fixed by the
  /// constructor (as the wall count is), so not state.
  std::vector<double>& depth = fields.add_real("depth", false);
  std::vector<double>& corner = fields.add_real("corner", false);
  /// Volume V_a in every wall sum: dp^D for a dummy; a boundary point's own (WallPoint::vol).
  std::vector<double>& vol = fields.add_real("vol", false);
  std::size_t size() const { return fields.size(); }
};
using WallParticles = BasicWallParticles<2>;

template <int D> class BasicSphFluid {
public:
  using Vec = VecD<D>;
  using Options = BasicSphOptions<D>;
  using Point = BasicWallPoint<D>;
  using Distance = BasicWallDistance<D>;
  static constexpr int S = symmetric_count<D>;

  /// Fluid particles start at rest at `positions`; walls are filled with dummy particles.
  /// Throws fsi::InputError on invalid options or positions outside the domain.
  /// `points` are appended to the walls' dummies as further wall particles (in order);
  /// `distances` are the exact surfaces of moved wall groups (by group; empty: none) for the
  /// through-a-wall guard: a particle that the group's points put behind the walls stops the run
  /// only if its distance puts it more than dp/2 behind too (a thin body's end face may have no
  /// boundary point of its own). Called during the pair builds, this one's included, from several
  /// threads at once.
  /// `block`: the positions are one process's block of the fill (ids from block.first); with
  /// block.deferred the first advection step's start (pairs, density, B) waits for decompose().
  BasicSphFluid(const Options& options, const std::vector<Vec>& positions,
                const std::vector<WallPolyline>& walls = {}, const std::vector<Point>& points = {},
                std::vector<Distance> distances = {},
                const particles::SetupBlock& block = {}) requires(D == 2);
  /// The 3-D fluid: its walls are the wall particles `points` (e.g. box_walls), as above.
  BasicSphFluid(const Options& options, const std::vector<Vec>& positions,
                const std::vector<Point>& points = {}, std::vector<Distance> distances = {},
                const particles::SetupBlock& block = {}) requires(D == 3);

  /// Initial velocities (before the first advance), one per particle in the order of the
  /// constructor's positions (particle id; the particles themselves are sorted by cell).
  void set_velocities(const std::vector<Vec>& v);
  /// Motion of a wall group from now on (its dummies follow it from the next acoustic step).
  void set_wall_motion(int group, WallMotion motion) requires(D == 2);
  /// Wall particles the caller moves (groups without a WallMotion, e.g. a structure's boundary
  /// points): before each advance set x, n at the step's end and v, a averaged over it (eq. 17);
  /// the pairs follow at the next advection step, as for a WallMotion.
  BasicWallParticles<D>& moved_walls() { return walls_; }
  /// How the force on a tracked wall is formed. exact: the reaction of the wall terms the fluid
  /// particles felt (action = -reaction). reference_code: the RKGC paper's code, whose reaction
  /// takes the dummy pressure of eq. 16 without B_i (method notes): a measurement of the momentum
  /// it does not conserve (bench/fluid_sph/interface_momentum.cpp), not a model to run with.
  enum class Reaction { exact, reference_code };
  /// From now on the force of the fluid on each wall particle a >= first is kept: wall_force(a)
  /// after each advance, N/m (2-D) or N (3-D), formed as `reaction` says (eqs. 15-17 and the
  /// no-slip viscous term frozen over Dt).
  void track_wall_forces(std::size_t first, Reaction reaction = Reaction::exact);
  Vec wall_force(std::size_t a) const;

  /// The acoustic step allowed now: min(acoustic criterion, what is left of the current Dt), or
  /// fixed_dt.
  double next_dt() const;
  /// One acoustic step of length dt (0 < dt <= what is left of Dt). When it fills the current Dt
  /// the per-Dt work runs. Throws RunError (particle id, step, time) on NaN, a density out of
  /// range or a particle behind a wall.
  void advance(double dt);
  /// Acoustic steps of next_dt() until time() reaches t_end (with a dual-criteria step the last
  /// one is shortened to land on it; the advection step then goes on at the next advance).
  void advance_to(double t_end);

  /// Steps from now on decomposed over processes through `decomposition` (issue 47), which must
  /// outlive the fluid. Each process built its block of the fill (SetupBlock::deferred: the
  /// first advection step starts here, decomposed), or the whole fluid, of which it keeps its
  /// block (particles/setup_block.hpp). The first migration partitions the particles at their
  /// build positions and the advection step's pairs are rebuilt over the
  /// owned particles and the ghosts within the kernel's support (every process holds every wall
  /// particle). Tracked wall forces (wall_force) are then this rank's particles' part: the
  /// caller sums them. Not periodic (refused); write_state is then collective (the one-process
  /// format on process 0); save/restore are for one process (bgs is refused under mpirun).
  void decompose(particles::Decomposition<D>& decomposition);
  /// The particles this process owns: the first owned() entries of particles(); ghosts follow.
  std::size_t owned() const { return fluid_.size() - hook().ghosts(); }

  double time() const { return t_; }
  long steps() const { return step_; }
  long advection_steps() const { return builds_; }
  double advection_dt() const { return Dt_; }
  /// Particles that left the domain, on this process (decomposed: the caller sums them).
  std::size_t removed() const { return removed_; }
  double mean_neighbours() const;
  double sigma0() const { return sigma0_; }
  const Options& options() const { return options_; }
  const BasicFluidParticles<D>& particles() const { return fluid_; }
  const BasicWallParticles<D>& walls() const { return walls_; }

  // Probes: over every process when decomposed (collective), the first owned() particles here.
  double kinetic_energy() const;
  Vec momentum() const;
  /// Kernel-weighted (Shepard) pressure at a point, from the fluid particles within 2h; 0 if none.
  double pressure_at(const Vec& point) const;
  /// Kernel-weighted (Shepard) velocity at a point, as pressure_at; 0 if no particle is near.
  Vec velocity_at(const Vec& point) const;
  /// Largest x of the bulk fluid (neighbours' kernel sum >= half the lattice's, W(0) left out
  /// as MPS's pnd leaves out i): the surge front of a dam break.
  double surge_front() const;
  /// Pressure of the last step, p = c0^2 (rho - rho0), per particle.
  double pressure(std::size_t i) const { return fluid_.p[i]; }

  /// A copy of the whole fluid state for iterative coupling; restore() returns to it exactly.
  struct State {
    particles::FieldSet::Snapshot fluid, walls;
    double t = 0, Dt = 0, elapsed = 0, dt_acoustic = 0;
    long step = 0, builds = 0, sub = 0, subs = 0;
    std::size_t removed = 0;
  };
  void save(State& into) const;
  void restore(const State& from);

  /// Checkpoint under prefix + name: a run continued from it is bitwise the uninterrupted one.
  void write_state(StateArchive& archive, const std::string& prefix) const;
  /// Throws InputError naming the key when the archive does not fit this fluid.
  void read_state(const StateArchive& archive, const std::string& prefix);

  // The operators, exposed for the consistency tests (eqs. 18-19): on the current pairs.
  /// grad psi_i by the RKGC form sum_j (psi_i B_j + psi_j B_i) grad W_ij V_j (eq. 18).
  Vec rkgc_gradient(std::size_t i, const std::vector<double>& psi) const;
  /// B_i sum_j (psi_j - psi_i) grad W_ij V_j (first-order consistent for any B_i = A_i^-1).
  Vec corrected_difference_gradient(std::size_t i, const std::vector<double>& psi) const;
  /// sum_j (psi_j - psi_i) grad W_ij V_j (uncorrected).
  Vec plain_difference_gradient(std::size_t i, const std::vector<double>& psi) const;

private:
  /// The members' set-up and the fluid particles (walls and the first advection step follow).
  struct Setup {};
  BasicSphFluid(Setup, const Options& options, const std::vector<Vec>& positions,
                std::vector<Distance> distances, std::size_t first_id);
  /// The first advection step's start, now or (block.deferred) in decompose().
  void start(const particles::SetupBlock& block);
  void fill_walls(const std::vector<WallPolyline>& walls) requires(D == 2);
  void append_wall_points(const std::vector<Point>& points);

  void wall_reaction();         // tracked walls: the wall terms of first_half, reversed
  void wall_viscous_reaction(); // tracked walls: the viscous wall term of prior_acceleration

  void per_advection_step(); // wrap, remove, sort, pairs, density, B, viscous, transport, Dt
  // From xb (fluid) and xb (walls); guard: the through-a-wall check (not on a rebuild of pairs
  // already checked, restore and read_state, whose walls' exact surface may have moved).
  void build_pairs(bool guard = true);
  void reinitialise_density();
  /// sum_j W_ij over fluid i's fluid and wall neighbours and itself, at the last list build.
  double kernel_sum(std::size_t i) const;
  /// sum_i W(point - x_i) V_i value(i) / sum_i W(point - x_i) V_i over the fluid particles (the
  /// periodic image nearest), 0 if none is within 2h: the probes' Shepard mean.
  template <class Value> double shepard(const Vec& point, Value value) const;
  void correction_matrices();
  void prior_acceleration();
  void transport_shift();
  void compute_advection_dt();
  void compute_acoustic_dt();
  void move_walls(double dt) requires(D == 2);
  void impose_inflow(double t) requires(D == 2); // the buffer's U(y, t) (src/inflow.cpp)
  void first_half(double dt);
  void second_half(double dt);
  void guard(long step, double t) const;
  /// The exchange hook: the decomposition given, or the serial one.
  particles::Decomposition<D>& hook() const { return decomposition_ ? *decomposition_ : local_; }
  /// Decomposed: the ghosts within the kernel's support of the owned particles at `x` (none
  /// held on entry).
  void build_ghosts(const particles::VectorField<D>& x);
  std::string where(std::size_t i, long step, double t) const;

  Options options_;
  particles::BasicWendlandC2<D> kernel_;
  double h_, sigma0_, mass_;
  BasicFluidParticles<D> fluid_;
  BasicWallParticles<D> walls_;
  std::vector<WallMotion> motions_; // by group, empty: static (2-D)
  std::vector<Distance> distances_; // by group, empty: the points' planes alone
  particles::BasicPeriodicGrid<D> grid_, wall_grid_;
  // Pairs, compressed rows: fluid i's fluid neighbours are pj_[pstart_[i] .. pstart_[i+1]).
  std::vector<std::uint32_t> pstart_, pj_, wstart_, wj_;
  std::array<std::vector<double>, D> pe_, we_; // e_ij by component
  std::vector<double> pdw_, pr_, wdw_, wr_;    // dW_ij, r_ij
  std::vector<double> scratch_;
  std::vector<std::uint32_t> count_;
  std::vector<std::uint8_t> keep_;
  double t_ = 0.0, Dt_ = 0.0, elapsed_ = 0.0, dt_acoustic_ = 0.0;
  long step_ = 0, builds_ = 0, sub_ = 0, subs_ = 0; // fixed dt: subs_ acoustic steps per Dt
  std::size_t removed_ = 0;
  std::size_t tracked_ = static_cast<std::size_t>(-1); // first tracked wall particle
  std::array<std::vector<double>, D> wf_;              // their force, last acoustic step
  Reaction reaction_ = Reaction::exact;
  mutable particles::LocalParticles<D> local_;           // the serial hook
  particles::Decomposition<D>* decomposition_ = nullptr; // set by decompose
};

// No `extern template class`: the members are instantiated one by one in src/ (the class as a
// whole cannot be, clang 14: src/sph_fluid.cpp), and the members defined here, in the class,
// must then be instantiated where they are used (clang does not emit them otherwise).

using SphFluid = BasicSphFluid<2>;
using SphFluid3 = BasicSphFluid<3>;

/// Lattice points (x0 + (i + 1/2) dp, y0 + (j + 1/2) dp) inside the rectangle [lo, hi].
std::vector<Vec2> fill_rectangle(const Vec2& lo, const Vec2& hi, double dp);
/// Lattice points lo + (i + 1/2, j + 1/2, k + 1/2) dp inside the box [lo, hi].
std::vector<Vec3> fill_box(const Vec3& lo, const Vec3& hi, double dp);
/// The dummies of an open box tank [lo, hi] (no lid): the lattice points lo + (i + 1/2) dp within
/// `layers` dp outside its floor and four sides, below hi along the open axis, with the normal of
/// the nearest face (on an edge or corner the normalised sum of the faces' normals, as at a
/// polyline's vertex) and the depth behind the nearest feature along it. `open`: the axis whose hi
/// face is open (2: z, 1: y for a scene's tank, y up). `periodic`: axes along which the tank
/// wraps (a slab), with no dummies behind those two faces and none beyond [lo, hi] along it.
std::vector<WallPoint3> box_walls(const Vec3& lo, const Vec3& hi, double dp, int layers = 4,
                                  int open = 2, std::array<bool, 3> periodic = {});

} // namespace fsi::sph
