#include "emps/emps_adapter.hpp"

#include "fsi/core/state_archive.hpp"

#include <algorithm>

namespace fsi::app::emps_plugin {

FluidAdapter::FluidAdapter(emps::EmpsFluid& fluid, erp::WallSet& walls,
                           const std::vector<erp::InterfaceWalls>& interfaces)
    : fluid_(fluid), walls_(walls), interfaces_(interfaces) {
  offset_.push_back(0);
  for (const auto& i : interfaces)
    offset_.push_back(offset_.back() + static_cast<std::size_t>(i.node_count()));
  loads_ = coupling::InterfaceLoads::zeros(offset_.back());
}

void FluidAdapter::set_interface_motion(const coupling::InterfaceMotion& m) {
  for (std::size_t j = 0; j < interfaces_.size(); ++j) { // eqs. 60-62
    const std::size_t first = offset_[j], n = offset_[j + 1] - offset_[j];
    interfaces_[j].update_nodes(walls_, std::span(m.x).subspan(first, n),
                                std::span(m.v).subspan(first, n), std::span(m.a).subspan(first, n));
  }
}

void FluidAdapter::advance(double t, double dt) {
  walls_.move_rigid(t + dt);
  fluid_.advance(t, dt);
  project();
}

// Each particle's wall force on an interface segment acts on the structure as -f_wall at its
// wall point (eqs. 53-58), distributed over the interface edge's nodes.
void FluidAdapter::project() {
  const emps::WallForces& w = fluid_.wall_forces();
  for (std::size_t j = 0; j < interfaces_.size(); ++j) {
    const erp::InterfaceWalls& iw = interfaces_[j];
    const int first = iw.first_segment(), last = first + iw.segment_count();
    point_loads_.clear();
    auto add = [&](int s, double t, const Vec2& f) {
      if (s < first || s >= last) return;
      point_loads_.push_back(
          {static_cast<std::size_t>(iw.edge(s)), iw.parent_coordinate(s, t), -f});
    };
    for (std::size_t i = 0; i < w.size(); ++i)
      for (const emps::FaceForces& f : w.face) add(f.segment[i], f.t[i], f.f[i]);
    part_.f.assign(static_cast<std::size_t>(iw.node_count()), Vec2::Zero()); // keeps capacity
    coupling::project_point_loads(iw.mesh(), point_loads_, part_);
    std::copy(part_.f.begin(), part_.f.end(),
              loads_.f.begin() + static_cast<std::ptrdiff_t>(offset_[j]));
  }
}

void FluidAdapter::save_state() {
  saved_ = fluid_.save();
}

void FluidAdapter::restore_state() {
  fluid_.restore(*saved_);
}

void FluidAdapter::write_state(StateArchive& archive) const {
  fluid_.write_state(archive, "fluid/");
  walls_.write_state(archive, "walls/");
}

void FluidAdapter::read_state(const StateArchive& archive) {
  fluid_.read_state(archive, "fluid/");
  walls_.read_state(archive, "walls/");
}

} // namespace fsi::app::emps_plugin
