#include "structure_fem/options.hpp"

namespace fsi::fem {

void visit_options(NewmarkOptions& o, OptionVisitor& v) {
  v.real("beta", o.beta, Range::left_open(0.0, 0.5), "beta_NB");
  v.real("gamma", o.gamma, Range::closed(0.5, 1.0), "gamma_NB");
}

void visit_options(NewtonOptions& o, OptionVisitor& v) {
  v.real("tolerance", o.residual_rtol, Range::open(0.0, 1.0),
         "residual norm relative to the load norm");
  v.real("increment_tolerance", o.increment_rtol, Range::open(0.0, 1.0),
         "increment norm relative to the displacement norm");
  v.integer("max_iterations", o.max_iterations, Range::closed(1, 1000),
            "iterations before the run stops");
  v.integer("substep_levels", o.max_substep_levels, Range::closed(0, 10),
            "a step whose Newton fails (no convergence, or an inverted element) is retried as 2, "
            "4, ... 2^levels sub-steps with the loads linear in time, each to the same "
            "tolerances; counted in run.json (docs/structure_fem.md); 0: the run stops");
}

void visit_options(LinearSolverOptions& o, OptionVisitor& v) {
  v.choice("linear_solver", o.kind,
           {{"auto", LinearSolverKind::ldlt_or_lu},
            {"cholmod", LinearSolverKind::cholmod},
            {"umfpack", LinearSolverKind::umfpack},
            {"ldlt", LinearSolverKind::simplicial_ldlt},
            {"cg", LinearSolverKind::cg_incomplete_cholesky},
            {"cg_amg", LinearSolverKind::cg_amg}},
           "sparse direct (CHOLMOD, UMFPACK, Eigen LDLT; auto: LDLT, UMFPACK LU for a matrix LDLT "
           "refuses, counted in run.json) or preconditioned CG (cg: incomplete Cholesky; cg_amg: "
           "smoothed-aggregation multigrid from the rigid-body modes, for 3-D)");
}

} // namespace fsi::fem
