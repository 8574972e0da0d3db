#include "emps/emps_model.hpp"

#include "emps/emps_report.hpp"

#include "fsi_app/finite_guard.hpp"
#include "fsi_app/wall_motion.hpp"
#include "particles/kernels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace fsi::app::emps_plugin {

emps::FluidOptions fluid_options(const Scene& scene) {
  const FluidSpec& f = scene.fluid->as<FluidSpec>();
  emps::FluidOptions o = f.options;
  o.gravity = scene.gravity;
  std::tie(o.domain_min, o.domain_max) = f.area.domain_or_box(scene, 4.0 * o.r_e());
  return o;
}

EmpsModel::EmpsModel(const Scene& scene, const std::vector<InterfaceMesh>& interfaces,
                     const std::vector<Polygon>& solid, const Ranks& ranks)
    : walls_(std::make_unique<erp::WallSet>()), probes_(scene.output.probes) {
  int group = 0;
  for (const auto& w : scene.walls) {
    wall_names_.push_back("wall '" + w.name + "'");
    if (w.motion)
      walls_->add_rigid_polyline(w.polyline, w.closed, group++, w.motion->pivot, make_motion(w));
    else
      walls_->add_polyline(w.polyline, w.closed, group++);
  }
  interface_walls_.reserve(interfaces.size()); // the adapter keeps a reference to the list
  for (const auto& mesh : interfaces) {
    wall_names_.push_back("interface " + std::to_string(interface_walls_.size()));
    interface_walls_.emplace_back(*walls_, mesh, group++);
  }
  const FluidSpec& f = scene.fluid->as<FluidSpec>();
  const auto [positions, block] =
      ranks_.setup(ranks, fill_regions(scene, f.area.regions, f.options.l0, solid));
  fluid_ = std::make_unique<emps::EmpsFluid>(fluid_options(scene), positions, *walls_, block);
  adapter_ = std::make_unique<FluidAdapter>(*fluid_, *walls_, interface_walls_);
}

void EmpsModel::advance(double time, double dt) {
  walls_->move_rigid(time + dt);
  fluid_->advance(time, dt);
}

std::optional<double> EmpsModel::stable_dt(double courant) const {
  return fluid_->stable_dt(courant);
}

void EmpsModel::declare(FieldsFile&) const {}

bool EmpsModel::decompose(const Ranks& ranks) {
  fluid_->decompose(ranks_.decompose(ranks));
  return true;
}

void EmpsModel::gather_frame() {
  if (!ranks_.decomposed()) return;
  gathered_.gather(ranks_, fluid_->particles(), fluid_->owned());
  kinetic_energy_ = fluid_->kinetic_energy(); // collective
  gathered_force_ = wall_force();             // collective
  if (ranks_.rows())
    ranks_.evaluate_probes(probes_, [&](const ProbeSpec& p) { return evaluate(p); });
}

emps::WallForceParts EmpsModel::wall_force() const {
  const auto [first, last] = interface_segments();
  emps::WallForceParts f = fluid_->wall_force_parts(first, last); // this rank's particles
  if (!ranks_.decomposed()) return f;
  std::vector<double> sum{f.pressure.x(),  f.pressure.y(), f.repulsive.x(),
                          f.repulsive.y(), f.viscous.x(),  f.viscous.y()};
  ranks_.sum(sum);
  return {{sum[0], sum[1]}, {sum[2], sum[3]}, {sum[4], sum[5]}};
}

void EmpsModel::write_frame(FieldsFile& file, const std::vector<std::string>& fields) const {
  const FrameParticles<2> p = frame();
  const std::size_t n = p.n;
  xy_.resize(2 * n);
  v_.resize(2 * n);
  flag_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    xy_[2 * i] = p.x[0][i], xy_[2 * i + 1] = p.x[1][i];
    v_[2 * i] = p.v[0][i], v_[2 * i + 1] = p.v[1][i];
    flag_[i] = p.surface[i];
  }
  file.write_grid("particles", xy_,
                  select_fields(fields, {{"velocity", 2, v_.data()},
                                         {"pressure", 1, p.p},
                                         {"pnd", 1, p.pnd},
                                         {"free_surface", 1, flag_.data()}}),
                  2, ranks_.rows());
}

std::optional<double> EmpsModel::probe(const ProbeSpec& probe) const {
  return ranks_.rows() ? ranks_.probe_value(probe) : evaluate(probe);
}

