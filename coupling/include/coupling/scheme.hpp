#pragma once
// The coupling scheme base: owns the step loop shared by every scheme (predict, checkpoint,
// evaluate, measure, accelerate, accept, log). A scheme subclass only says how one evaluation
// exchanges data and advances the solvers, and whether it checkpoints (style: preCICE's
// BaseCouplingScheme).
//
// Coupling vector (what accelerations see): for n interface nodes, 6n entries
//   [x_0x, x_0y, ..., x_(n-1)y | v_0x, ..., v_(n-1)y | a_0x, ..., a_(n-1)y],
// scaled for inner products by (1, dt, dt^2) per block so that all blocks are lengths [m].
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "coupling/acceleration.hpp"
#include "coupling/convergence.hpp"
#include "coupling/interface.hpp"
#include "coupling/options.hpp"
#include "coupling/predictor.hpp"
#include "coupling/stats.hpp"

namespace fsi::coupling {

/// What a scheme couples. Each scheme states which members it needs (make_scheme checks).
struct Participants {
  FluidSolver* fluid = nullptr;         ///< css, bgs, one_way_fluid
  StructureSolver* structure = nullptr; ///< css, bgs, one_way_structure
  MotionFunction prescribed_motion;     ///< one_way_fluid
  LoadFunction prescribed_loads;        ///< one_way_structure
};

/// Strategy objects of a scheme, built by the registry from the option names.
struct SchemeComponents {
  std::unique_ptr<Predictor> predictor; ///< first guess of the interface at t^{n+1}
  /// Non-null makes the scheme implicit (iterated within the step).
  std::unique_ptr<Acceleration> acceleration;
  /// Implicit schemes: measures[0] on positions, measures[1] (optional) on velocities.
  std::vector<std::unique_ptr<ConvergenceMeasure>> measures;
};

/// Coupling vector of a motion (layout above) and back; n = motion.size().
Eigen::VectorXd pack(const InterfaceMotion& motion);
InterfaceMotion unpack(const Eigen::VectorXd& z);
/// Per-entry weights (1, dt, dt^2 per block) for a coupling vector of n nodes.
Eigen::VectorXd coupling_scale(std::size_t n, double dt);

class CouplingScheme {
public:
  virtual ~CouplingScheme() = default;
  CouplingScheme(const CouplingScheme&) = delete;
  CouplingScheme& operator=(const CouplingScheme&) = delete;

  std::string_view name() const { return name_; }
  bool implicit() const { return components_.acceleration != nullptr; }

  /// Initialise the participants and take the initial interface state (at t0 [s]).
  void initialize(double t0 = 0.0);
  /// One coupling step from t to t + dt [s] (dt is the structure step; the fluid takes
  /// options.substeps sub-steps). Throws fsi::RunError on a non-finite residual, on interface
  /// size mismatch, and (with stop_on_unconverged) on the first unconverged step.
  void advance(double t, double dt);
  void finalize();

  /// Checkpoint between steps: the coupler's own state under "coupling/" (step index, accepted
  /// interface state, loads, statistics, the acceleration's history) and then each participant's
  /// (FluidSolver / StructureSolver::write_state). read_state() continues bitwise; it throws
  /// InputError when the archive does not fit (another interface, another acceleration).
  void write_state(StateArchive& archive) const;
  void read_state(const StateArchive& archive);

  /// Called after every step with its statistics (the per-step iteration log).
  void set_step_callback(StepCallback callback) { callback_ = std::move(callback); }
  const StepStats& last_step() const { return last_; }
  const CouplingSummary& summary() const { return summary_; }
  /// Accepted interface state at the end of the last step (after initialize: the initial one).
  const InterfaceMotion& interface_motion() const { return state_; }
  /// Loads handed to the structure in the last step (fluid loads averaged over sub-steps).
  const InterfaceLoads& interface_loads() const { return loads_; }
  const CouplingOptions& options() const { return options_; }

protected:
  CouplingScheme(std::string name, const CouplingOptions& options, SchemeComponents components);

  // --- hooks --------------------------------------------------------------------------------
  /// Initialise the solvers; return the interface state at t0.
  virtual InterfaceMotion initialize_participants(double t0) = 0;
  virtual void finalize_participants() = 0;
  /// The participants' checkpoint hooks (write_state / read_state).
  virtual void write_participants(StateArchive& archive) const = 0;
  virtual void read_participants(const StateArchive& archive) = 0;
  /// Checkpoint / roll back all participants to t^n (implicit schemes).
  virtual void save_checkpoint() {}
  virtual void restore_checkpoint() {}
  /// First input of the step. Default: the predictor applied to the accepted state.
  virtual InterfaceMotion first_input(double t, double dt);
  /// One evaluation of the step with interface input `input` (state at t + dt): exchange and
  /// advance in the scheme's order; return the interface state computed at t + dt.
  virtual InterfaceMotion evaluate(double t, double dt, const InterfaceMotion& input) = 0;
  /// true where input - output is the fixed-point residual (eq. 68); false (one-way schemes): it
  /// is meaningless and reported as 0.
  virtual bool has_residual() const { return false; }

  // --- helpers for subclasses (timed) --------------------------------------------------------
  /// The fluid over [t, t + dt] in options.substeps sub-steps k = 1..m; before sub-step k it gets
  /// motion_at(k/m). Stores the loads averaged over the sub-steps in loads_ and returns them.
  const InterfaceLoads& run_fluid(FluidSolver& fluid, double t, double dt,
                                  const std::function<InterfaceMotion(double s)>& motion_at);
  /// The structure over [t, t + dt] under `loads`; returns its interface state at t + dt.
  InterfaceMotion run_structure(StructureSolver& structure, const InterfaceLoads& loads, double t,
                                double dt);
  /// Serial exchange (css, bgs): fluid with `input` (linearly interpolated from the accepted
  /// state at sub-steps), then the structure with the fluid's loads.
  InterfaceMotion serial_evaluate(FluidSolver& fluid, StructureSolver& structure, double t,
                                  double dt, const InterfaceMotion& input);
  /// Time f() into the fluid or structure wall-time counter of the current step.
  template <class F> void time_fluid(F&& f) { timed(step_.time_fluid, std::forward<F>(f)); }
  template <class F> void time_structure(F&& f) { timed(step_.time_structure, std::forward<F>(f)); }

  const CouplingOptions options_;
  std::size_t n_nodes_ = 0;
  InterfaceMotion state_; ///< accepted interface state at the start of the current step
  InterfaceLoads loads_;

private:
  template <class F> static void timed(double& counter, F&& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    counter += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  void check_sizes(const InterfaceMotion& m, const char* what) const;

  std::string name_;
  SchemeComponents components_;
  StepCallback callback_;
  StepStats step_; // statistics of the step in progress
  StepStats last_;
  CouplingSummary summary_;
  long step_index_ = 0;
  bool initialized_ = false;
};

} // namespace fsi::coupling
