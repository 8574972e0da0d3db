// The 3-D TL-SPH solid as the coupler's S (TlsphModel3::coupling_solver3(), issues 45 and 46):
// the nodal loads handed through S reach the particles whole and its motion out is the interface
// particles' (a); a clamped square plate under a uniform pressure on its front face through S
// relaxes to a static centre deflection 18 % above the T10 solution of the same scene entry, the
// split in docs/solid_tlsph.md (b, [slow]);
// the state written and read through S, and saved and restored by it, continues bitwise (c).
#include "fem/fem_model_t10.hpp"
#include "fsi/core/state_archive.hpp"
#include "fsi_app/scene.hpp"
#include "tlsph/tlsph_model3.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <random>
#include <string>

using namespace fsi;
using namespace fsi::app;
using tlsph_plugin::TlsphModel3;

namespace {

// A 6 x 5 x 4 dp block, its x < 0 rows clamped, wetted on three faces (one of them the clamp's
// x- face: its nodes carry reactions).
const std::string block_scene = R"(dimension: 3
gravity: [0.0, 0.0, 0.0]
time: {end: 1.0e-4, dt: 5.0e-5}
output: {interval: 1.0e-4}
structures:
  - name: block
    type: tlsph
    region: {min: [-0.03, 0.0, 0.0], max: [0.06, 0.05, 0.04]}
    dp: 0.01
    material: {youngs_modulus: 1.0e6, poisson_ratio: 0.3, density: 1000.0}
    clamped: [{min: [-0.03, 0.0, 0.0], max: [0.0, 0.05, 0.04]}]
    interface: [left, top, front]
)";

// A 1 x 1 x 0.2 m square plate (a / H = 5) clamped on its four side faces (the clamps' corners
// by the odd images of odd images), wetted on its face z = 0.2 (front): an FE entry, T10 10 x 10 x
// 2 cells; as TL-SPH (type switched) dp = 0.05, H / dp = 4, each clamped side continued 4 dp
// outwards. The probe interpolates at the centre of the mid-plane (a T10 node; the TL-SPH kernel
// interpolation between the two middle layers).
const std::string plate_scene = R"(dimension: 3
gravity: [0.0, 0.0, 0.0]
time: {end: 0.001, dt: 0.001}
output:
  interval: 0.001
  probes:
    - {name: centre, quantity: displacement_z, structure: plate, point: [0.5, 0.5, 0.1],
       interpolate: true}
structures:
  - name: plate
    clamped: [left, right, bottom, top]
    interface: [front]
    material: {youngs_modulus: 1.0e7, poisson_ratio: 0.3, density: 1000.0}
    mesh:
      kind: box
      origin: [0, 0, 0]
      width: 1.0
      height: 1.0
      depth: 0.2
      elements_x: 10
      elements_y: 10
      elements_z: 2
)";

std::unique_ptr<TlsphModel3> build(const Scene& scene) {
  return std::make_unique<TlsphModel3>(scene, scene.structures[0]);
}

// A pressure p on every triangle of the interface, -p n A / 3 to each corner (the order-1
// triangles' consistent load of a uniform pressure), on the reference faces.
coupling::InterfaceLoads3 pressure_loads(const InterfaceMesh3& mesh, double p) {
  auto loads = coupling::InterfaceLoads3::zeros(mesh.node_count());
  for (const auto& f : mesh.faces) {
    const Vec3 a = mesh.X0[f[0]], b = mesh.X0[f[1]], c = mesh.X0[f[2]];
    const Vec3 share = -p / 6.0 * (b - a).cross(c - a); // -p (A n) / 3
    for (int k = 0; k < 3; ++k) loads.f[f[static_cast<std::size_t>(k)]] += share;
  }
  return loads;
}

coupling::InterfaceLoads3 random_loads(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto loads = coupling::InterfaceLoads3::zeros(n);
  for (auto& f : loads.f) f = Vec3(u(rng), u(rng), u(rng));
  return loads;
}

} // namespace

