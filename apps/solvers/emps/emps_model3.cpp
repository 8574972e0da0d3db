#include "emps/emps_model3.hpp"

#include "emps/emps_report.hpp"
#include "emps/tank_cover.hpp"
#include "emps/wall_point_pressure.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/format.hpp"
#include "fsi_app/wall_motion.hpp"
#include "geometry_erp/box_walls.hpp"
#include "geometry_erp/surface_fill.hpp"
#include "geometry_erp/triangle_locator.hpp"
#include "particles/kernels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <sstream>
#include <tuple>
#include <utility>

namespace fsi::app::emps_plugin {

namespace {

// Interface corners within this many l0 of a tank triangle's plane lie in it (tank_cover.hpp).
constexpr double kCoplanar = 1e-6;

/// The volume a closed surface encloses (either orientation), m^3: |sum a . (b x c)| / 6.
double enclosed_volume(const erp::StlSurface& surface) {
  const auto& X = surface.points;
  double v = 0.0;
  for (const auto& t : surface.triangles)
    v += X[static_cast<std::size_t>(t[0])].dot(
        X[static_cast<std::size_t>(t[1])].cross(X[static_cast<std::size_t>(t[2])]));
  return std::abs(v) / 6.0;
}

} // namespace

std::optional<erp::RigidTriangles3> tank_motion(const FluidSpec3& f,
                                                const erp::TriangleWallSet& walls) {
  if (!f.tank_motion) return std::nullopt;
  return erp::RigidTriangles3{make_motion3(*f.tank_motion), 0, walls.nodes().x};
}

emps::FluidOptions3 fluid_options3(const Scene& scene) {
  const FluidSpec3& f = scene.fluid->as<FluidSpec3>();
  emps::FluidOptions3 o = f.options;
  o.gravity = scene.gravity3;
  std::vector<Vec3> surfaces; // the tank_file's and the region_file's points
  for (const auto* surface : {&f.tank_surface, &f.region_surface})
    if (*surface)
      surfaces.insert(surfaces.end(), (*surface)->points.begin(), (*surface)->points.end());
  std::tie(o.domain_min, o.domain_max) =
      box_domain(f.domain, f.tank, surfaces, f.regions, 4.0 * o.r_e());
  if (f.periodic_z) { // the period: the tank's depth
    o.periodic_z = true;
    o.domain_min.z() = f.tank->min.z(), o.domain_max.z() = f.tank->max.z();
  }
  return o;
}

Fill3 fill_regions3(const FluidSpec3& f, const Ranks& ranks) {
  std::vector<Vec3> surface; // region_file's points outside every box: ids after the boxes'
  if (f.region_surface)
    for (const Vec3& p : erp::fill_closed_surface(f.region_surface->points,
                                                  f.region_surface->triangles, f.options.l0)) {
      bool in_box = false;
      for (const Box& r : f.regions) in_box = in_box || inside_box(p, r.min, r.max);
      if (!in_box) surface.push_back(p);
    }
  Fill3 fill = fill_box_part(
      f.regions, f.options.l0, ranks, [](const Vec3&) { return true; }, surface.size());
  const std::size_t boxes = fill.total - surface.size();
  for (std::size_t i = std::max(fill.ids.first, boxes); i < fill.ids.last; ++i)
    fill.x.push_back(surface[i - boxes]);
  return fill;
}

std::unique_ptr<erp::TriangleWallSet> fluid_walls(const Scene& scene,
                                                  const std::vector<InterfaceMesh3>& interfaces,
                                                  std::vector<erp::InterfaceTriangles>& triangles) {
  const FluidSpec3& f = scene.fluid->as<FluidSpec3>();
  erp::TriangleWallSet tank;
  if (f.tank && f.periodic_z) { // no z faces, 4 r_e longer than the period at each end
    const Vec3 margin(0.0, 0.0, 4.0 * f.options.r_e());
    erp::add_box_slab(tank, f.tank->min - margin, f.tank->max + margin, 0);
  } else if (f.tank) {
    erp::add_box_tank(tank, f.tank->min, f.tank->max, false, 0);
  }
  if (f.tank_surface) tank.add_triangles(f.tank_surface->points, f.tank_surface->triangles, 0);
  auto walls = std::make_unique<erp::TriangleWallSet>();
  try {
    const std::vector<std::array<int, 3>> kept = uncovered_triangles(
        tank.nodes().x, tank.triangles().node, interfaces, kCoplanar * f.options.l0);
    if (!kept.empty()) walls->add_triangles(tank.nodes().x, kept, 0);
  } catch (const InputError& e) {
    fail_at(scene, f.tank_line, f.tank_surface ? "fluid.tank_file" : "fluid.tank", e.what());
  }
  triangles.clear();
  triangles.reserve(interfaces.size()); // the adapter keeps a reference to the list
  try {
    for (const auto& mesh : interfaces)
      triangles.emplace_back(*walls, mesh, static_cast<int>(1 + triangles.size()));
  } catch (const InputError& e) {
    fail_at(scene, scene.fluid->line, "fluid", e.what());
  }
  return walls;
}

void check3(const Scene& scene, Section& s, std::vector<Section>& probes) {
  const FluidSpec3& f = scene.fluid->as<FluidSpec3>();
  const emps::FluidOptions3 o = fluid_options3(scene);
  check_box_regions(scene, s, probes, f.regions, f.tank, o.domain_min, o.domain_max);
  if (!f.region_surface) return;
  std::optional<std::pair<Vec3, Vec3>> tank; // the tank's box, or the box around tank_file's
  if (f.tank || f.tank_surface)
    tank = box_domain(std::nullopt, f.tank,
                      f.tank_surface ? std::span<const Vec3>(f.tank_surface->points)
                                     : std::span<const Vec3>(),
                      {}, 0.0);
  for (const Vec3& p : f.region_surface->points) {
    if (!inside_box(p, o.domain_min, o.domain_max))
      s.fail("domain", "the region_file surface reaches outside the domain");
    if (tank && !inside_box(p, tank->first, tank->second))
      s.fail("region_file", "the surface reaches outside the tank");
  }
}

// Bytes per fluid particle in 3-D, as emps_plugin.cpp counts 2-D: the registered particle
// arrays, the lattice positions, neighbour rows of `capacity` (EmpsFluid3's) with the build
// positions, the cell grid, three faces of erp::TriangleHits (137 B) and of TriangleForces
// (52 B), with convex_corners the convex pieces (erp::ConvexFaces, their seeds and planes, 347 B)
// and their three slots of TriangleForces, with a viscous wall term (viscosity or approach
// viscosity) three more slots (the viscous faces'), the scratch
// and keep arrays and the output buffers; coupled, the particle arrays once more (the state
// TriangleAdapter saves for iterative coupling).
Footprint footprint3(const Scene& scene) {
  const FluidSpec3& f = scene.fluid->as<FluidSpec3>();
  const emps::FluidOptions3 o = fluid_options3(scene);
  const double reach = (1.0 + o.skin) * o.re_over_l0;
  const double capacity = std::ceil(2.0 * 4.0 / 3.0 * std::numbers::pi * std::pow(reach, 3)) + 16;
  const auto particle = static_cast<double>(emps::Particles3().fields.bytes_per_particle());
  const double saved_state = scene.structures.empty() ? 0.0 : particle;
  using Convex = erp::ConvexFaces; // pieces; face, end, seed and bary of each piece; n, s a plane
  const double convex = o.wall.convex_corners
                            ? 1 + Convex::max_pieces * (2 + sizeof(int) + sizeof(Vec3) + 52) +
                                  Convex::max_planes * (sizeof(Vec3) + 8)
                            : 0.0;
  const bool viscous_walls = o.viscosity > 0 || o.wall.mirror.approach_viscosity > 0;
  const double per_particle = particle + saved_state + 24 + (capacity * 4 + 4 + 24) + 8 + 3 * 137 +
                              (viscous_walls ? 6 : 3) * 52 + convex + 24 + 1 + (24 + 24 + 8);
  Footprint e;
  for (const Box& r : f.regions) e.count += (r.max - r.min).prod() / std::pow(o.l0, 3);
  if (f.region_surface) e.count += enclosed_volume(*f.region_surface) / std::pow(o.l0, 3);
  double cells = 1.0;
  for (int c = 0; c < 3; ++c)
    cells *= std::ceil((o.domain_max[c] - o.domain_min[c]) / (o.r_e() * (1.0 + o.skin))) + 2.0;
  e.bytes = e.count * per_particle + cells * 8.0;
  e.key = "l0";
  e.counts = significant(e.count, 3) + " particles (fluid region volume / l0^3) and " +
             significant(cells, 3) + " cells";
  check_index_range(e, cells);
  return e;
}

EmpsModel3::EmpsModel3(const Scene& scene, const std::vector<InterfaceMesh3>& interfaces,
                       const Ranks& ranks)
    : probes_(scene.output.probes) {
  const FluidSpec3& f = scene.fluid->as<FluidSpec3>();
  ranks_.refuse(f.periodic);
  Fill3 fill = fill_regions3(f, ranks);
  validate3(scene, interfaces, fill, ranks);
  const auto [positions, block] =
      ranks_.setup(ranks, std::move(fill.x), fill.ids.first, fill.total);
  walls_ = fluid_walls(scene, interfaces, interfaces_);
  tank_motion_ = tank_motion(f, *walls_);
  if (tank_motion_) tank_motion_->move(*walls_, 0.0);
  locator_ = std::make_unique<erp::TriangleLocator>(*walls_, f.options.r_e());
  try {
    // The walls move with fluid.tank_motion or the structures' interfaces, else never.
    const bool walls_move = tank_motion_.has_value() || !interfaces_.empty();
    fluid_ = std::make_unique<emps::EmpsFluid3>(fluid_options3(scene), positions, *walls_,
                                                walls_move, block);
  } catch (const InputError& e) {
    fail_at(scene, scene.fluid->line, "fluid", e.what());
  }
  adapter_ = std::make_unique<TriangleAdapter>(*fluid_, *walls_, interfaces_);
  wall_points_ = std::make_unique<WallPointProbes>(scene, *walls_, f.options.r_e(), false);
}

coupling::FluidSolver& EmpsModel3::coupling_solver() {
  throw RunError("fluid_emps: a 3-D fluid couples through coupling_solver3()");
}

void EmpsModel3::advance(double time, double dt) {
  if (tank_motion_) tank_motion_->move(*walls_, time + dt); // walls at t + dt, then the fluid
  fluid_->advance(time, dt);
}

std::optional<double> EmpsModel3::stable_dt(double courant) const {
  return fluid_->stable_dt(courant);
}

bool EmpsModel3::decompose(const Ranks& ranks) {
  fluid_->decompose(ranks_.decompose(ranks));
  return true;
}

void EmpsModel3::gather_frame() {
  if (!ranks_.decomposed()) return;
  gathered_.gather(ranks_, fluid_->particles(), fluid_->owned());
  kinetic_energy_ = fluid_->kinetic_energy();              // collective
  wall_points_->gather(fluid_->triangle_forces(), ranks_); // collective
  if (ranks_.rows())
    ranks_.evaluate_probes(probes_, [&](const ProbeSpec& p) { return evaluate(p); });
}

void EmpsModel3::write_frame(FieldsFile& file, const std::vector<std::string>& fields) const {
  const FrameParticles<3> p = frame();
  const std::size_t n = p.n;
  xyz_.resize(3 * n);
  v_.resize(3 * n);
  flag_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t c = 0; c < 3; ++c) xyz_[3 * i + c] = p.x[c][i], v_[3 * i + c] = p.v[c][i];
    flag_[i] = p.surface[i];
  }
  file.write_grid("particles", xyz_,
                  select_fields(fields, {{"velocity", 3, v_.data()},
                                         {"pressure", 1, p.p},
                                         {"pnd", 1, p.pnd},
                                         {"free_surface", 1, flag_.data()}}),
                  3, ranks_.rows());
}

