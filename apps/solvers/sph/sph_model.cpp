#include "sph/sph_model.hpp"

#include "sph/boundary_adapter.hpp"
#include "sph/sph_frame.hpp"

#include "fsi/core/error.hpp"
#include "fsi_app/finite_guard.hpp"
#include "fsi_app/fluid_regions.hpp"
#include "fsi_app/wall_motion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace fsi::app::sph_plugin {

sph::SphOptions sph_options(const Scene& scene) {
  const SphSpec& f = scene.fluid->as<SphSpec>();
  sph::SphOptions o = f.options;
  o.gravity = scene.gravity;
  o.periodic_x = o.inflow.on(); // the channel wraps in x
  std::tie(o.domain_min, o.domain_max) = f.area.domain_or_box(scene, 8.0 * o.dp);
  return o;
}

namespace {

sph::WallMotion wall_motion(const WallSpec& wall) {
  std::shared_ptr<const erp::Motion> motion = make_motion(wall);
  const Vec2 pivot = wall.motion->pivot;
  return [motion, pivot](double t) {
    const erp::RigidKinematics k = motion->at(t);
    sph::RigidMotion m;
    m.centre = pivot;
    m.d = k.d, m.v = k.d_dot, m.a = k.d_ddot;
    m.theta = k.theta, m.omega = k.omega, m.alpha = k.alpha;
    return m;
  };
}

bool has_wall_force_probe(const Scene& scene) {
  return std::any_of(scene.output.probes.begin(), scene.output.probes.end(), [](const auto& p) {
    return p.quantity == "wall_force_x" || p.quantity == "wall_force_y";
  });
}

} // namespace

SphModel::SphModel(const Scene& scene, const std::vector<InterfaceMesh>& interfaces,
                   const std::vector<Polygon>& solid, const Ranks& ranks)
    : probes_(scene.output.probes) {
  const SphSpec& f = scene.fluid->as<SphSpec>();
  ranks_.refuse(f.periodic);
  std::vector<sph::WallPolyline> walls;
  for (std::size_t w = 0; w < scene.walls.size(); ++w) {
    walls.push_back({scene.walls[w].polyline, scene.walls[w].closed, static_cast<int>(w)});
  }
  std::vector<sph::WallPoint> points;
  // The guard's exact surface of each interface (group walls + j): its chords where its points
  // are now (interface_x_, moved by the adapter).
  std::vector<sph::WallDistance> distances(walls.size());
  try {
    for (std::size_t j = 0; j < interfaces.size(); ++j) {
      boundaries_.emplace_back(interfaces[j], f.options.dp, f.interface_layers,
                               f.interface_spacing * f.options.dp);
      const auto p = boundaries_.back().wall_points(static_cast<int>(walls.size() + j));
      points.insert(points.end(), p.begin(), p.end());
      interface_x_.push_back(interfaces[j].X0);
      distances.emplace_back(
          [this, j](const Vec2& q) { return boundaries_[j].signed_distance(interface_x_[j], q); });
    }
  } catch (const InputError& e) {
    fail_at(scene, scene.fluid->line, "fluid", e.what());
  }
  const auto [positions, block] =
      ranks_.setup(ranks, fill_regions(scene, f.area.regions, f.options.dp, solid));
  try {
    fluid_ = std::make_unique<sph::SphFluid>(sph_options(scene), positions, walls, points,
                                             std::move(distances), block);
  } catch (const InputError& e) {
    fail_at(scene, scene.fluid->line, "fluid", e.what());
  }
  for (std::size_t w = 0; w < scene.walls.size(); ++w)
    if (scene.walls[w].motion)
      fluid_->set_wall_motion(static_cast<int>(w), wall_motion(scene.walls[w]));
  first_point_ = fluid_->walls().size() - points.size();
  tracked_ = !interfaces.empty() || has_wall_force_probe(scene);
  interface_acceleration_ = f.interface_acceleration;
  if (tracked_) fluid_->track_wall_forces(interfaces.empty() ? 0 : first_point_);
  adapter_ = std::make_unique<BoundaryAdapter<2>>(*fluid_, boundaries_, interface_x_, first_point_,
                                                  interface_acceleration_);
}

SphModel::~SphModel() = default;

coupling::FluidSolver& SphModel::coupling_solver() {
  return *adapter_;
}

