#pragma once
// Newton–Raphson on the free degrees of freedom with step halving and round-off stops, shared by
// the T6 and T10 solids (static load steps and Newmark steps).
#include <functional>
#include <vector>

#include "structure_fem/dof_map.hpp"
#include "structure_fem/types.hpp"

namespace fsi::fem {

/// Newton–Raphson convergence: iteration k has converged when
///   ||R_k|| <= residual_atol + residual_rtol * R_ref   (R_ref = max(||R_0||, ||f_ext + f_g||))
/// and, for k >= 1, ||du_k|| <= increment_atol + increment_rtol * ||u||,
/// with R on the free dofs. A step with ||R_0|| <= residual_atol needs no iteration. It has also
/// converged when ||du_k|| <= roundoff_rtol * ||u||: the residual is then at its round-off floor
/// (which grows with the condition number) and no further progress is possible in double; and
/// when the residual test holds and, for k >= 2, ||du_k|| > ||du_{k-1}|| / 2: Newton's increments
/// shrink quadratically until they reach the round-off of the linear solve, so one that no longer
/// halves is that floor. Both are counted (StepReport::roundoff_stops).
struct NewtonOptions {
  int max_iterations = 20;       ///< >= 1
  double residual_rtol = 1e-8;   ///< >= 0
  double residual_atol = 1e-10;  ///< [N/m], >= 0
  double increment_rtol = 1e-10; ///< >= 0
  double increment_atol = 1e-14; ///< [m], >= 0
  double roundoff_rtol = 1e-13;  ///< >= 0
  /// An iterate u + du with an inverted element (det F <= 0) is not a configuration of the body:
  /// du is halved, at most this many times, before the step fails with the inversion. The
  /// convergence test uses the full ||du||, and the converged u has det F > 0 everywhere.
  int max_halvings = 10; ///< >= 0
  /// A dynamic step that fails (Newton does not converge, or an element inverts) is taken again
  /// from the same state as 2, 4, ... 2^max_substep_levels sub-steps, the external forces linear
  /// in time between those of t^n and t^{n+1}; each sub-step meets the same tolerances. 0: off.
  int max_substep_levels = 0; ///< in [0, 10]
};

/// Throws InputError naming the field ("newton: key"), its value and the allowed range.
void validate(const NewtonOptions& options);

struct NewtonIterationLog {
  double residual_norm;  ///< ||R|| on the free dofs before the solve [N/m]
  double increment_norm; ///< ||du|| of the solve [m]
  int linear_iterations; ///< CG iterations (1 for direct solvers)
};

/// What one Newton solve did; the caller logs it.
struct StepReport {
  long step = 0;          ///< dynamic: index of the step just taken; static: load step
  double time = 0.0;      ///< dynamic: t^{n+1}; static: load factor
  int iterations = 0;     ///< Newton iterations (linear solves)
  int halvings = 0;       ///< increments halved because the iterate had an inverted element
  int roundoff_stops = 0; ///< Newton solves ended at the round-off floor (NewtonOptions)
  int substeps = 1;       ///< dynamic: sub-steps the step needed (1: none; NewtonOptions)
  int guess_retries = 0;  ///< dynamic: Newton solves retried from u^n + dt v^n (eq. 64 failed)
  double final_residual = 0.0;
  std::vector<NewtonIterationLog> history;
};

/// residual(u, R): R on the free dofs at u, and the effective tangent at u left where solve uses
/// it. Throws InvertedElement if u has an element with det F <= 0.
using NewtonResidual = std::function<void(const Vector& u, Vector& R)>;
/// solve(rhs, iterations): the effective tangent's inverse applied to rhs (factorising it).
using NewtonLinearSolve = std::function<Vector(const Vector& rhs, int& iterations)>;

/// Iterates u <- u + du, K_eff du = -R, until the convergence test of NewtonOptions holds;
/// force_scale is ||f_ext + f_g|| on the free dofs (for R_ref). Fills report's iterations,
/// halvings, round-off stops, final residual and history. Throws RunError if it does not
/// converge or the residual is not finite, InvertedElement after max_halvings halvings.
void newton_raphson(const NewtonOptions& options, const DofMap& dofs, double force_scale,
                    const NewtonResidual& residual, const NewtonLinearSolve& solve, Vector& u,
                    StepReport& report);

} // namespace fsi::fem
