#include "sph/sph_model3.hpp"

#include "sph/boundary_adapter.hpp"
#include "sph/sph_frame.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/format.hpp"
#include "fsi/core/state_archive.hpp"
#include "fsi_app/fluid_regions.hpp"

#include <cmath>
#include <cstdint>
#include <tuple>
#include <unordered_set>

namespace fsi::app::sph_plugin {

namespace {

bool velocity_probe(const std::string& q) {
  return q == "velocity_x" || q == "velocity_y" || q == "velocity_z";
}

// Rows of boundary points behind an interface (the 2-D default of fluid.interface_layers).
constexpr int kInterfaceLayers = 4;

// Each interface's boundary points (lattice at spacing l0); InputError naming the fluid block.
std::vector<sph::InterfaceBoundary3> boundaries_of(const Scene& scene,
                                                   const std::vector<InterfaceMesh3>& interfaces) {
  const double dp = scene.fluid->as<SphSpec3>().options.dp;
  std::vector<sph::InterfaceBoundary3> out;
  try {
    for (const auto& mesh : interfaces) out.emplace_back(mesh, dp, kInterfaceLayers);
  } catch (const InputError& e) {
    fail_at(scene, scene.fluid->line, "fluid", e.what());
  }
  return out;
}

// The options checked and the fluid's particles: the regions' fill less what lies behind an
// interface or within l0/2 of it (its signed distance at the reference positions), this
// process's part of it (fill_box_part: under mpirun its block of ids, built without the rest);
// InputError naming the fluid block when none is left.
Fill3 checked_fluid(const Scene& scene, const std::vector<sph::InterfaceBoundary3>& bs,
                    const Ranks& ranks) {
  const SphSpec3& f = scene.fluid->as<SphSpec3>();
  try {
    sph_options3(scene).validate();
  } catch (const InputError& e) {
    fail_at(scene, scene.fluid->line, "fluid", e.what());
  }
  const double dp = f.options.dp;
  Fill3 fill = fill_box_part(f.regions, dp, ranks, [&bs, dp](const Vec3& p) {
    for (const auto& b : bs)
      if (b.signed_distance(p) < 0.5 * dp) return false;
    return true;
  });
  if (fill.total == 0)
    fail_at(scene, f.regions.front().line, "fluid.regions", "no particle fits the regions");
  return fill;
}

// The tank's dummies less those whose dp cell of the tank's lattice holds one of `points` (a
// structure's boundary points): where a structure stands in the tank's wall, the fluid sees it
// and not a rigid wall.
std::vector<sph::WallPoint3> tank_walls(const SphSpec3& f,
                                        const std::vector<sph::WallPoint3>& points) {
  if (!f.tank) return {};
  const double dp = f.options.dp;
  const auto cell = [lo = f.tank->min, dp](const Vec3& x) {
    std::int64_t key = 0;
    for (int c = 0; c < 3; ++c)
      key = (key << 21) + static_cast<std::int64_t>(std::floor((x[c] - lo[c]) / dp)) + (1 << 20);
    return key;
  };
  std::unordered_set<std::int64_t> taken;
  for (const auto& p : points) taken.insert(cell(p.x));
  std::vector<sph::WallPoint3> out;
  for (const auto& w :
       sph::box_walls(f.tank->min, f.tank->max, dp, 4, 1, {false, false, f.periodic_z}))
    if (!taken.count(cell(w.x))) out.push_back(w);
  return out;
}

} // namespace

sph::SphOptions3 sph_options3(const Scene& scene) {
  const SphSpec3& f = scene.fluid->as<SphSpec3>();
  sph::SphOptions3 o = f.options;
  o.gravity = scene.gravity3;
  std::tie(o.domain_min, o.domain_max) = box_domain(f.domain, f.tank, {}, f.regions, 8.0 * o.dp);
  if (f.periodic_z) { // the period: the tank's depth
    o.periodic_z = true;
    o.domain_min.z() = f.tank->min.z(), o.domain_max.z() = f.tank->max.z();
  }
  return o;
}

void check3(const Scene& scene, Section& s, std::vector<Section>& probes) {
  const SphSpec3& f = scene.fluid->as<SphSpec3>();
  const sph::SphOptions3 o = sph_options3(scene);
  check_box_regions(scene, s, probes, f.regions, f.tank, o.domain_min, o.domain_max);
  for (std::size_t i = 0; i < scene.output.probes.size(); ++i) {
    const std::string& q = scene.output.probes[i].quantity;
    if (q == "wall_force_x" || q == "wall_force_y")
      probes[i].fail("quantity", q + " is not yet available in a 3-D scene");
  }
  try {
    o.validate();
  } catch (const InputError& e) {
    s.fail("", e.what());
  }
}

// Per fluid particle as in 2-D (sph_plugin.cpp) with 3-D pairs: about 74 of 44 B (index, e_ij,
// dW_ij, r_ij), the particles twice, grid 8 B, sort 8 B, output 56 B; the tank's dummies not
// counted.
Footprint footprint3(const Scene& scene) {
  const SphSpec3& f = scene.fluid->as<SphSpec3>();
  const sph::SphOptions3 o = sph_options3(scene);
  const auto particle =
      static_cast<double>(sph::BasicFluidParticles<3>().fields.bytes_per_particle());
  Footprint e;
  for (const Box3& r : f.regions) e.count += (r.max - r.min).prod() / std::pow(o.dp, 3);
  double cells = 1.0;
  for (int c = 0; c < 3; ++c)
    cells *= std::ceil((o.domain_max[c] - o.domain_min[c]) / (2.0 * o.h())) + 2.0;
  e.bytes = e.count * (2 * particle + 74 * 44 + 8 + 8 + 56) + cells * 8.0;
  e.key = "l0";
  e.counts = significant(e.count, 3) + " particles (fluid region volume / l0^3) and " +
             significant(cells, 3) + " cells";
  check_index_range(e, cells);
  return e;
}

void validate3(const Scene& scene, const std::vector<InterfaceMesh3>& interfaces) {
  checked_fluid(scene, boundaries_of(scene, interfaces), OneProcess());
}

SphModel3::SphModel3(const Scene& scene, const std::vector<InterfaceMesh3>& interfaces,
                     const Ranks& ranks)
    : boundaries_(boundaries_of(scene, interfaces)), probes_(scene.output.probes) {
  const SphSpec3& f = scene.fluid->as<SphSpec3>();
  ranks_.refuse(f.periodic);
  Fill3 fill = checked_fluid(scene, boundaries_, ranks);
  const auto [positions, block] =
      ranks_.setup(ranks, std::move(fill.x), fill.ids.first, fill.total);
  // The interfaces' points (group 1 + j) after the tank's dummies (group 0); the guard's exact
  // surface of interface j: its flat triangles where its points are now (interface_x_).
  std::vector<sph::WallPoint3> points;
  std::vector<sph::SphFluid3::Distance> distances(1);
  for (std::size_t j = 0; j < boundaries_.size(); ++j) {
    const auto p = boundaries_[j].wall_points(static_cast<int>(1 + j));
    points.insert(points.end(), p.begin(), p.end());
    interface_x_.push_back(interfaces[j].X0);
    distances.emplace_back(
        [this, j](const Vec3& q) { return boundaries_[j].signed_distance(interface_x_[j], q); });
  }
  std::vector<sph::WallPoint3> walls = tank_walls(f, points);
  first_point_ = walls.size();
  walls.insert(walls.end(), points.begin(), points.end());
  try {
    fluid_ = std::make_unique<sph::SphFluid3>(sph_options3(scene), positions, walls,
                                              std::move(distances), block);
  } catch (const InputError& e) {
    fail_at(scene, scene.fluid->line, "fluid", e.what());
  }
  if (!boundaries_.empty()) fluid_->track_wall_forces(first_point_);
  adapter_ =
      std::make_unique<BoundaryAdapter<3>>(*fluid_, boundaries_, interface_x_, first_point_, false);
}

SphModel3::~SphModel3() = default;

coupling::FluidSolver& SphModel3::coupling_solver() {
  throw RunError("fluid_sph: a 3-D fluid couples through coupling_solver3()");
}

coupling::FluidSolver3& SphModel3::coupling_solver3() {
  return *adapter_;
}

void SphModel3::advance(double time, double dt) {
  fluid_->advance_to(time + dt);
}

std::optional<double> SphModel3::stable_dt(double) const {
  return fluid_->advection_dt();
}

void SphModel3::write_frame(FieldsFile& file, const std::vector<std::string>& fields) const {
  const SphFrame<3> p = frame(ranks_, *fluid_);
  const std::size_t n = p.n;
  xyz_.resize(3 * n);
  v_.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < 3; ++c) xyz_[3 * i + c] = p.x[c][i], v_[3 * i + c] = p.v[c][i];
  file.write_grid("particles", xyz_,
                  select_fields(fields, {{"velocity", 3, v_.data()},
                                         {"pressure", 1, p.p},
                                         {"density", 1, p.rho},
                                         {"wkgc_indicator", 1, p.det_a}}),
                  3, ranks_.rows());
}