TEST_CASE("tlsph S 3-D: the loads through S are the particles' external force, its motion the "
          "interface particles'",
          "[apps][tlsph][3d]") {
  const Scene scene = parse_scene(block_scene, "b.yaml", {});
  const auto model = build(scene);
  const InterfaceMesh3& mesh = model->interface_mesh3();
  const tlsph::TlsphSolid3& solid = model->solid();
  // 9 x 5 x 4 particles: node grids of 11 x 7 x 6 lines. The faces x- (7 x 6 nodes), y+ (11 x 6)
  // and z+ (11 x 7) share three edges (6, 7 and 11 nodes) and a corner; 2 triangles a cell.
  CHECK(mesh.node_count() == 42 + 66 + 77 - 6 - 7 - 11 + 1);
  CHECK(mesh.faces.size() == 2 * (6 * 5 + 10 * 5 + 10 * 6));
  coupling::StructureSolver3& s = model->coupling_solver3();
  const auto loads = random_loads(mesh.node_count(), 7);
  s.set_interface_loads(loads);
  // At rest (F = I, v = 0, no gravity) a = f / (rho V): the free particles' m a sum to the loads
  // on the nodes attached to them, particle by particle; the clamped ones take none (reactions).
  std::vector<Vec3> on(solid.size(), Vec3::Zero());
  const auto& particle = solid.interface_particles();
  for (std::size_t k = 0; k < mesh.node_count(); ++k) on[particle[k]] += loads.f[k];
  const double rho = solid.options().material.density;
  double worst = 0.0, total = 0.0;
  Vec3 sum_ma = Vec3::Zero(), sum_f = Vec3::Zero();
  std::size_t clamped_nodes = 0;
  for (std::size_t i = 0; i < solid.size(); ++i) {
    const Vec3 ma = rho * solid.volume(i) * solid.acceleration(i);
    if (solid.clamped(i)) {
      CHECK(ma.isZero());
      continue;
    }
    worst = std::max(worst, (ma - on[i]).norm());
    total += on[i].norm();
    sum_ma += ma, sum_f += on[i];
  }
  for (std::size_t k = 0; k < mesh.node_count(); ++k) clamped_nodes += solid.clamped(particle[k]);
  WARN("S 3-D: " << mesh.node_count() << " nodes (" << clamped_nodes << " on clamped particles), "
                 << "largest |m a - f| per particle " << worst << " N of sum |f| " << total
                 << " N; |sum m a - sum f| " << (sum_ma - sum_f).norm() << " N");
  // On the clamped particles: the x- face and the y+ and z+ nodes at x < 0 (3 grid lines more).
  CHECK(clamped_nodes == 42 + 3 * 6 + 3 * 7 - 3);
  CHECK(worst <= 1e-15 * total);
  CHECK((sum_ma - sum_f).norm() <= 1e-14 * total);
  // Motion out, after two coupler steps: each node at x_p + F_p (X - X_p) of its particle, with
  // its particle's v and a (a node on a clamped particle at X, at rest).
  s.advance(0.0, 5.0e-5);
  s.set_interface_loads(loads);
  s.advance(5.0e-5, 5.0e-5);
  const coupling::InterfaceMotion3 m = s.interface_motion();
  REQUIRE(m.x.size() == mesh.node_count());
  double dx = 0.0, dv = 0.0, moved = 0.0;
  for (std::size_t k = 0; k < mesh.node_count(); ++k) {
    const std::size_t i = particle[k];
    const Vec3 X = mesh.X0[k];
    const bool held = solid.clamped(i);
    const Vec3 x = held ? X
                        : Vec3(solid.position(i) +
                               solid.deformation_gradient(i) * (X - solid.reference_position(i)));
    dx = std::max(dx, (m.x[k] - x).norm());
    dv = std::max(dv, (m.v[k] - (held ? Vec3::Zero() : solid.velocity(i))).norm() +
                          (m.a[k] - (held ? Vec3::Zero() : solid.acceleration(i))).norm());
    moved = std::max(moved, (m.x[k] - X).norm());
  }
  WARN("S 3-D motion: largest node displacement " << moved << " m; |x - (x_p + F_p (X - X_p))| "
                                                  << dx << " m, v and a differences " << dv);
  CHECK(moved > 1e-8);
  CHECK(dx <= 1e-15);
  CHECK(dv == 0.0);
}

