#pragma once
// Total-Lagrangian SPH solid with kernel gradient correction (RKGC paper, ../shared/seeds/
// rkgc-riemann-sph-multires-fsi.txt, eqs. 6-14; ../shared/sph-method-notes.md, "Solid").
// Neighbours, kernel gradients grad0 W_ab and the correction matrices B0_a (eq. 14) are computed
// once in the reference configuration; each step evaluates F_a (eq. 13), S(E) from materials/,
// P = F S (eq. 7) and the momentum equation (eq. 12), integrated by velocity Verlet in two half
// steps. Units SI, per unit thickness in 2-D (forces in N/m, energies in J/m). Written once for
// D = 2 and 3 (docs/architecture.md, "Two and three dimensions"); the coupling interface: order-1
// edges along the outline in 2-D, order-1 triangles over a box's faces in 3-D.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "fsi/core/interface_mesh.hpp"
#include "fsi/core/options.hpp"
#include "fsi/core/types.hpp"
#include "materials/energies.hpp"
#include "materials/material.hpp"
#include "particles/field_set.hpp"
#include "particles/vector_field.hpp"
#include "solid_tlsph/geometry.hpp"

namespace fsi {
class StateArchive;
}

namespace fsi::tlsph {

/// A clamped region: particles whose reference position satisfies `contains` have their
/// position and velocity prescribed. Without `position`/`velocity` (a fixed clamp) they stay at
/// X0 with v = 0; with them (a rigid motion such as a rolling tank's clamp) x = position(X0, t),
/// v = velocity(X0, t). Both or neither must be set.
template <int D> struct BasicClamp {
  std::function<bool(const VecD<D>& X0)> contains;
  std::function<VecD<D>(const VecD<D>& X0, double t)> position;
  std::function<VecD<D>(const VecD<D>& X0, double t)> velocity;
  /// Fixed clamps (the default form; a moving clamp always holds its particles): u = 0 on the
  /// clamp's face, the line through `face_point` with normal `face_normal`, instead of at the
  /// clamped particles. Each clamped particle at the mirror position of a free particle moves
  /// as its odd image, u_g = -u_p (so u = 0 on the face); every clamped particle carries no
  /// strain energy, those without a partner stay at X0, and the force on p gains minus the
  /// force on its image (f_p = -dPi/dx_p with x_g(x_p)). A clamped particle within 2h of a free
  /// one without a partner is an InputError. In the corner where two odd-image clamps meet, a
  /// clamped particle whose mirror is clamped takes the free particle mirrored across both faces
  /// as its partner, u_g = +u_p (the odd image of the odd image). false: the paper's clamp (the
  /// clamped particles held, with their own F and stress; the beams are then soft by ~ 3 dp / L,
  /// docs/solid_tlsph.md).
  bool odd_image = true;
  /// The face; when unset (face_normal = 0) it is found from the reference lattice: the line
  /// (plane in 3-D) through the midpoints of the clamped-free particle pairs dp apart, which
  /// must all be perpendicular to it and on it (InputError otherwise: set the face, or
  /// odd_image = false).
  VecD<D> face_point = VecD<D>::Zero();
  VecD<D> face_normal = VecD<D>::Zero();
};
using Clamp = BasicClamp<2>;
using Clamp3 = BasicClamp<3>;

/// A probe's displacement as a fixed combination of particle displacements,
/// u = sum_k weights[k] u(particles[k]) (the nearest particle: one entry of weight 1).
struct ProbeStencil {
  std::vector<std::uint32_t> particles;
  std::vector<double> weights;
};

/// How the reference kernel gradient is corrected (eq. 14 or its second-order extension).
enum class GradientCorrection {
  /// The paper's B0 (eq. 14): F exact for linear displacement fields. At a surface particle the
  /// one-sided support makes F of a bending (quadratic) field first-order wrong: the beams are
  /// too soft (docs/solid_tlsph.md, "Accuracy").
  linear,
  /// Second order: per pair a corrected gradient g~_ab = w_ab [A_a^-1 p_ab]_(0,1) from the
  /// weighted least-squares fit of u_b - u_a by a quadratic in X_b - X_a (p_ab its 5
  /// monomials, w_ab = |dW_ab| / r_ab V_b, A_a = sum_b w_ab p_ab p_ab^T), so F is exact for
  /// quadratic fields at every particle, the surface included. The force is the variational
  /// one, f_a = sum_b (V_a P_a g~_ab - V_b P_b g~_ba) = -dPi/dx_a of Pi = sum_a V_a W(F_a):
  /// pairwise antisymmetric, conservative. Reduces to `linear` where the support is symmetric.
  quadratic,
};

template <int D> struct BasicTlsphOptions {
  materials::MaterialOptions material;
  double dp = 0.01;       ///< lattice spacing dp_S [m], > 0 (the geometry's spacing)
  double h_factor = 1.15; ///< h = h_factor dp, in [1, 2] (notes: 1.15; hydrostatic case 1.3)
  VecD<D> gravity = VecD<D>::Zero(); ///< g [m/s^2]
  double cfl = 0.6;                  ///< dt_s = cfl min(sqrt(h/|a|), h/(c_s + |v|)), in (0, 1]
  bool kernel_correction = true;     ///< B0 of eq. 14; false: B0 = I (standard SPH, for tests)
  /// Order of the gradient correction (needs kernel_correction); `linear` is the paper's form,
  /// `quadratic` (the default) takes ~ 2.6 x its sub-steps (dt_scale()) and meets the beam
  /// targets of docs/solid_tlsph.md with the default clamp.
  GradientCorrection gradient_correction = GradientCorrection::quadratic;
  /// Pairwise artificial viscosity, a_a += sum_b 2 nu_d (v_b - v_a) |dW_ab| / r_ab V_b with
  /// nu_d = pair_damping * c_s h / 2 (Morris form in the reference configuration; conserves
  /// momentum, dissipates the relative motion of neighbours). >= 0; 0 = off (default).
  double pair_damping = 0.0;
  /// Mass-proportional damping a -= mass_damping v [1/s], >= 0; 0 = off. For static solutions
  /// by dynamic relaxation (close to 2 omega_1 is critical for the first mode).
  double mass_damping = 0.0;
  /// Hourglass control of the quadratic correction (`linear`, the paper's form, has none), >= 0;
  /// 0 = off. A penalty energy
  /// Pi_hg = 1/2 hourglass E sum_a V_a sum_b w_ab |r_ab|^2 (w_ab = |dW_ab| / r_ab V_b) on r_ab,
  /// the residual of a's weighted quadratic fit of u_b - u_a: zero for rigid motions and
  /// quadratic fields (bending), it stiffens the row-alternating zero-energy mode of particle
  /// integration, which point loads excite next to an odd-image clamp (docs/solid_tlsph.md,
  /// "Coupled").
  double hourglass = 0.5;
  std::vector<BasicClamp<D>> clamps;
  /// Outline tags (3-D: the box's face tags, geometry.hpp) whose surface particles form the
  /// coupling interface; empty: every edge (face).
  std::vector<std::string> interface_tags;
  /// Also hand every particle to the coupling as an interface node after the outline's nodes
  /// (InterfaceMesh::particle_volume): a particle fluid then takes the solid's own particles as
  /// its boundary (the RKGC paper's pair); a fluid that uses the edges ignores them.
  bool interface_particles = false;
  /// Row capacity of the reference neighbour list, >= 8 (a full 3-D row at h = 1.15 dp: 56).
  int max_neighbors = D == 2 ? 64 : 128;
};
using TlsphOptions = BasicTlsphOptions<2>;
using TlsphOptions3 = BasicTlsphOptions<3>;

/// Throws InputError naming the field, its value and the allowed range.
template <int D> void validate(const BasicTlsphOptions<D>& options);

/// The keys a user sets, each once (dp is required; fsi/core/options.hpp); the material's are
/// materials::visit_options.
void visit_options(TlsphOptions& options, OptionVisitor& visitor);

/// Everything that evolves; cheap to copy for save/restore in iterative coupling.
struct TlsphState {
  particles::FieldSet::Snapshot fields;
  double time = 0.0;
  long step = 0;
  double external_work = 0.0;
};

using TlsphEnergies = materials::SolidEnergies;

template <int D> class BasicTlsphSolid {
public:
  using Vec = VecD<D>;
  using Mat = MatD<D>;
  using Geometry = BasicSolidGeometry<D>;
  using Options = BasicTlsphOptions<D>;

  /// Validates the options and the geometry, builds the reference neighbour list, grad0 W V_b
  /// per pair and B0 (eq. 14), marks clamped and surface particles, builds the interface (2-D:
  /// from the outline; 3-D: from Geometry::box, the outline empty), and starts at rest at X0
  /// with a^0 from eq. 12 (gravity only). Throws InputError (bad options, empty geometry, a
  /// neighbour row over max_neighbors, a singular moment matrix).
  BasicTlsphSolid(Geometry geometry, Options options);
  ~BasicTlsphSolid();

  std::size_t size() const { return fields_.size(); }
  const Options& options() const { return options_; }
  double h() const { return h_; }
  double sound_speed() const { return c_s_; } ///< c_s = sqrt(K / rho0)
  double time() const { return time_; }
  long step() const { return step_; }
  const particles::FieldSet& fields() const { return fields_; }

  /// Advances from t to t + dt in sub-steps of at most the stable dt_s (recomputed before each
  /// sub-step from max |a|, |v|; the remaining interval split evenly), with the interface loads
  /// held fixed. `t` is the start time and must equal time() to within 1e-12 (1 + |t|); throws
  /// InputError otherwise, RunError (what, particle, step, time) on NaN or det F <= 0; the state is
  /// then that of the failed sub-step (restore() a saved one). Returns the sub-steps taken.
  int advance(double t, double dt);
  /// The stable step dt_s of the current state (GradientCorrection::quadratic: times
  /// dt_scale() <= 1).
  double stable_dt() const;
  /// 1 for the linear correction; for the quadratic one max_a sum_b |B0_a grad0 W_ab V_b| /
  /// max_a sum_b |g~_ab| (its one-sided surface stencils raise the highest frequency).
  double dt_scale() const { return dt_scale_; }

  // --- coupling interface ---
  /// 2-D: nodes on the tagged outline edges (each surface particle's projection onto its nearest
  /// tagged edge, and the edges' vertices), ordered along the outline (counter-clockwise: solid
  /// on the left of a -> b), order-1 edges between neighbours along it. 3-D: nodes on the tagged
  /// faces of Geometry::box (each outer-layer particle's projection onto its face, and the
  /// face's border lines at the same lattice coordinates), order-1 triangles, two per cell of
  /// that grid, corners counter-clockwise seen from outside. Each node is attached to
  /// a particle (interface_particles(); clamped ones included: their loads are reactions).
  /// With TlsphOptions::interface_particles every particle follows as a node of its own (at its
  /// position, with its volume V0; on no element).
  BasicInterfaceMesh<D> interface_mesh() const;
  /// Particle each interface node k is attached to (a corner particle carries several).
  const std::vector<std::uint32_t>& interface_particles() const { return interface_; }
  /// Current x, v, a of the interface nodes.
  std::vector<Vec> interface_positions() const;
  std::vector<Vec> interface_velocities() const;
  std::vector<Vec> interface_accelerations() const;
  /// Outward unit normals of the interface nodes in the current configuration: the reference
  /// normal n0 (from the outline) mapped by the cofactor of F, n = F^-T n0 / |F^-T n0|
  /// (Nanson's formula; the rotation R of F = R U for pure rotations); zero for particle nodes.
  std::vector<Vec> interface_normals() const;
  /// Nodal forces on the interface nodes [N/m in 2-D, N in 3-D], held over the next advance();
  /// each is added to its particle's and enters eq. 12 as a^{F:S} = f / m. Clamped nodes ignore
  /// them (reactions).
  void set_interface_loads(const std::vector<Vec>& forces);
  /// External nodal forces on any particles (e.g. a test's tip load) [N/m in 2-D, N in 3-D],
  /// size() entries.
  void set_external_forces(const std::vector<Vec>& forces);

  // --- output ---
  Vec position(std::size_t i) const { return at(x_, i); }
  Vec reference_position(std::size_t i) const { return at(X0_, i); }
  Vec displacement(std::size_t i) const {
    Vec u;
    for (int k = 0; k < D; ++k) u(k) = x_[k][i] - X0_[k][i];
    return u;
  }
  Vec velocity(std::size_t i) const { return at(v_, i); }
  Vec acceleration(std::size_t i) const { return at(a_, i); }
  double volume(std::size_t i) const { return V0_[i]; }
  bool clamped(std::size_t i) const { return clamped_[i] != 0; }
  bool surface(std::size_t i) const { return surface_[i] != 0; }
  /// F_a of eq. 13 at the current positions.
  Mat deformation_gradient(std::size_t i) const;
  Mat correction_matrix(std::size_t i) const;
  std::vector<double> det_F() const;
  /// Von Mises of the Cauchy stress sigma = F S F^T / J (plane: with sigma_33 from the law).
  std::vector<double> von_mises() const;
  /// Index of the particle whose reference position is nearest to X0 (a probe).
  std::size_t nearest_particle(const Vec& X0) const;
  /// Kernel interpolation at reference point X0 with the linear correction (probe.cpp): the
  /// weighted least-squares fit u(X) = a + G (X - X0) over the particles b within 2h, weights
  /// W(|X_b - X0|) V_b, gives u(X0) = a = sum_b c_b u_b. Exact for linear displacement fields
  /// (at the surface too); Shepard's sum u_b W V_b / sum W V_b where the support is symmetric.
  /// Throws InputError when the particles within 2h do not span the space (X0 off the solid).
  ProbeStencil interpolation_stencil(const Vec& X0) const;
  /// sum_k weights[k] u(particles[k]).
  Vec displacement_at(const ProbeStencil& stencil) const;
  Vec interpolate_displacement(const Vec& X0) const {
    return displacement_at(interpolation_stencil(X0));
  }
  TlsphEnergies energies() const;

  /// Sets positions and velocities (e.g. an initial velocity or a prescribed displacement field
  /// in a test), then recomputes F, stress and accelerations. Clamped particles keep their
  /// prescribed values. Sizes must be size().
  void set_positions(const std::vector<Vec>& x);
  void set_velocities(const std::vector<Vec>& v);

  TlsphState save() const;
  /// Returns to a saved state (positions, velocities, accelerations, pending loads, time, step).
  void restore(const TlsphState& state);
  /// Checkpoint of the state under keys `prefix` + name; read_state continues bitwise.
  void write_state(StateArchive& archive, const std::string& prefix) const;
  /// Throws InputError naming the key when the archive holds another particle count.
  void read_state(const StateArchive& archive, const std::string& prefix);

private:
  using Field = particles::VectorField<D>;
  /// The D x D components (i, j) of a per-particle matrix, row-major.
  using Tensor = std::array<std::vector<double>*, D * D>;
  static Vec at(const Field& f, std::size_t i) {
    Vec v;
    for (int k = 0; k < D; ++k) v(k) = f[k][i];
    return v;
  }

  void build_reference();
  /// g~_ab and the reverse pair index of GradientCorrection::quadratic.
  void build_quadratic();
  /// The 2-D interface along the tagged outline (interface.cpp).
  void build_outline_interface(const Geometry& geometry) requires(D == 2);
  /// The 3-D interface over Geometry::box's tagged faces (interface_box.cpp).
  void build_box_interface(const Geometry& geometry) requires(D == 3);
  /// Appends every particle as a node of its own (TlsphOptions::interface_particles).
  void add_particle_nodes();
  /// Partners of the Clamp::odd_image particles.
  void build_images();
  /// The face of fixed clamp k (its given one, or found from the lattice), oriented outwards
  /// from the clamp.
  void clamp_face(std::size_t k, Vec& point, Vec& normal) const;
  /// Residuals r_ab of particle a's quadratic fit (its row of pairs) at the current positions;
  /// r[k] holds component k for the row's pairs.
  void hourglass_residuals(std::size_t a, const std::array<double*, D>& r) const;
  /// True for a particle of a fixed odd-image clamp (no strain energy, not integrated).
  bool imaged(std::size_t i) const { return clamped_[i] && imaged_[clamped_[i] - 1u]; }
  /// F (eq. 13) and P B0 per particle; throws RunError on det F <= 0 or NaN.
  void compute_stress();
  /// a = eq. 12 + gravity + external + damping (needs compute_stress()).
  void compute_acceleration();
  void prescribe(double t);
  /// Copies `values` (size() entries, else InputError naming `what`) into `field` at the free
  /// particles, then moves the odd images.
  void set_free(const std::vector<Vec>& values, Field& field, const char* what);
  void substep(double dt);
  void update_loaded();

  Options options_;
  std::unique_ptr<materials::MaterialInterface<D>> material_;
  double h_ = 0.0, c_s_ = 0.0, rho0_ = 0.0;
  double time_ = 0.0, external_work_ = 0.0;
  long step_ = 0;

  particles::FieldSet fields_;
  // State: current position, velocity, acceleration, pending external forces.
  Field x_, v_, a_, f_;
  // Reference data (not state): X0, V0, B0, clamp index (0 = free, k + 1 = clamps[k]), surface.
  Field X0_;
  std::vector<double>& V0_;
  Tensor B_;
  std::vector<std::uint8_t>&clamped_, &surface_;
  // Scratch: F and P B0 per particle (recomputed every step).
  Tensor F_, PB_;

  // Reference neighbour pairs, CSR by particle: neighbour b and grad0 W_ab V_b (eq. 14).
  std::vector<std::uint32_t> pair_start_, pair_b_;
  std::array<std::vector<double>, D> pair_g_; // grad0 W_ab V_b per component
  std::vector<double> pair_dwr_;              // |dW_ab| / r_ab V_b
  // GradientCorrection::quadratic only: the corrected gradient g~_ab and the index of the
  // reverse pair (b, a) in b's row.
  std::array<std::vector<double>, D> pair_q_;
  std::vector<std::uint32_t> pair_rev_;
  bool quadratic_ = false;
  // TlsphOptions::hourglass only: per pair the fit operator s_ab = w_ab h^2 A_a^-1 p_ab (one
  // value per monomial), the penalty stiffness k_ab = hourglass E V_a w_ab (row of a; 0 on
  // image rows) and the residual r_ab (scratch, compute_stress).
  std::vector<double> pair_fit_, pair_k_;
  std::array<std::vector<double>, D> pair_r_;
  // Clamp::odd_image: the free partner of each image particle (none = not an image) and its sign
  // s (u_g = s u_p: -1 across one face, +1 across two in the corner where two clamps meet), the
  // images of each free particle (rows image_start_ into image_list_); scratch force per unit
  // mass of the images.
  std::vector<std::size_t> image_partner_;
  std::vector<double> image_sign_;
  std::vector<std::uint32_t> image_start_, image_list_;
  std::array<std::vector<double>, D> image_a_;
  std::vector<std::uint8_t> imaged_; // per clamp: a fixed clamp with odd_image
  bool images_ = false;
  double dt_scale_ = 1.0; // stable-step factor of the quadratic correction (build_quadratic)

  std::vector<std::uint32_t> loaded_;    // free particles with a nonzero external force
  std::vector<std::uint32_t> interface_; // particle of each interface node
  std::vector<Vec> interface_n0_;        // reference outward normals
  std::vector<Vec> interface_offset_;    // node X minus its particle's X0 (onto the outline)
  BasicInterfaceMesh<D> interface_mesh_;
};

using TlsphSolid = BasicTlsphSolid<2>;
using TlsphSolid3 = BasicTlsphSolid<3>;

} // namespace fsi::tlsph