std::optional<double> SphModel3::evaluate(const ProbeSpec& probe) const {
  if (probe.quantity == "surge_front") return fluid_->surge_front();
  if (probe.quantity == "pressure") return fluid_->pressure_at(*probe.point3);
  if (velocity_probe(probe.quantity))
    return fluid_->velocity_at(*probe.point3)[probe.quantity.back() - 'x'];
  if (probe.quantity == "kinetic_energy") return fluid_->kinetic_energy(); // J
  if (probe.quantity == "mean_speed") return mean_speed(ranks_, *fluid_);
  return std::nullopt;
}

void SphModel3::report(JsonObject& run) const {
  run.add("fluid", fluid_report(ranks_, *fluid_, ranks_.filled(), first_point_));
}

bool SphModel3::decompose(const Ranks& ranks) {
  fluid_->decompose(ranks_.decompose(ranks));
  return true;
}

void SphModel3::gather_frame() {
  if (!ranks_.decomposed()) return;
  sph_plugin::gather_frame(ranks_, *fluid_);
  ranks_.evaluate_probes(probes_, [&](const ProbeSpec& p) { return evaluate(p); });
}

std::optional<double> SphModel3::probe(const ProbeSpec& probe) const {
  return ranks_.decomposed() ? ranks_.probe_value(probe) : evaluate(probe);
}

std::optional<ParticleCount> SphModel3::particle_count() const {
  const auto& o = fluid_->options();
  return ParticleCount{ranks_.global(fluid_->owned()), {o.domain_min, o.domain_max}};
}

void SphModel3::write_state(StateArchive& archive) const {
  adapter_->write_state(archive);
}

void SphModel3::read_state(const StateArchive& archive) {
  adapter_->read_state(archive);
  ranks_.restored(fluid_->particles().size());
}

} // namespace fsi::app::sph_plugin