TEST_CASE("tlsph S 3-D: state written and read, saved and restored through S continues bitwise",
          "[apps][tlsph][3d]") {
  const Scene scene = parse_scene(block_scene, "b.yaml", {});
  const auto a = build(scene), b = build(scene);
  coupling::StructureSolver3 &sa = a->coupling_solver3(), &sb = b->coupling_solver3();
  const std::size_t n = a->interface_mesh3().node_count();
  const double dt = 5.0e-5;
  sa.set_interface_loads(random_loads(n, 1));
  sa.advance(0.0, dt);
  StateArchive archive;
  sa.write_state(archive);
  sb.read_state(archive);
  // An implicit scheme's iteration: save, advance with one load, restore, advance with another.
  sa.save_state();
  sa.set_interface_loads(random_loads(n, 2));
  sa.advance(dt, dt);
  const coupling::InterfaceMotion3 first = sa.interface_motion();
  sa.restore_state();
  for (auto* s : {&sa, &sb}) {
    s->set_interface_loads(random_loads(n, 3));
    s->advance(dt, dt);
  }
  const coupling::InterfaceMotion3 ma = sa.interface_motion(), mb = sb.interface_motion();
  CHECK(ma.x == mb.x);
  CHECK(ma.v == mb.v);
  CHECK(ma.a == mb.a);
  CHECK(ma.x != first.x); // the restored step took the other load
}

TEST_CASE("tlsph S 3-D: a clamped square plate under a pressure through S relaxes to a centre "
          "deflection above the T10 plate's by more than its section's quadrature",
          "[apps][tlsph][3d][slow]") {
  const double p = 1000.0, H = 0.2, dp = 0.05;
  // The T10 plate: the scene's entry with the pressure as its own face load, solved statically.
  const Scene fe =
      parse_scene(plate_scene + "    loads: [{boundary: front, pressure: 1000.0}]\n", "p.yaml", {});
  auto fe_part = find_structure_plugin("fem")->build(fe, 0);
  auto& t10 = dynamic_cast<fem_plugin::FemModelT10&>(*fe_part);
  t10.structure().solve_static();
  const double w_fe = *t10.probe(fe.output.probes[0]);
  // The same entry as TL-SPH: the pressure through S on the whole front face (the clamps' share
  // are reactions), relaxed by mass damping of 250 /s (every mode decays at >= 125 /s).
  const Scene sph = parse_scene(plate_scene, "p.yaml",
                                {"structures[0].type=tlsph", "structures[0].mass_damping=250"});
  const auto plate = build(sph);
  coupling::StructureSolver3& s = plate->coupling_solver3();
  const auto loads = pressure_loads(plate->interface_mesh3(), p);
  const double step = 1.0e-3;
  double w = 0.0, w_before = 0.0;
  for (int n = 0; n < 150; ++n) {
    s.set_interface_loads(loads);
    s.advance(n * step, step);
    w_before = w, w = *plate->probe(sph.output.probes[0]);
  }
  // The particle quadrature of the section softens bending by 1 / (1 - (dp/H)^2); the measured
  // rest (the clamp's Poisson restraint, shear and the clamp of a thick plate) in
  // docs/solid_tlsph.md, "3-D", where +17.7 % at H/dp = 4 falls to +9.2 % at 6.
  const double quadrature = 1.0 / (1.0 - (dp / H) * (dp / H)) - 1.0;
  WARN("clamped square plate, a/H = 5, H/dp = 4: TL-SPH centre "
       << w << " m (last step's change " << w - w_before << "), T10 " << w_fe
       << " m: " << 100.0 * (w / w_fe - 1.0) << " %; the section's quadrature "
       << 100.0 * quadrature << " %");
  CHECK(w_fe < -1e-4);
  CHECK(std::abs(w - w_before) < 1e-4 * std::abs(w));
  CHECK(w / w_fe - 1.0 > quadrature);
  // A regression guard on the measured +17.7 %, not an accuracy criterion: issue 46's 3 % is not
  // met at H/dp = 4 (the split above).
  CHECK(w / w_fe - 1.0 < 0.18);
}
