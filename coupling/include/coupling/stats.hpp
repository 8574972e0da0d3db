#pragma once
// Per-step coupling statistics and their running summary (for logs and run.json).
#include <functional>
#include <optional>

namespace fsi::coupling {

struct StepStats {
  long step = 0;      ///< 0-based index of the coupling step
  double t = 0.0;     ///< start of the step [s]
  double dt = 0.0;    ///< coupling (structure) step [s]
  int iterations = 0; ///< F + S evaluations in the step (1 for staggered and one-way schemes)
  /// ||x~ - x|| of the interface positions (eq. 68) [m] at the first and the last evaluation.
  /// CSS reports the predictor mismatch; one-way schemes report 0.
  double residual_initial = 0.0;
  double residual_final = 0.0;
  /// Relaxation factor of the last update; empty when the last update was not a relaxation
  /// (quasi-Newton update, staggered scheme, or converged at the first evaluation).
  std::optional<double> omega;
  bool converged = true;   ///< false: max_iterations reached (implicit schemes only)
  double time_fluid = 0.0; ///< wall time in F (advance, save, restore, exchange) [s]
  double time_structure = 0.0;
  double time_coupler = 0.0; ///< the rest of the step: predictor, acceleration, measures [s]
};

struct CouplingSummary {
  long steps = 0;
  long iterations = 0;    ///< total over all steps
  int max_iterations = 0; ///< largest per step
  long unconverged = 0;   ///< steps that hit max_iterations
  double time_fluid = 0.0, time_structure = 0.0, time_coupler = 0.0; ///< [s]

  double mean_iterations() const {
    return steps > 0 ? static_cast<double>(iterations) / static_cast<double>(steps) : 0.0;
  }
  void add(const StepStats& s);
};

using StepCallback = std::function<void(const StepStats&)>;

} // namespace fsi::coupling
