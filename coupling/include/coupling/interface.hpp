#pragma once
// Interface data and the two abstract solvers seen by the coupler (EMPS-ERP-FEM paper, eqs. 66-67).
//
// Interface quantities live on a fixed, ordered set of interface nodes. The coupler knows only
// their count; the adapters map them to FE nodes and to polygon nodes through the node
// correspondence relation NCR (eqs. 59-62). Nothing here knows about particles, meshes or a
// particular method.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fsi/core/node_motion.hpp"
#include "fsi/core/types.hpp"

namespace fsi {
class StateArchive;
}

namespace fsi::coupling {

/// State of the interface nodes at one instant (eqs. 60-62): current positions x = x0 + u [m],
/// velocities v [m/s] and accelerations a [m/s^2].
template <int D> using BasicInterfaceMotion = BasicNodeMotion<D>;
using InterfaceMotion = BasicInterfaceMotion<2>;
using InterfaceMotion3 = BasicInterfaceMotion<3>;

/// Nodal forces on the structure at the interface nodes (f^{F->S}, eqs. 58-59) [N per unit
/// thickness in 2-D, N in 3-D]. Sign: the force the fluid exerts ON the structure (= -f_wall
/// summed, eq. 58). BasicInterfaceLoads<D> for D = 2 (InterfaceLoads) and 3 (InterfaceLoads3).
template <int D> struct BasicInterfaceLoads {
  std::vector<VecD<D>> f;

  std::size_t size() const { return f.size(); }
  static BasicInterfaceLoads zeros(std::size_t n);
};

extern template struct BasicInterfaceLoads<2>;
extern template struct BasicInterfaceLoads<3>;
using InterfaceLoads = BasicInterfaceLoads<2>;
using InterfaceLoads3 = BasicInterfaceLoads<3>;

/// Prescribed interface motion at time t (one-way fluid runs).
template <int D> using BasicMotionFunction = std::function<BasicInterfaceMotion<D>(double t)>;
using MotionFunction = BasicMotionFunction<2>;
using MotionFunction3 = BasicMotionFunction<3>;
/// Prescribed interface loads at time t (one-way structure runs, e.g. recorded loads).
template <int D> using BasicLoadFunction = std::function<BasicInterfaceLoads<D>(double t)>;
using LoadFunction = BasicLoadFunction<2>;
using LoadFunction3 = BasicLoadFunction<3>;

/// (1 - s) a + s b, node by node, for x, v and a. Exact at the ends: s = 0 gives a, s = 1 gives b.
template <int D>
BasicInterfaceMotion<D> interpolate(const BasicInterfaceMotion<D>& a,
                                    const BasicInterfaceMotion<D>& b, double s);

extern template InterfaceMotion interpolate(const InterfaceMotion&, const InterfaceMotion&, double);
extern template InterfaceMotion3 interpolate(const InterfaceMotion3&, const InterfaceMotion3&,
                                             double);

/// What the coupler drives in either solver.
///
/// Lifecycle: initialize(); then per step [save_state(); {restore_state();} set the interface
/// input; advance(); read the output]...; finalize().
class Participant {
public:
  virtual ~Participant() = default;
  virtual void initialize() = 0;
  /// Advance from t to t + dt [s].
  virtual void advance(double t, double dt) = 0;
  /// Checkpoint the full solver state; restore_state() returns to it exactly (iterative coupling
  /// re-runs a step). One checkpoint is enough: a new save overwrites the old one.
  virtual void save_state() = 0;
  virtual void restore_state() = 0;
  /// Checkpoint of the whole solver between two steps (everything its next advance() reads), so
  /// that read_state() continues bitwise. Solvers without checkpoints keep the default, which
  /// throws RunError (a run asked for a checkpoint this solver cannot give).
  virtual void write_state(StateArchive& archive) const;
  virtual void read_state(const StateArchive& archive);
  virtual void finalize() {}
};

/// The fluid solver F (eq. 66): given the wall motion, advance and report the wall loads.
/// BasicFluidSolver<D> for D = 2 (FluidSolver) and 3 (FluidSolver3).
template <int D> class BasicFluidSolver : public Participant {
public:
  /// The interface (wall) state at the END of the step that the next advance() computes.
  virtual void set_interface_motion(const BasicInterfaceMotion<D>& motion) = 0;
  /// Loads on the structure from the last advance(), projected to the interface nodes
  /// (eqs. 52-59). Valid until the next advance() or restore_state().
  virtual const BasicInterfaceLoads<D>& interface_loads() const = 0;
  /// Largest stable time step [s] if the solver has such a limit (CFL, viscous, ...).
  virtual std::optional<double> stable_dt() const { return std::nullopt; }
};
using FluidSolver = BasicFluidSolver<2>;
using FluidSolver3 = BasicFluidSolver<3>;

/// The structure solver S (eq. 67): given the interface loads, advance and report the interface
/// motion.
///
/// The motion predictor (eqs. 63-65) is not a solver duty: it is computed by the coupler from
/// interface_motion() (see predictor.hpp). BasicStructureSolver<D> for D = 2 (StructureSolver)
/// and 3 (StructureSolver3).
template <int D> class BasicStructureSolver : public Participant {
public:
  /// Loads acting over the step that the next advance() computes (at its end, t + dt).
  virtual void set_interface_loads(const BasicInterfaceLoads<D>& loads) = 0;
  /// Interface state after the last advance() (after initialize(): the initial state).
  virtual BasicInterfaceMotion<D> interface_motion() const = 0;
};
using StructureSolver = BasicStructureSolver<2>;
using StructureSolver3 = BasicStructureSolver<3>;

} // namespace fsi::coupling
