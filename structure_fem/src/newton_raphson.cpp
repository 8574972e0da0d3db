#include "structure_fem/newton_raphson.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "fsi/core/error.hpp"
#include "structure_fem/assembly.hpp"

namespace fsi::fem {

void validate(const NewtonOptions& n) {
  auto non_negative = [](const char* key, double v) {
    if (!(v >= 0.0) || !std::isfinite(v))
      throw InputError(std::string("newton: ") + key + " = " + std::to_string(v) +
                       ": must be >= 0");
  };
  if (n.max_iterations < 1)
    throw InputError("newton: max_iterations = " + std::to_string(n.max_iterations) +
                     ": must be >= 1");
  non_negative("residual_rtol", n.residual_rtol);
  non_negative("residual_atol", n.residual_atol);
  non_negative("increment_rtol", n.increment_rtol);
  non_negative("increment_atol", n.increment_atol);
  non_negative("roundoff_rtol", n.roundoff_rtol);
  if (n.max_substep_levels < 0 || n.max_substep_levels > 10)
    throw InputError("newton: max_substep_levels = " + std::to_string(n.max_substep_levels) +
                     ": must be in [0, 10]");
  if (n.max_halvings < 0)
    throw InputError("newton: max_halvings = " + std::to_string(n.max_halvings) + ": must be >= 0");
}

namespace {
/// The node of the free dof with the largest |R| (the first non-finite one if any).
int worst_node(const DofMap& dofs, const Vector& R) {
  Eigen::Index worst = 0;
  for (Eigen::Index i = 0; i < R.size(); ++i) {
    if (!std::isfinite(R[i])) {
      worst = i;
      break;
    }
    if (std::abs(R[i]) > std::abs(R[worst])) worst = i;
  }
  for (int d = 0; d < dofs.num_dofs(); ++d)
    if (dofs.free_index(d) == worst) return d / dofs.dim();
  return -1;
}
} // namespace

void newton_raphson(const NewtonOptions& o, const DofMap& dofs, double force_scale,
                    const NewtonResidual& residual, const NewtonLinearSolve& solve, Vector& u,
                    StepReport& report) {
  report.history.clear();
  report.halvings = 0;
  report.roundoff_stops = 0;
  Vector R, du;
  double R_ref = 0.0;
  residual(u, R);
  for (int k = 0;; ++k) {
    const double r = R.norm();
    report.final_residual = r;
    if (!std::isfinite(r))
      throw RunError("Newton: the residual is not finite at node " +
                     std::to_string(worst_node(dofs, R)));
    if (k == 0) R_ref = std::max(r, force_scale);
    const bool residual_ok = r <= o.residual_atol + o.residual_rtol * R_ref;
    const bool increment_ok = k == 0 ? r <= o.residual_atol
                                     : report.history.back().increment_norm <=
                                           o.increment_atol + o.increment_rtol * u.norm();
    const auto& h = report.history;
    const bool at_roundoff =
        (k > 0 && h.back().increment_norm <= o.roundoff_rtol * u.norm()) ||
        (residual_ok && k >= 2 &&
         h[h.size() - 1].increment_norm > 0.5 * h[h.size() - 2].increment_norm);
    if ((residual_ok && increment_ok) || at_roundoff) {
      report.iterations = k;
      if (!(residual_ok && increment_ok)) report.roundoff_stops = 1;
      return;
    }
    if (k == o.max_iterations) {
      std::ostringstream s;
      s << "Newton did not converge in " << o.max_iterations << " iterations (residual " << r
        << ", tolerance " << o.residual_atol + o.residual_rtol * R_ref << "; last increment "
        << report.history.back().increment_norm << ", tolerance "
        << o.increment_atol + o.increment_rtol * u.norm() << "; largest residual at node "
        << worst_node(dofs, R) << ")";
      throw RunError(s.str());
    }
    int its = 0;
    du = solve(-R, its);
    report.history.push_back({r, du.norm(), its});
    for (int halving = 0;; ++halving) { // u + du, or u + du / 2^m if u + du is inverted
      Vector u_trial = u;
      dofs.add_free(du, u_trial);
      try {
        residual(u_trial, R);
      } catch (const InvertedElement& e) {
        if (halving == o.max_halvings)
          throw InvertedElement(std::string(e.what()) + " in Newton iteration " +
                                std::to_string(k + 1) + " after " + std::to_string(halving) +
                                " halvings of the increment");
        du *= 0.5;
        ++report.halvings;
        continue;
      }
      u = std::move(u_trial);
      break;
    }
  }
}

} // namespace fsi::fem
