#pragma once
// The EMPS fluid behind the coupler's F interface (eqs. 50-62). The fluid sees each structure
// only as its interface mesh: interface node k of structure s is polygon node first_node + k of
// that structure's interface walls, and the coupler's interface nodes are the structures' nodes
// concatenated in order.
#include "coupling/interface.hpp"
#include "coupling/projection.hpp"
#include "fluid_emps/emps_fluid.hpp"
#include "geometry_erp/interface_walls.hpp"

#include <optional>
#include <vector>

namespace fsi::app::emps_plugin {

/// F (eq. 66): wall motion in; particle wall forces out, as point loads projected with the
/// interface edge's shape functions (eqs. 52-59).
class FluidAdapter final : public coupling::FluidSolver {
public:
  FluidAdapter(emps::EmpsFluid& fluid, erp::WallSet& walls,
               const std::vector<erp::InterfaceWalls>& interfaces);
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
  const std::vector<erp::InterfaceWalls>& interfaces_;
  std::vector<std::size_t> offset_; ///< first coupler node of each interface, and the total
  std::vector<coupling::PointLoad> point_loads_;
  coupling::InterfaceLoads part_, loads_;
  std::optional<emps::EmpsFluid::State> saved_;
};

} // namespace fsi::app::emps_plugin
