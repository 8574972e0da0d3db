#include "fsi_app/adapters.hpp"

#include "fsi/core/state_archive.hpp"

namespace fsi::app {

FluidAdapter::FluidAdapter(emps::EmpsFluid& fluid, erp::WallSet& walls,
                           const erp::InterfaceWalls& interface)
    : fluid_(fluid), walls_(walls), interface_(interface),
      loads_(coupling::InterfaceLoads::zeros(static_cast<std::size_t>(interface.node_count()))) {}

void FluidAdapter::set_interface_motion(const coupling::InterfaceMotion& m) {
  interface_.update_nodes(walls_, m.x, m.v, m.a); // eqs. 60-62
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
  const int first = interface_.first_segment(), last = first + interface_.segment_count();
  point_loads_.clear();
  auto add = [&](int s, double t, const Vec2& f) {
    if (s < first || s >= last) return;
    point_loads_.push_back(
        {static_cast<std::size_t>(interface_.edge(s)), interface_.parent_coordinate(s, t), -f});
  };
  for (std::size_t i = 0; i < w.segment.size(); ++i) {
    add(w.segment[i], w.t[i], w.f[i]);
    add(w.segment2[i], w.t2[i], w.f2[i]);
  }
  std::fill(loads_.f.begin(), loads_.f.end(), Vec2::Zero());
  coupling::project_point_loads(interface_.mesh(), point_loads_, loads_);
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

StructureAdapter::StructureAdapter(fem::Structure& structure, fem::FeInterface interface)
    : structure_(structure), interface_(std::move(interface)),
      forces_(fem::Vector::Zero(2 * static_cast<Eigen::Index>(structure.num_nodes()))) {}

void StructureAdapter::set_interface_loads(const coupling::InterfaceLoads& loads) {
  forces_.setZero();
  for (std::size_t k = 0; k < loads.size(); ++k) { // eq. 59
    const int K = interface_.fe_node[k];
    forces_[2 * K] = loads.f[k].x();
    forces_[2 * K + 1] = loads.f[k].y();
  }
  structure_.set_external_forces(forces_);
}

void StructureAdapter::advance(double, double dt) {
  const auto& report = structure_.advance(dt);
  newton_iterations_ += report.iterations;
  newton_max_ = std::max(newton_max_, report.iterations);
  newton_halvings_ += report.halvings;
  steps_with_halvings_ += report.halvings > 0 ? 1 : 0;
  if (report.substeps > 1) ++substepped_steps_, substeps_ += report.substeps;
}

void StructureAdapter::write_state(StateArchive& archive) const {
  structure_.write_state(archive, "structure/");
  archive.put("run/structure/newton", std::vector<std::int64_t>{newton_iterations_, newton_max_});
  archive.put("run/structure/halvings",
              std::vector<std::int64_t>{newton_halvings_, steps_with_halvings_, substepped_steps_,
                                        substeps_});
}

void StructureAdapter::read_state(const StateArchive& archive) {
  structure_.read_state(archive, "structure/");
  const auto& counts = archive.integers("run/structure/newton", 2);
  newton_iterations_ = counts[0], newton_max_ = static_cast<int>(counts[1]);
  if (archive.all_integers().count("run/structure/halvings")) { // absent before the safeguard
    const auto& h = archive.integers("run/structure/halvings", 4);
    newton_halvings_ = h[0], steps_with_halvings_ = h[1];
    substepped_steps_ = h[2], substeps_ = h[3];
  }
}

coupling::InterfaceMotion StructureAdapter::interface_motion() const {
  const std::size_t n = interface_.fe_node.size();
  coupling::InterfaceMotion m = coupling::InterfaceMotion::zeros(n);
  const auto& X = structure_.mesh().X;
  const auto &u = structure_.displacement(), &v = structure_.velocity(),
             &a = structure_.acceleration();
  for (std::size_t k = 0; k < n; ++k) { // eqs. 60-62
    const int K = interface_.fe_node[k];
    m.x[k] = X[static_cast<std::size_t>(K)] + Vec2(u[2 * K], u[2 * K + 1]);
    m.v[k] = Vec2(v[2 * K], v[2 * K + 1]);
    m.a[k] = Vec2(a[2 * K], a[2 * K + 1]);
  }
  return m;
}

} // namespace fsi::app
