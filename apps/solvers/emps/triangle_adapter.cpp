#include "emps/triangle_adapter.hpp"

#include "emps/triangle_loads.hpp"
#include "fsi/core/error.hpp"
#include "fsi/core/node_archive.hpp"
#include "fsi/core/state_archive.hpp"

#include <algorithm>
#include <span>
#include <string>

namespace fsi::app::emps_plugin {

TriangleAdapter::TriangleAdapter(emps::EmpsFluid3& fluid, erp::TriangleWallSet& walls,
                                 const std::vector<erp::InterfaceTriangles>& interfaces)
    : fluid_(fluid), walls_(walls), interfaces_(interfaces) {
  offset_.push_back(0);
  for (const auto& i : interfaces)
    offset_.push_back(offset_.back() + static_cast<std::size_t>(i.node_count()));
  loads_ = coupling::InterfaceLoads3::zeros(offset_.back());
}

void TriangleAdapter::set_interface_motion(const coupling::InterfaceMotion3& m) {
  if (m.size() != offset_.back())
    throw RunError("fluid_emps: interface motion of " + std::to_string(m.size()) +
                   " nodes, the fluid's interfaces have " + std::to_string(offset_.back()));
  for (std::size_t j = 0; j < interfaces_.size(); ++j) { // eqs. 60-62
    const std::size_t first = offset_[j], n = offset_[j + 1] - offset_[j];
    interfaces_[j].update_nodes(walls_, std::span(m.x).subspan(first, n),
                                std::span(m.v).subspan(first, n), std::span(m.a).subspan(first, n));
  }
  walls_.update();
}

void TriangleAdapter::advance(double t, double dt) {
  fluid_.advance(t, dt);
  for (std::size_t j = 0; j < interfaces_.size(); ++j) {
    project_triangle_forces(fluid_.triangle_forces(), interfaces_[j], part_);
    std::copy(part_.f.begin(), part_.f.end(),
              loads_.f.begin() + static_cast<std::ptrdiff_t>(offset_[j]));
  }
}

void TriangleAdapter::write_state(StateArchive& archive) const {
  fluid_.write_state(archive, "fluid/");
  put_nodes(archive, "walls/", walls_.nodes());
}

void TriangleAdapter::read_state(const StateArchive& archive) {
  fluid_.read_state(archive, "fluid/");
  read_nodes(archive, "walls/", walls_.nodes());
  walls_.update();
}

} // namespace fsi::app::emps_plugin
