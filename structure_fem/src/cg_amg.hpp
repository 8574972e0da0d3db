#pragma once
// cg_amg: conjugate gradient preconditioned by one smoothed-aggregation V-cycle.
#include <memory>

#include "structure_fem/linear_solver.hpp"

namespace fsi::fem {

std::unique_ptr<LinearSolver> make_cg_amg(const LinearSolverOptions& options);

} // namespace fsi::fem