void SphModel::advance(double time, double dt) {
  if (!tracked_) return fluid_->advance_to(time + dt);
  // As advance_to, with the tracked walls' mean force over the step (the wall_force probes).
  const double t_end = time + dt;
  Vec2 impulse = Vec2::Zero();
  while (fluid_->time() < t_end - 1e-12 * std::max(1.0, std::abs(t_end))) {
    const double h = std::min(fluid_->next_dt(), t_end - fluid_->time());
    fluid_->advance(h);
    Vec2 f = Vec2::Zero();
    for (std::size_t a = 0; a < fluid_->walls().size(); ++a) f += fluid_->wall_force(a);
    impulse += f * h;
  }
  wall_force_ = impulse / dt;
}

std::optional<double> SphModel::stable_dt(double) const {
  return fluid_->advection_dt();
}

void SphModel::write_frame(FieldsFile& file, const std::vector<std::string>& fields) const {
  const SphFrame<2> p = frame(ranks_, *fluid_);
  const std::size_t n = p.n;
  xy_.resize(2 * n);
  v_.resize(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    xy_[2 * i] = p.x[0][i], xy_[2 * i + 1] = p.x[1][i];
    v_[2 * i] = p.v[0][i], v_[2 * i + 1] = p.v[1][i];
  }
  file.write_grid("particles", xy_,
                  select_fields(fields, {{"velocity", 2, v_.data()},
                                         {"pressure", 1, p.p},
                                         {"density", 1, p.rho},
                                         {"wkgc_indicator", 1, p.det_a}}),
                  2, ranks_.rows());
}

Vec2 SphModel::wall_force() const {
  Vec2 total = wall_force_;
  if (!boundaries_.empty()) {
    total = Vec2::Zero();
    for (const Vec2& q : adapter_->interface_loads().f) total += q;
  }
  if (!ranks_.decomposed()) return total;
  std::vector<double> sum{total.x(), total.y()}; // this rank's particles' part
  ranks_.sum(sum);
  return {sum[0], sum[1]};
}

std::optional<double> SphModel::evaluate(const ProbeSpec& probe) const {
  if (probe.quantity == "surge_front") return fluid_->surge_front();
  if (probe.quantity == "pressure") return fluid_->pressure_at(*probe.point);
  if (probe.quantity == "velocity_x") return fluid_->velocity_at(*probe.point).x();
  if (probe.quantity == "velocity_y") return fluid_->velocity_at(*probe.point).y();
  if (probe.quantity == "kinetic_energy") return fluid_->kinetic_energy(); // J per m of depth
  if (probe.quantity == "mean_speed") return mean_speed(ranks_, *fluid_);
  if (probe.quantity == "wall_force_x") return wall_force().x();
  if (probe.quantity == "wall_force_y") return wall_force().y();
  return std::nullopt;
}

std::vector<std::pair<std::string, Vec2>> SphModel::force_parts() const {
  return {{"total", wall_force()}};
}

void SphModel::report(JsonObject& run) const {
  run.add("fluid", fluid_report(ranks_, *fluid_, ranks_.filled(), first_point_));
}

bool SphModel::decompose(const Ranks& ranks) {
  fluid_->decompose(ranks_.decompose(ranks));
  return true;
}

void SphModel::gather_frame() {
  if (!ranks_.decomposed()) return;
  sph_plugin::gather_frame(ranks_, *fluid_);
  ranks_.evaluate_probes(probes_, [&](const ProbeSpec& p) { return evaluate(p); });
}

std::optional<double> SphModel::probe(const ProbeSpec& probe) const {
  return ranks_.decomposed() ? ranks_.probe_value(probe) : evaluate(probe);
}

std::optional<std::string> SphModel::non_finite() const {
  const sph::WallParticles& w = fluid_->walls();
  for (std::size_t i = 0; i < w.size(); ++i) {
    const std::string what = i < first_point_
                                 ? "wall particle " + std::to_string(i)
                                 : "interface point " + std::to_string(i - first_point_);
    if (auto bad = non_finite_point(what, {w.x[0][i], w.x[1][i]}, {w.v[0][i], w.v[1][i]}))
      return bad;
  }
  return std::nullopt;
}

std::optional<ParticleCount> SphModel::particle_count() const {
  const auto& o = fluid_->options();
  return ParticleCount{ranks_.global(fluid_->owned()), {o.domain_min, o.domain_max}};
}

void SphModel::write_state(StateArchive& archive) const {
  adapter_->write_state(archive);
}

void SphModel::read_state(const StateArchive& archive) {
  adapter_->read_state(archive);
  ranks_.restored(fluid_->particles().size());
}

} // namespace fsi::app::sph_plugin
