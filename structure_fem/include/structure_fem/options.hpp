#pragma once
// The FE structure's user options, each declared once (key, member, range, doc; the member's
// initial value is the default) for readers such as the scene file (fsi/core/options.hpp).
#include "fsi/core/options.hpp"
#include "structure_fem/linear_solver.hpp"
#include "structure_fem/newmark.hpp"
#include "structure_fem/structure.hpp"

namespace fsi::fem {

/// beta, gamma of eqs. 40-41.
void visit_options(NewmarkOptions& options, OptionVisitor& visitor);
/// tolerance, increment_tolerance, max_iterations, substep_levels.
void visit_options(NewtonOptions& options, OptionVisitor& visitor);
/// linear_solver: the kind.
void visit_options(LinearSolverOptions& options, OptionVisitor& visitor);

} // namespace fsi::fem
