#pragma once
// The solid as the coupler sees it, one template over the element family (T6: `Structure`,
// per unit thickness, forces in N/m; T10: `StructureT10`): node arrays in (external forces),
// node arrays out (displacement, velocity, acceleration, predictor, stress), one Newmark step at
// a time, and a value-type state for save/restore in iterative coupling. Units SI. Node arrays
// have size dim * nodes, entry dim K + c for component c of node K.
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "materials/energies.hpp"
#include "structure_fem/assembly.hpp"
#include "structure_fem/linear_solver.hpp"
#include "structure_fem/material.hpp"
#include "structure_fem/mesh.hpp"
#include "structure_fem/newmark.hpp"
#include "structure_fem/newton_raphson.hpp"

namespace fsi {
class StateArchive;
}

namespace fsi::fem {

template <class Family> struct BasicStructureOptions {
  MaterialOptions material; ///< E, nu, rho, the law; the plane model is 2-D only
  VecD<Family::dim> gravity = VecD<Family::dim>::Zero(); ///< body acceleration g [m/s^2]
  std::vector<typename Family::Condition> clamped;       ///< fixed or prescribed-motion conditions
  NewmarkOptions newmark;
  NewtonOptions newton;
  /// 2-D: LDL^T with LU fallback; 3-D: CHOLMOD (issue 44).
  LinearSolverOptions linear_solver{Family::dim == 3 ? LinearSolverKind::cholmod
                                                     : LinearSolverKind::ldlt_or_lu};
};
using StructureOptions = BasicStructureOptions<T6>;
using StructureT10Options = BasicStructureOptions<T10>;

/// Throws InputError naming the field, its value and the allowed range.
template <class Family> void validate(const BasicStructureOptions<Family>& options);

struct StaticOptions {
  int load_steps = 1; ///< the load (f_ext + gravity) is applied in equal increments, >= 1
  /// Time at which prescribed motions are evaluated; their displacements are applied in the same
  /// increments as the load, and the structure is at this time afterwards. Default: time().
  std::optional<double> time = std::nullopt;
};

/// The full kinematic state; cheap to copy (iterative coupling re-runs a step from it).
struct StructureState {
  Vector u, v, a; ///< node arrays [m], [m/s], [m/s^2]
  Vector f_ext;   ///< the external forces of the last step (for the work integral)
  double time = 0.0;
  long step = 0;
  double external_work = 0.0; ///< integral f_ext . du (trapezoidal) [J/m]
};

/// u-hat, v-hat, a-hat at t + dt (eqs. 63-65).
struct Prediction {
  Vector u, v, a;
};

using Energies = materials::SolidEnergies;

template <class Family> class BasicStructure {
public:
  static constexpr int dim = Family::dim;

  /// Validates options and mesh, builds the assembly pattern, mass and gravity forces, analyses
  /// the pattern once, and starts at rest with u = 0 and a^0 from M a^0 = f_g (constrained dofs
  /// start at their prescribed u, v, a at t = 0).
  BasicStructure(typename Family::Mesh mesh, BasicStructureOptions<Family> options);
  ~BasicStructure();
  BasicStructure(const BasicStructure&) = delete;
  BasicStructure& operator=(const BasicStructure&) = delete;

  const typename Family::Mesh& mesh() const { return mesh_; }
  std::size_t num_nodes() const { return mesh_.num_nodes(); }
  const DofMap& dofs() const { return *dofs_; }
  const BasicStructureOptions<Family>& options() const { return options_; }

  /// Nodal external forces for the next step (e.g. projected fluid forces, eq. 58) [N/m; 3-D: N],
  /// size dim * nodes; they act at t^{n+1}. Entries on clamped dofs are ignored (reactions).
  void set_external_forces(const Vector& f_ext);
  const Vector& external_forces() const { return f_ext_next_; }

  /// One Newmark step (eqs. 40-41) t -> t + dt, Newton–Raphson on u^{n+1} starting from the
  /// predictor (eq. 64). Constrained dofs take their prescribed u, v, a at t + dt; the inertia of
  /// the prescribed accelerations enters the free equations through the consistent mass. A failed
  /// step is retried with sub-steps if NewtonOptions::max_substep_levels > 0. Throws RunError
  /// (with step and time) if Newton or the linear solver fails or an element inverts at every
  /// level; the state is then unchanged.
  const StepReport& advance(double dt);

  /// Static equilibrium f_int(u) = f_ext + f_g with load stepping from the current u; sets
  /// v = a = 0 on the free dofs (constrained dofs: their prescribed v, a). Returns one report per
  /// load step. Throws RunError like advance().
  std::vector<StepReport> solve_static(const StaticOptions& options = {});

  /// Re-solves M a = f_ext + f_g - f_int(u) for the current u with the forces just set, which
  /// then count as the forces at t^n (e.g. releasing a load at t^n).
  void update_acceleration();

  const Vector& displacement() const { return state_.u; }
  const Vector& velocity() const { return state_.v; }
  const Vector& acceleration() const { return state_.a; }
  /// Current node positions x = X + u (eq. 28 / 60).
  std::vector<VecD<dim>> positions() const;
  double time() const { return state_.time; }
  long step() const { return state_.step; }

  /// Second-order predictor for t + dt (eqs. 63-65); constrained dofs: their prescribed values.
  Prediction predict(double dt) const;

  StructureState save() const { return state_; }
  /// Returns to a saved state; the pending external forces become those of that state, so set
  /// the new forces after restoring.
  void restore(const StructureState& state);

  /// Checkpoint: the state (u, v, a, forces of the last step, time, step, work) and the pending
  /// external forces, under keys `prefix` + name. Everything advance() reads besides the mesh
  /// and the options; the linear solver keeps no values between steps.
  void write_state(StateArchive& archive, const std::string& prefix) const;
  /// Throws InputError naming the key when the archive has another number of nodes.
  void read_state(const StateArchive& archive, const std::string& prefix);

  /// Von Mises Cauchy stress per node (element nodal values averaged) [Pa].
  Vector von_mises() const;
  /// Energies of the free motion; the work of prescribed motions is not counted.
  Energies energies() const;

  /// Factorisations the default solver did by LU since construction (LinearSolver::fallbacks).
  long linear_solver_fallbacks() const { return solver_->fallbacks(); }
  /// Preconditioner hierarchies built since construction (cg_amg; LinearSolver::setups).
  long linear_solver_setups() const { return solver_->setups(); }

  /// The report of the last advance().
  const StepReport& last_report() const { return report_; }

private:
  /// newton_raphson on the free dofs; residual(u, R) fills R (free) and K_eff_.
  void newton(Vector& u, const NewtonResidual& residual, StepReport& report);
  /// One Newmark step from state_ with f_ext_next_; throws RunError without step and time.
  StepReport step(double dt);
  void factor_and_solve(const SparseMatrix& K, const Vector& rhs, Vector& x, int& iterations);
  /// Sets the constrained entries of u, v, a to the prescribed motion at time t.
  void prescribe(double t, Vector& u, Vector& v, Vector& a) const;
  /// M_fc a_c on the free dofs: the inertia of the constrained accelerations in a.
  Vector constrained_inertia(const Vector& a) const;

  typename Family::Mesh mesh_;
  BasicStructureOptions<Family> options_;
  std::unique_ptr<typename Family::Material> material_;
  std::unique_ptr<DofMap> dofs_;
  std::unique_ptr<BasicAssembler<Family>> assembler_;
  std::unique_ptr<LinearSolver> solver_;
  SparseMatrix M_, K_, K_eff_;
  SparseMatrix M_all_;                           ///< consistent mass on all dofs
  std::vector<std::pair<int, int>> constrained_; ///< (dof, condition) of every constrained dof
  Vector f_g_, f_ext_next_, f_int_;
  StructureState state_;
  StepReport report_;
};

using Structure = BasicStructure<T6>;
using StructureT10 = BasicStructure<T10>;
extern template class BasicStructure<T6>;
extern template class BasicStructure<T10>;

} // namespace fsi::fem
