#pragma once
// The 3-D EMPS fluid behind the coupler's F interface (eq. 66), the counterpart of the 2-D
// FluidAdapter: the fluid sees each structure as its interface's flat triangles
// (erp::InterfaceTriangles, whose wall nodes are the interface nodes, eq. 50); the coupler's
// interface nodes are the structures' nodes concatenated in order. One fluid step a coupler step.
#include "coupling/interface.hpp"
#include "fluid_emps/emps_fluid.hpp"
#include "geometry_erp/interface_triangles.hpp"

#include <optional>
#include <vector>

namespace fsi::app::emps_plugin {

class TriangleAdapter final : public coupling::FluidSolver3 {
public:
  TriangleAdapter(emps::EmpsFluid3& fluid, erp::TriangleWallSet& walls,
                  const std::vector<erp::InterfaceTriangles>& interfaces);
  void initialize() override {}
  /// Eqs. 60-62: the interface nodes' x, v, a become the wall nodes'; the normals follow
  /// (walls.update(); the fluid refits its triangle index at the start of its step).
  void set_interface_motion(const coupling::InterfaceMotion3& motion) override;
  /// One fluid step, then its wall forces on each interface's triangles as nodal loads
  /// (project_triangle_forces, eqs. 52-59).
  void advance(double t, double dt) override;
  const coupling::InterfaceLoads3& interface_loads() const override { return loads_; }
  void save_state() override { saved_ = fluid_.save(); }
  void restore_state() override { fluid_.restore(*saved_); }
  /// The fluid under "fluid/", the wall nodes' x, v, a under "walls/".
  void write_state(StateArchive& archive) const override;
  void read_state(const StateArchive& archive) override;

private:
  emps::EmpsFluid3& fluid_;
  erp::TriangleWallSet& walls_;
  const std::vector<erp::InterfaceTriangles>& interfaces_;
  std::vector<std::size_t> offset_; ///< first coupler node of each interface, and the total
  coupling::InterfaceLoads3 part_, loads_;
  std::optional<emps::EmpsFluid3::State> saved_;
};

} // namespace fsi::app::emps_plugin
