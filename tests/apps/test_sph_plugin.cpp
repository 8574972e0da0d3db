// fluid.type: sph through the plug-in registry (issues 18, 20): its keys shared with the EMPS
// fluid, the errors for another type's keys, a hydrostatic column (pressure and the walls' force
// against the weight), a restart through the run driver that continues bitwise, and the moving
// boundary on a structure's interface mesh: a column resting on a rigid interface carries its
// weight, a coupled throw of fluid at a free rigid body conserves the total momentum, and the
// SPH fluid with either structure continues bitwise from a checkpoint.
#include "fsi/core/error.hpp"
#include "fsi_app/coupled_model.hpp"
#include "fsi_app/output/checkpoint_file.hpp"
#include "fsi_app/run.hpp"
#include "fsi_app/scene.hpp"
#include "fsi_app/solver_plugin.hpp"
#include "scene_probes.hpp"
#include "sph/sph_model.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace fsi;
using namespace fsi::app;
using fsi::app::sph_plugin::SphModel;
using fsi::app::test::named;
namespace fs = std::filesystem;

namespace {

std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parse_scene(text, "scene.yaml", overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string slurp(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fluid-only scene of the SPH fluid around `fluid_keys` (no walls unless given).
std::string sph_scene(const std::string& fluid_keys, const std::string& rest = "",
                      const std::string& gravity = "[0.0, -9.81]") {
  return "gravity: " + gravity +
         "\ntime:\n  end: 0.1\n  courant: 0.2\noutput:\n  interval: 0.01\nfluid:\n  type: sph\n"
         "  density: 1000.0\n  l0: 0.005\n  sound_speed: 20.0\n" +
         fluid_keys + rest;
}

} // namespace

TEST_CASE("sph plug-in: the EMPS scene's shared keys, another type's keys refused by name",
          "[apps][sph]") {
  // The shipped dam break as sph: every shared key read, the SPH-only keys at their defaults.
  const Scene scene = load_scene(FSI_SOURCE_DIR "/data/scenes/dam_break_rigid_sph.yaml", {});
  REQUIRE(scene.fluid->type == "sph");
  const auto o = sph_plugin::sph_options(scene);
  CHECK(o.dp == 0.0025);
  CHECK(o.c0 == 20.0);
  CHECK(o.rho0 == 1000.0);
  CHECK(o.viscosity == 1.0e-6);
  CHECK(o.correction == sph::Correction::rkgc);
  CHECK(o.h_over_dp == 1.3);
  CHECK(o.u_advection() == 2.0); // u_ref 0: sound_speed / 10
  CHECK(o.fixed_dt == 0.0);      // the dual criteria
  const Scene fixed =
      load_scene(FSI_SOURCE_DIR "/data/scenes/dam_break_rigid_sph.yaml", {"fluid.fixed_dt=2.5e-5"});
  CHECK(sph_plugin::sph_options(fixed).fixed_dt == 2.5e-5);
  // The EMPS scene itself with --set fluid.type=sph: its EMPS-only key is named, with its type.
  const std::string emps_only =
      error_of(slurp(FSI_SOURCE_DIR "/data/scenes/dam_break_rigid.yaml"), {"fluid.type=sph"});
  INFO(emps_only);
  CHECK(emps_only.find("scene.yaml:") == 0);
  CHECK(emps_only.find("fluid.alpha_rep: is a key of fluid type emps, not of sph") !=
        std::string::npos);
  // The SPH scene has no SPH-only key: it reads as emps too.
  CHECK(error_of(slurp(FSI_SOURCE_DIR "/data/scenes/dam_break_rigid_sph.yaml"),
                 {"fluid.type=emps"}) == "");
  // An SPH-only key given to emps: unknown there, named.
  const std::string correction = error_of(slurp(FSI_SOURCE_DIR "/data/scenes/dam_break_rigid.yaml"),
                                          {"fluid.correction=none"});
  CHECK(correction.find("fluid.correction: unknown key") != std::string::npos);
  // Values out of range and cross-checks against the scene: one line, before any computation.
  const std::string region = "  regions:\n    - min: [0, 0]\n      max: [0.1, 0.1]\n";
  for (const std::string key : {"wkgc_alpha: 2.0", "fixed_dt: -1.0e-5"})
    CHECK(error_of(sph_scene("  " + key + "\n" + region))
              .find("fluid." + key.substr(0, key.find(':'))) != std::string::npos);
  CHECK(error_of(sph_scene("  transport_velocity: true\n  regions:\n    - min: [0, 0]\n      "
                           "max: [0.1, 0.1]\n"))
            .find("fluid.transport_velocity: needs free_surface: false") != std::string::npos);
  CHECK(error_of(sph_scene("  regions:\n    - min: [0, 0]\n      max: [0.1, 0.1]\n  domain:\n    "
                           "min: [0, 0]\n    max: [0.05, 0.2]\n"))
            .find("fluid.domain: fluid region 0 reaches outside the domain") != std::string::npos);
}

TEST_CASE("sph plug-in: a hydrostatic column through the registry: pressure and wall force",
          "[apps][sph]") {
  const Scene scene = load_scene(FSI_TEST_DATA "/sph_column.yaml", {});
  const FluidPlugin* plugin = find_fluid_plugin(scene.fluid->type);
  REQUIRE(plugin != nullptr);
  const auto model = plugin->build(scene, {}, {}, OneProcess());
  const ProbeSpec &p_low = named(scene, "p_low"), &force_y = named(scene, "force_y"),
                  &energy = named(scene, "energy");
  const double rho = 1000.0, g = 9.81, H = 0.1, width = 0.1;
  const double weight = rho * g * H * width; // N per m of depth
  double t = 0.0, p_sum = 0.0, f_sum = 0.0, e_end_damping = 0.0, e_max = 0.0;
  long samples = 0;
  while (t < scene.time.end - 1e-12) {
    const double dt = std::min(*model->stable_dt(0.2), scene.time.end - t);
    model->advance(t, dt);
    t += dt;
    if (t < 0.3) e_end_damping = *model->probe(energy);
    if (t > 0.3) e_max = std::max(e_max, *model->probe(energy));
    if (t > 0.4) p_sum += *model->probe(p_low), f_sum += *model->probe(force_y), ++samples;
  }
  const double p = p_sum / static_cast<double>(samples);
  const double f = f_sum / static_cast<double>(samples);
  const double p_exact = rho * g * (H - 0.02);
  INFO("pressure at y = 0.02: " << p << " Pa vs rho g (H - y) " << p_exact << " Pa; walls' "
                                << "vertical force " << f << " N/m vs -weight " << -weight
                                << "; kinetic energy " << e_end_damping << " J/m at 0.3 s, max "
                                << e_max << " after");
  CHECK(std::abs(p / p_exact - 1.0) < 0.03);
  CHECK(std::abs(f / -weight - 1.0) < 0.02);
  // Not asserted: the kinetic energy grows after the damping (measured 0.0029 -> 0.011 J/m, the
  // side-wall problem of docs/fluid_sph.md, "Known problems").
}

TEST_CASE("sph plug-in: a run continued from a checkpoint is bitwise the uninterrupted run",
          "[apps][sph]") {
  const Scene scene = load_scene(FSI_TEST_DATA "/sph_column.yaml",
                                 {"time.end=0.1", "checkpoint={interval_steps: 25, keep: 9}"});
  test::check_restart_bitwise(scene, fs::temp_directory_path() / "fsi_test_sph_restart", 50, 100,
                              10000);
}

namespace {

// Order-2 interface edges along an open or closed polyline, each side cut into edges of at most
// `length` (mid-side nodes at the chord's middle), solid on the left of the walking direction.
InterfaceMesh polyline_mesh(const std::vector<Vec2>& points, bool closed, double length) {
  InterfaceMesh mesh;
  mesh.order = 2;
  const std::size_t sides = closed ? points.size() : points.size() - 1;
  mesh.X0.push_back(points[0]);
  for (std::size_t s = 0; s < sides; ++s) {
    const Vec2 a = points[s], b = points[(s + 1) % points.size()];
    const int n = static_cast<int>(std::ceil((b - a).norm() / length - 1e-9));
    for (int k = 0; k < n; ++k) {
      const std::size_t first = mesh.X0.size() - 1;
      mesh.X0.push_back(a + (k + 0.5) / n * (b - a));
      const bool closing = closed && s + 1 == sides && k + 1 == n;
      if (!closing) mesh.X0.push_back(a + (k + 1.0) / n * (b - a));
      mesh.edges.push_back({first, first + 1, closing ? 0 : first + 2});
    }
  }
  return mesh;
}

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

} // namespace

TEST_CASE("sph interface boundary: 4 layers at dp, loads with the exact total force and moment",
          "[apps][sph]") {
  // The inner outline of an open container 0.1 m wide, 0.2 m tall.
  const double dp = 0.005;
  const InterfaceMesh mesh =
      polyline_mesh({{0.1, 0.2}, {0.1, 0.0}, {0.0, 0.0}, {0.0, 0.2}}, false, 0.0123);
  const sph::InterfaceBoundary b(mesh, dp, 4);
  std::vector<Vec2> x, n, force(b.size()), nodal;
  b.place(mesh.X0, x, n);
  Vec2 total = Vec2::Zero();
  double moment = 0.0, closest = 1.0, farthest_nearest = 0.0;
  for (std::size_t p = 0; p < b.size(); ++p) {
    force[p] = Vec2(std::sin(3.0 * p + 1.0), std::cos(7.0 * p));
    const auto& e = mesh.edges[b.edge(p)];
    const Vec2 anchor = edge_point(mesh, mesh.X0, b.edge(p), b.xi(p));
    const Vec2 t = (mesh.X0[e[2]] - mesh.X0[e[0]]).normalized(), n_e(t.y(), -t.x());
    CHECK((anchor + b.along(p) * t - b.depth(p) * n_e - x[p]).norm() < 1e-15);
    CHECK(n[p].dot(n_e) > 0.7); // the edge's normal, or a corner's bisector
    CHECK(b.depth(p) > 0.0);    // inside the solid
    total += force[p];
    moment += cross(anchor, force[p]);
    double nearest = 1.0;
    for (std::size_t q = 0; q < b.size(); ++q)
      if (q != p) nearest = std::min(nearest, (x[q] - x[p]).norm());
    closest = std::min(closest, nearest);
    farthest_nearest = std::max(farthest_nearest, nearest);
  }
  b.distribute(force, nodal);
  Vec2 total_nodal = Vec2::Zero();
  double moment_nodal = 0.0;
  for (std::size_t k = 0; k < nodal.size(); ++k)
    total_nodal += nodal[k], moment_nodal += cross(mesh.X0[k], nodal[k]);
  INFO("points " << b.size() << ", nearest-neighbour spacing " << closest << " .. "
                 << farthest_nearest << " m");
  // Floor 20 x 4, sides 4 x 40 each, 13 of the 16 lattice points in each corner (as the walls).
  CHECK(b.size() == 80 + 2 * 160 + 2 * 13);
  CHECK(std::abs(closest - dp) < 1e-12);
  CHECK(std::abs(farthest_nearest - dp) < 1e-12);
  CHECK((total_nodal - total).norm() < 1e-13 * static_cast<double>(b.size()));
  CHECK(std::abs(moment_nodal - moment) < 1e-14 * static_cast<double>(b.size()));
}

TEST_CASE("sph interface boundary: a column at rest on a rigid interface carries its weight",
          "[apps][sph]") {
  // The container is the structure: its inner outline, right side down, floor, left side up.
  const Scene scene = parse_scene(
      sph_scene("  viscosity: 1.0e-6\n  damping_time: 0.3\n  regions:\n    - min: [0.0, 0.0]\n"
                "      max: [0.1, 0.1]\n  domain:\n    min: [-0.05, -0.05]\n    max: [0.15, "
                "0.25]\n"),
      "column.yaml", {});
  const InterfaceMesh mesh =
      polyline_mesh({{0.1, 0.2}, {0.1, 0.0}, {0.0, 0.0}, {0.0, 0.2}}, false, 0.02);
  SphModel model(scene, {mesh});
  coupling::FluidSolver& F = model.coupling_solver();
  const coupling::InterfaceMotion rest{mesh.X0, std::vector<Vec2>(mesh.node_count(), Vec2::Zero()),
                                       std::vector<Vec2>(mesh.node_count(), Vec2::Zero())};
  const double weight = 1000.0 * 9.81 * 0.1 * 0.1, dt = 1e-3;
  Vec2 sum = Vec2::Zero();
  long samples = 0;
  for (int k = 0; k < 500; ++k) {
    F.set_interface_motion(rest);
    F.advance(k * dt, dt);
    if (k < 400) continue;
    for (const Vec2& f : F.interface_loads().f) sum += f;
    ++samples;
  }
  const Vec2 mean = sum / static_cast<double>(samples);
  INFO("mean load on the interface over 0.4-0.5 s: ("
       << mean.x() << ", " << mean.y() << ") N/m, weight " << weight << " N/m; "
       << model.fluid().steps() << " acoustic steps");
  CHECK(model.fluid().removed() == 0);
  CHECK(std::abs(mean.y() / -weight - 1.0) < 0.02);
  CHECK(std::abs(mean.x()) < 0.01 * weight);
}

TEST_CASE("sph interface boundary: fluid thrown at a free rigid body conserves total momentum",
          "[apps][sph]") {
  // No gravity: a 0.04 m square of water at 1 m/s hits a free 0.04 x 0.06 m body (1000 kg/m^3)
  // 0.02 m away. The body moves by its interface loads (M dV/dt = sum f); fluid + body momentum
  // stays at its start to round-off through the impact, with boundary points on the lattice and
  // with the body's particles as nodes of the interface mesh.
  const Scene scene = parse_scene(
      sph_scene("  viscosity: 1.0e-6\n  regions:\n    - min: [0.0, 0.0]\n      max: [0.04, 0.04]\n"
                "  domain:\n    min: [-0.2, -0.2]\n    max: [0.4, 0.25]\n",
                "", "[0.0, 0.0]"),
      "throw.yaml", {});
  const std::vector<Vec2> body = {{0.06, -0.01}, {0.1, -0.01}, {0.1, 0.05}, {0.06, 0.05}};
  InterfaceMesh mesh = polyline_mesh(body, true, 0.01);
  const bool particles = GENERATE(false, true); // the body's own lattice at dp/2 as the points
  if (particles)
    for (int j = 0; j < 24; ++j)
      for (int i = 0; i < 16; ++i) {
        mesh.X0.push_back({0.06 + (i + 0.5) * 0.0025, -0.01 + (j + 0.5) * 0.0025});
        mesh.particle_volume.push_back(0.0025 * 0.0025);
      }
  SphModel model(scene, {mesh}, {body});
  sph::SphFluid& fluid = model.fluid();
  fluid.set_velocities(std::vector<Vec2>(fluid.particles().size(), Vec2(1.0, 0.0)));
  coupling::FluidSolver& F = model.coupling_solver();
  const double M = 1000.0 * 0.04 * 0.06, dt = 5e-4;
  Vec2 d = Vec2::Zero(), V = Vec2::Zero();
  const Vec2 P0 = fluid.momentum();
  coupling::InterfaceMotion m{mesh.X0, std::vector<Vec2>(mesh.node_count(), Vec2::Zero()),
                              std::vector<Vec2>(mesh.node_count(), Vec2::Zero())};
  double worst = 0.0;
  for (int k = 0; k < 80; ++k) {
    for (std::size_t n = 0; n < mesh.node_count(); ++n)
      m.x[n] = mesh.X0[n] + d + V * dt, m.v[n] = V;
    F.set_interface_motion(m);
    F.advance(k * dt, dt);
    Vec2 f = Vec2::Zero();
    for (const Vec2& q : F.interface_loads().f) f += q;
    d += V * dt;
    V += f * dt / M;
    worst = std::max(worst, (fluid.momentum() + M * V - P0).norm() / P0.norm());
  }
  INFO((particles ? "particle nodes" : "lattice points")
       << ": body momentum " << M * V.x() << " N s/m of the fluid's initial " << P0.x()
       << "; worst relative change of the total " << worst << "; " << fluid.steps()
       << " acoustic steps");
  CHECK(fluid.removed() == 0);
  CHECK(M * V.x() > 0.05 * P0.x()); // the impact happened
  CHECK(worst < 1e-12);
}

TEST_CASE("sph + fem: the tiny obstacle under the SPH fluid follows it under the EMPS fluid",
          "[apps][sph][coupled]") {
  // Any fluid with any structure: SPH + FEM against EMPS + FEM, CSS at 2e-5 s, to 0.06 s.
  // Measured corner x at 0.02 .. 0.06 s: SPH +12.8, +11.9, +9.6, +4.4, +3.0 % from EMPS with the
  // dummy pressure of eq. 16 extrapolated to every dummy (the side-wall fix; before it +8.1, +6.6,
  // +7.2, -0.6, -3.6 %); held to 15 % (a regression bound between two methods, not an accuracy
  // claim).
  test::check_tiny_obstacle_follows(FSI_TEST_DATA "/tiny_coupled_sph.yaml", {}, 0.15);
}

namespace {

/// tiny_any_pair.yaml as sph + `structure` to 0.004 s (200 coupling steps, 6 advection steps),
/// continued from its checkpoint at step 100 (inside an advection step): bitwise the
/// uninterrupted run, the obstacle's corner pushed in +x. With fluid.interface_acceleration the
/// interface velocity at the checkpoint (fluid/interface/motion) feeds the walls' mean
/// acceleration, so the test fails without it.
void check_sph_pair_restart(const std::string& structure, const std::string& extra = "") {
  std::vector<std::string> overrides = {"fluid.type=sph",
                                        "fluid.interface_acceleration=true",
                                        "structures[0].type=" + structure,
                                        "time.end=0.004",
                                        "output.interval=0.001",
                                        "checkpoint={interval_steps: 100, keep: 9}"};
  if (!extra.empty()) overrides.push_back(extra);
  const Scene scene = load_scene(FSI_TEST_DATA "/tiny_any_pair.yaml", overrides);
  const fs::path dir = fs::temp_directory_path() /
                       ("fsi_test_sph_" + structure + (extra.empty() ? "" : "_x") + "_restart");
  test::check_restart_bitwise(scene, dir, 100, 200, 2000);
  std::ifstream csv(dir / "whole" / "probes.csv");
  std::string line, last;
  std::getline(csv, line);
  REQUIRE(line == "time,corner_x,front");
  while (std::getline(csv, line)) last = line;
  const double corner = std::stod(last.substr(last.find(',') + 1));
  INFO("corner_x at 0.004 s: " << corner << " m");
  CHECK(corner > 1e-6);
}

} // namespace

TEST_CASE("sph + fem continued from a checkpoint is bitwise the uninterrupted run",
          "[apps][sph][coupled]") {
  check_sph_pair_restart("fem");
}

TEST_CASE("sph + tlsph continued from a checkpoint is bitwise the uninterrupted run",
          "[apps][sph][coupled]") {
  check_sph_pair_restart("tlsph");
}

TEST_CASE("sph + tlsph with the solid's particles as the boundary continues bitwise",
          "[apps][sph][coupled]") {
  check_sph_pair_restart("tlsph", "structures[0].tlsph.interface_particles=true");
}
