#pragma once
// The T10 solid (issue 44): static equilibrium with load steps and Newmark-beta steps, both by
// the Newton–Raphson of newton_raphson.hpp, on a TetMesh with clamped or sliding faces. Units SI;
// node arrays have size 3 * nodes, entry 3K + c for component c of node K. Not yet: prescribed
// motions, sub-steps, save/restore and checkpoints (the T6 Structure has them).
#include <memory>
#include <vector>

#include "materials/energies.hpp"
#include "structure_fem/assembly.hpp"
#include "structure_fem/linear_solver.hpp"
#include "structure_fem/material.hpp"
#include "structure_fem/mesh_t10.hpp"
#include "structure_fem/newmark.hpp"
#include "structure_fem/newton_raphson.hpp"

namespace fsi::fem {

struct StructureT10Options {
  MaterialOptions material;                 ///< E, nu, rho and the law (plane is ignored)
  Vec3 gravity{0.0, 0.0, 0.0};              ///< body acceleration g [m/s^2]
  std::vector<DirichletCondition3> clamped; ///< fixed components (u = 0)
  NewmarkOptions newmark;
  NewtonOptions newton;
  /// CHOLMOD: the 3-D default of issue 44 (K is SPD away from buckling).
  LinearSolverOptions linear_solver{LinearSolverKind::cholmod};
};

/// Throws InputError naming the field, its value and the allowed range.
void validate(const StructureT10Options& options);

class StructureT10 {
public:
  /// Builds the assembly pattern, mass and gravity forces, analyses the pattern once, and starts
  /// at rest with u = 0 and a^0 from M a^0 = f_g.
  StructureT10(TetMesh mesh, StructureT10Options options);

  const TetMesh& mesh() const { return mesh_; }
  const DofMap& dofs() const { return *dofs_; }

  /// Dead nodal external forces [N], size 3 * nodes (e.g. face_traction_forces); they act from
  /// the next step or static solve on. Entries on constrained dofs are ignored (reactions).
  void set_external_forces(const Vector& f_ext);

  /// Static equilibrium f_int(u) = lambda (f_ext + f_g) for lambda = 1/n, 2/n, ... 1 from the
  /// current u; sets v = a = 0. Returns one report per load step; throws RunError naming the
  /// load step if Newton fails.
  std::vector<StepReport> solve_static(int load_steps = 1);

  /// Starts a motion from u (the constrained entries must be zero) and v, with a from
  /// M a = f_ext + f_g - f_int(u).
  void set_initial_conditions(const Vector& u, const Vector& v);

  /// One Newmark step t -> t + dt (eqs. 40-41), Newton on u^{n+1} from u^n + dt v^n + dt^2 a^n/2.
  const StepReport& advance(double dt);

  const Vector& displacement() const { return u_; }
  const Vector& velocity() const { return v_; }
  double time() const { return time_; }
  /// Kinetic and strain energy and the work of gravity and the external forces (dead loads:
  /// f . u, which the trapezoidal rule integrates exactly).
  materials::SolidEnergies energies() const;

private:
  void newton(Vector& u, const NewtonResidual& residual, StepReport& report);
  /// Solves M a = f_ext + f_g - f_int(u) on the free dofs.
  void update_acceleration();

  TetMesh mesh_;
  StructureT10Options options_;
  std::unique_ptr<Material3> material_;
  std::unique_ptr<DofMap> dofs_;
  std::unique_ptr<AssemblerT10> assembler_;
  std::unique_ptr<LinearSolver> solver_;
  SparseMatrix M_, K_, K_eff_;
  Vector f_g_, f_ext_, f_int_;
  Vector u_, v_, a_;
  double time_ = 0.0;
  StepReport report_;
};

} // namespace fsi::fem