std::optional<double> EmpsModel::evaluate(const ProbeSpec& probe) const {
  const FrameParticles<2> p = frame();
  if (probe.quantity ==
      "surge_front") { // largest x of the bulk: isolated spray (pnd < n0/2) skipped
    double front = -std::numeric_limits<double>::infinity();
    const double bulk = 0.5 * fluid_->n0();
    for (std::size_t i = 0; i < p.n; ++i)
      if (p.pnd[i] >= bulk) front = std::max(front, p.x[0][i]);
    return ranks_.frame_max(front);
  }
  if (probe.quantity == "pressure") { // MPS-weighted mean over particles within r_e (eq. 8)
    const particles::MpsWeight w_e(fluid_->options().r_e());
    double sum = 0.0, weights = 0.0;
    for (std::size_t i = 0; i < p.n; ++i) {
      const double r = std::hypot(p.x[0][i] - probe.point->x(), p.x[1][i] - probe.point->y());
      if (r >= w_e.r_e) continue;
      const double w = w_e.inside(r);
      sum += w * p.p[i];
      weights += w;
    }
    sum = ranks_.frame_sum(sum), weights = ranks_.frame_sum(weights);
    return weights > 0.0 ? sum / weights : 0.0;
  }
  if (probe.quantity == "mean_pressure") { // plain mean over the particles in the box
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < p.n; ++i)
      if (p.x[0][i] >= probe.box_min->x() && p.x[0][i] <= probe.box_max->x() &&
          p.x[1][i] >= probe.box_min->y() && p.x[1][i] <= probe.box_max->y())
        sum += p.p[i], ++count;
    sum = ranks_.frame_sum(sum);
    const double inside = ranks_.frame_sum(static_cast<double>(count));
    return inside > 0.0 ? sum / inside : 0.0;
  }
  if (probe.quantity == "kinetic_energy") // J per m of depth
    return ranks_.decomposed() ? kinetic_energy_ : fluid_->kinetic_energy();
  if (probe.quantity == "mean_speed") {
    double speeds = 0.0;
    for (std::size_t i = 0; i < p.n; ++i)
      speeds += std::sqrt(p.v[0][i] * p.v[0][i] + p.v[1][i] * p.v[1][i]);
    const double all = ranks_.frame_sum(static_cast<double>(p.n));
    return all > 0.0 ? ranks_.frame_sum(speeds) / all : 0.0;
  }
  if (probe.quantity == "wall_force_x" || probe.quantity == "wall_force_y") {
    const emps::WallForceParts f = ranks_.decomposed() ? gathered_force_ : wall_force();
    const Vec2 v = probe.part == "pressure"    ? f.pressure
                   : probe.part == "repulsive" ? f.repulsive
                   : probe.part == "viscous"   ? f.viscous
                                               : f.total();
    return probe.quantity == "wall_force_x" ? v.x() : v.y();
  }
  return std::nullopt;
}

std::pair<int, int> EmpsModel::interface_segments() const {
  if (interface_walls_.empty()) return {0, static_cast<int>(walls_->segments().size())};
  const auto& last = interface_walls_.back(); // the interfaces' segments are contiguous
  return {interface_walls_.front().first_segment(), last.first_segment() + last.segment_count()};
}

std::vector<std::pair<std::string, Vec2>> EmpsModel::force_parts() const {
  const emps::WallForceParts f = wall_force();
  return {{"pressure", f.pressure}, {"repulsive", f.repulsive}, {"viscous", f.viscous}};
}

void EmpsModel::write_state(StateArchive& archive) const {
  fluid_->write_state(archive, "fluid/");
  walls_->write_state(archive, "walls/");
}

void EmpsModel::read_state(const StateArchive& archive) {
  fluid_->read_state(archive, "fluid/");
  ranks_.restored(fluid_->particles().size());
  walls_->read_state(archive, "walls/");
}

std::optional<std::string> EmpsModel::non_finite() const {
  const erp::WallSegments& s = walls_->segments();
  const erp::WallNodes& n = walls_->nodes();
  for (std::size_t k = 0; k < s.size(); ++k)
    for (const int node : s.node[k])
      if (auto what = non_finite_point(
              wall_names_[static_cast<std::size_t>(s.group[k])] + " node " + std::to_string(node),
              n.x[static_cast<std::size_t>(node)], n.v[static_cast<std::size_t>(node)]))
        return what;
  return std::nullopt;
}

std::optional<ParticleCount> EmpsModel::particle_count() const {
  const auto& o = fluid_->options();
  // Decomposed: the global count, one reduction a step (the guard's collective check).
  return ParticleCount{ranks_.global(fluid_->owned()), {o.domain_min, o.domain_max}};
}

void EmpsModel::report(JsonObject& run) const {
  run.add("fluid", fluid_report(*fluid_, ranks_.filled(), ranks_));
}

} // namespace fsi::app::emps_plugin
