#pragma once
// The EMPS fluid and the FEM structure behind the coupler's interfaces (eqs. 50-62), each on its
// own: the fluid sees the structure only as an interface mesh, the structure sees only nodal
// loads. These are the only classes that know a concrete solver and the coupling library.
// Interface node k is polygon node L = first_node + k of the interface walls and FE node
// K = fe_node[k] (NCR, eq. 50).
#include "coupling/interface.hpp"
#include "coupling/projection.hpp"
#include "fluid_emps/emps_fluid.hpp"
#include "geometry_erp/interface_walls.hpp"
#include "structure_fem/interface_mesh.hpp"
#include "structure_fem/structure.hpp"

#include <optional>

namespace fsi::app {

/// F (eq. 66): wall motion in; particle wall forces out, as point loads projected with the
/// interface edge's shape functions (eqs. 52-59).
class FluidAdapter final : public coupling::FluidSolver {
public:
  FluidAdapter(emps::EmpsFluid& fluid, erp::WallSet& walls, const erp::InterfaceWalls& interface);
  void initialize() override {}
  void set_interface_motion(const coupling::InterfaceMotion& motion) override;
  void advance(double t, double dt) override;
  const coupling::InterfaceLoads& interface_loads() const override { return loads_; }
  void save_state() override;
  void restore_state() override;
  /// The fluid under "fluid/", all wall nodes under "walls/".
  void write_state(StateArchive& archive) const override;
  void read_state(const StateArchive& archive) override;

private:
  void project();

  emps::EmpsFluid& fluid_;
  erp::WallSet& walls_;
  const erp::InterfaceWalls& interface_;
  std::vector<coupling::PointLoad> point_loads_;
  coupling::InterfaceLoads loads_;
  std::optional<emps::EmpsFluid::State> saved_;
};

/// S (eq. 67): interface loads in (as FE nodal forces); FE node motion out (eqs. 60-62).
class StructureAdapter final : public coupling::StructureSolver {
public:
  StructureAdapter(fem::Structure& structure, fem::FeInterface interface);
  void initialize() override {}
  void set_interface_loads(const coupling::InterfaceLoads& loads) override;
  void advance(double t, double dt) override;
  coupling::InterfaceMotion interface_motion() const override;
  void save_state() override { saved_ = structure_.save(); }
  void restore_state() override { structure_.restore(*saved_); }
  /// The structure under "structure/", with the Newton counters.
  void write_state(StateArchive& archive) const override;
  void read_state(const StateArchive& archive) override;

  /// The interface the structure describes, with its FE nodes.
  const fem::FeInterface& interface() const { return interface_; }
  /// Newton iterations of all advances so far, and the most in one.
  long newton_iterations() const { return newton_iterations_; }
  int newton_max() const { return newton_max_; }
  long newton_halvings() const { return newton_halvings_; }
  long steps_with_halvings() const { return steps_with_halvings_; }
  long substepped_steps() const { return substepped_steps_; }
  long substeps() const { return substeps_; }

private:
  fem::Structure& structure_;
  fem::FeInterface interface_;
  fem::Vector forces_;
  std::optional<fem::StructureState> saved_;
  long newton_iterations_ = 0;
  int newton_max_ = 0;
  long newton_halvings_ = 0, steps_with_halvings_ = 0; ///< Newton safeguard (Structure::newton)
  long substepped_steps_ = 0, substeps_ = 0;           ///< retried steps, their sub-steps
};

} // namespace fsi::app