std::optional<double> EmpsModel3::probe(const ProbeSpec& probe) const {
  return ranks_.rows() ? ranks_.probe_value(probe) : evaluate(probe);
}

std::optional<double> EmpsModel3::evaluate(const ProbeSpec& probe) const {
  const FrameParticles<3> p = frame();
  const std::size_t n = p.n;
  const auto x = [&](std::size_t i) { return Vec3(p.x[0][i], p.x[1][i], p.x[2][i]); };
  if (probe.quantity == "surge_front") { // largest x of the bulk (pnd >= n0/2), as in 2-D
    double front = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i)
      if (p.pnd[i] >= 0.5 * fluid_->n0()) front = std::max(front, p.x[0][i]);
    return ranks_.frame_max(front);
  }
  if (probe.quantity == "pressure") { // MPS-weighted mean over particles within r_e (eq. 8)
    const particles::MpsWeight w_e(fluid_->options().r_e());
    double sum = 0.0, weights = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double r = (x(i) - *probe.point3).norm();
      if (r >= w_e.r_e) continue;
      const double w = w_e.inside(r);
      sum += w * p.p[i], weights += w;
    }
    sum = ranks_.frame_sum(sum), weights = ranks_.frame_sum(weights);
    return weights > 0.0 ? sum / weights : 0.0;
  }
  if (probe.quantity == "mean_pressure") { // plain mean over the particles in the box
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (inside_box(x(i), *probe.box3_min, *probe.box3_max)) sum += p.p[i], ++count;
    sum = ranks_.frame_sum(sum);
    const double inside = ranks_.frame_sum(static_cast<double>(count));
    return inside > 0.0 ? sum / inside : 0.0;
  }
  if (probe.quantity == "water_height") { // a wave gauge: the bulk's top along the vertical
    const auto& o = fluid_->options();
    const Vec3 up = o.gravity.norm() > 0.0 ? Vec3(-o.gravity.normalized()) : Vec3::UnitY();
    double top = 0.0; // the height above the point of the highest bulk particle's top (y + l0/2)
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 d = x(i) - *probe.point3;
      const double h = d.dot(up);
      if (p.pnd[i] >= probe.pnd_fraction * fluid_->n0() && (d - h * up).norm() < o.l0)
        top = std::max(top, h + 0.5 * o.l0);
    }
    return ranks_.frame_max(top);
  }
  if (probe.quantity == "wall_pressure") // the wall's own (wall_point_pressure.hpp)
    return wall_points_->value(probe, fluid_->triangle_forces(), ranks_.decomposed());
  if (probe.quantity == "particles") return ranks_.frame_sum(static_cast<double>(n));
  if (probe.quantity == "wall_gap") {
    locator_->update(); // the interfaces' triangles move
    locator_->query(std::span<const double>(p.x[0], n), std::span<const double>(p.x[1], n),
                    std::span<const double>(p.x[2], n), hits_);
    double gap = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i)
      if (hits_.triangle[i] >= 0) gap = std::min(gap, hits_.crossed[i] ? -hits_.r[i] : hits_.r[i]);
    return ranks_.frame_min(gap);
  }
  if (probe.quantity == "kinetic_energy") // J
    return ranks_.decomposed() ? kinetic_energy_ : fluid_->kinetic_energy();
  if (probe.quantity == "mean_speed") {
    double speeds = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      speeds += std::sqrt(p.v[0][i] * p.v[0][i] + p.v[1][i] * p.v[1][i] + p.v[2][i] * p.v[2][i]);
    const double all = ranks_.frame_sum(static_cast<double>(n));
    return all > 0.0 ? ranks_.frame_sum(speeds) / all : 0.0;
  }
  return std::nullopt;
}

std::optional<ParticleCount> EmpsModel3::particle_count() const {
  const auto& o = fluid_->options();
  // Decomposed: the global count, one reduction a step (the guard's collective check).
  return ParticleCount{ranks_.global(fluid_->owned()), {o.domain_min, o.domain_max}};
}

void EmpsModel3::report(JsonObject& run) const {
  JsonObject f = fluid_report(*fluid_, ranks_.filled(), ranks_);
  f.add("wall_triangles", static_cast<long long>(walls_->triangles().size()));
  run.add("fluid", f);
}

void EmpsModel3::write_state(StateArchive& archive) const {
  adapter_->write_state(archive);
}

void EmpsModel3::read_state(const StateArchive& archive) {
  adapter_->read_state(archive);
  ranks_.restored(fluid_->particles().size());
}

} // namespace fsi::app::emps_plugin
