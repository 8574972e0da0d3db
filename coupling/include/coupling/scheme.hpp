#pragma once
// The coupling scheme base: owns the step loop shared by every scheme (predict, checkpoint,
// evaluate, measure, accelerate, accept, log). A scheme subclass only says how one evaluation
// exchanges data and advances the solvers, and whether it checkpoints (style: preCICE's
// BaseCouplingScheme).
//
// Coupling vector (what accelerations see): for n interface nodes, 3Dn entries
//   [x_0x, x_0y, ..., x_(n-1)y | v_0x, ..., v_(n-1)y | a_0x, ..., a_(n-1)y]   (D = 2),
// in 3-D x, y, z per node; scaled for inner products by (1, dt, dt^2) per block so that all
// blocks are lengths [m]. Every type here is a template on D for D = 2 (today's names) and 3
// (names ending in 3).
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
template <int D> struct BasicParticipants {
  BasicFluidSolver<D>* fluid = nullptr;         ///< css, bgs, one_way_fluid
  BasicStructureSolver<D>* structure = nullptr; ///< css, bgs, one_way_structure
  BasicMotionFunction<D> prescribed_motion;     ///< one_way_fluid
  BasicLoadFunction<D> prescribed_loads;        ///< one_way_structure
};
using Participants = BasicParticipants<2>;
using Participants3 = BasicParticipants<3>;

/// Strategy objects of a scheme, built by the registry from the option names.
template <int D> struct BasicSchemeComponents {
  std::unique_ptr<BasicPredictor<D>> predictor; ///< first guess of the interface at t^{n+1}
  /// Non-null makes the scheme implicit (iterated within the step).
  std::unique_ptr<Acceleration> acceleration;
  /// Implicit schemes: measures[0] on positions, measures[1] (optional) on velocities.
  std::vector<std::unique_ptr<ConvergenceMeasure>> measures;
};
using SchemeComponents = BasicSchemeComponents<2>;
using SchemeComponents3 = BasicSchemeComponents<3>;

/// Coupling vector of a motion (layout above) and back; n = motion.size().
template <int D> Eigen::VectorXd pack(const BasicInterfaceMotion<D>& motion);
template <int D = 2> BasicInterfaceMotion<D> unpack(const Eigen::VectorXd& z);
/// Per-entry weights (1, dt, dt^2 per block) for a coupling vector of n nodes.
template <int D = 2> Eigen::VectorXd coupling_scale(std::size_t n, double dt);

extern template Eigen::VectorXd pack(const InterfaceMotion&);
extern template Eigen::VectorXd pack(const InterfaceMotion3&);
extern template InterfaceMotion unpack<2>(const Eigen::VectorXd&);
extern template InterfaceMotion3 unpack<3>(const Eigen::VectorXd&);
extern template Eigen::VectorXd coupling_scale<2>(std::size_t, double);
extern template Eigen::VectorXd coupling_scale<3>(std::size_t, double);

template <int D> class BasicCouplingScheme {
public:
  using Motion = BasicInterfaceMotion<D>;
  using Loads = BasicInterfaceLoads<D>;
  using Fluid = BasicFluidSolver<D>;
  using Structure = BasicStructureSolver<D>;

  virtual ~BasicCouplingScheme() = default;
  BasicCouplingScheme(const BasicCouplingScheme&) = delete;
  BasicCouplingScheme& operator=(const BasicCouplingScheme&) = delete;

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
  const Motion& interface_motion() const { return state_; }
  /// Loads handed to the structure in the last step (fluid loads averaged over sub-steps).
  const Loads& interface_loads() const { return loads_; }
  const CouplingOptions& options() const { return options_; }

protected:
  BasicCouplingScheme(std::string name, const CouplingOptions& options,
                      BasicSchemeComponents<D> components);

  // --- hooks --------------------------------------------------------------------------------
  /// Initialise the solvers; return the interface state at t0.
  virtual Motion initialize_participants(double t0) = 0;
  virtual void finalize_participants() = 0;
  /// The participants' checkpoint hooks (write_state / read_state).
  virtual void write_participants(StateArchive& archive) const = 0;
  virtual void read_participants(const StateArchive& archive) = 0;
  /// Checkpoint / roll back all participants to t^n (implicit schemes).
  virtual void save_checkpoint() {}
  virtual void restore_checkpoint() {}
  /// First input of the step. Default: the predictor applied to the accepted state.
  virtual Motion first_input(double t, double dt);
  /// One evaluation of the step with interface input `input` (state at t + dt): exchange and
  /// advance in the scheme's order; return the interface state computed at t + dt.
  virtual Motion evaluate(double t, double dt, const Motion& input) = 0;
  /// true where input - output is the fixed-point residual (eq. 68); false (one-way schemes): it
  /// is meaningless and reported as 0.
  virtual bool has_residual() const { return false; }

  // --- helpers for subclasses (timed) --------------------------------------------------------
  /// The fluid over [t, t + dt] in options.substeps sub-steps k = 1..m; before sub-step k it gets
  /// motion_at(k/m). Stores the loads averaged over the sub-steps in loads_ and returns them.
  const Loads& run_fluid(Fluid& fluid, double t, double dt,
                         const std::function<Motion(double s)>& motion_at);
  /// The structure over [t, t + dt] under `loads`; returns its interface state at t + dt.
  Motion run_structure(Structure& structure, const Loads& loads, double t, double dt);
  /// Serial exchange (css, bgs): fluid with `input` (linearly interpolated from the accepted
  /// state at sub-steps), then the structure with the fluid's loads.
  Motion serial_evaluate(Fluid& fluid, Structure& structure, double t, double dt,
                         const Motion& input);
  /// Time f() into the fluid or structure wall-time counter of the current step.
  template <class F> void time_fluid(F&& f) { timed(step_.time_fluid, std::forward<F>(f)); }
  template <class F> void time_structure(F&& f) { timed(step_.time_structure, std::forward<F>(f)); }

  const CouplingOptions options_;
  std::size_t n_nodes_ = 0;
  Motion state_; ///< accepted interface state at the start of the current step
  Loads loads_;

private:
  template <class F> static void timed(double& counter, F&& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    counter += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  void check_sizes(const Motion& m, const char* what) const;

  std::string name_;
  BasicSchemeComponents<D> components_;
  StepCallback callback_;
  StepStats step_; // statistics of the step in progress
  StepStats last_;
  CouplingSummary summary_;
  long step_index_ = 0;
  bool initialized_ = false;
};

extern template class BasicCouplingScheme<2>;
extern template class BasicCouplingScheme<3>;
using CouplingScheme = BasicCouplingScheme<2>;
using CouplingScheme3 = BasicCouplingScheme<3>;

} // namespace fsi::coupling
