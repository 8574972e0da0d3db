// 3-D scenes (dimension: 3, issue 44): the key and its errors, 3-D points and vectors, a fluid
// refused, the fem plug-in's box and its T10 mesh; each error one line naming file, line, key.
#include "fem/fem_model_t10.hpp"
#include "fem/fem_spec.hpp"
#include "fsi/core/error.hpp"
#include "fsi_app/cli.hpp"
#include "fsi_app/scene.hpp"
#include "structure_fem/gmsh_reader.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <sstream>
#include <string>

using namespace fsi::app;

namespace {

// A 2 x 1 x 1 box of cells (12 T10) clamped on its left face, a probe at its tip.
const std::string t10_box_scene = R"(dimension: 3
gravity: [0.0, -9.81, 0.0]
time: {end: 0.002, dt: 0.001}
output:
  interval: 0.001
  probes:
    - {name: tip_z, quantity: displacement_z, structure: beam, point: [1.0, 0.1, 0.1]}
structures:
  - name: beam
    mesh: {kind: box, origin: [0, 0, 0], width: 1.0, height: 0.1, depth: 0.1,
           elements_x: 2, elements_y: 1, elements_z: 1}
    material: {youngs_modulus: 1.0e7, poisson_ratio: 0.3, density: 1000.0}
    clamped: [left]
    loads: [{boundary: right, force: [0, 0, -1.0]}]
)";

Scene parsed(const std::vector<std::string>& overrides = {}) {
  return parse_scene(t10_box_scene, "b.yaml", overrides);
}

} // namespace

TEST_CASE("apps: a 3-D scene reads its points as [x, y, z]", "[apps][scene][3d]") {
  const Scene s = parsed();
  CHECK(s.dimension == 3);
  CHECK(s.gravity3 == fsi::Vec3(0.0, -9.81, 0.0));
  REQUIRE(s.output.probes[0].point3);
  CHECK(*s.output.probes[0].point3 == fsi::Vec3(1.0, 0.1, 0.1));
  const auto& fe = s.structures[0].as<fem_plugin::StructureSpec>();
  CHECK(fe.mesh.depth == 0.1);
  CHECK(fe.mesh.elements_z == 1);
  CHECK(fe.loads[0].force3 == fsi::Vec3(0.0, 0.0, -1.0));
  CHECK(fe.options.linear_solver.kind == fsi::fem::LinearSolverKind::cholmod); // 3-D default
  CHECK(load_scene(FSI_TEST_DATA "/valid_structure.yaml", {}).dimension == 2); // the default
}

TEST_CASE("apps: bad 3-D keys name file, line and key", "[apps][scene][3d]") {
  // (override, the whole message after "b.yaml: --set OVERRIDE: ")
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"dimension=4", "dimension: must be in [2, 3], got 4"},
      {"gravity=[0, -9.81]", "gravity: expected [x, y, z]: the scene is 3-D (dimension: 3)"},
      {"structures[0].material.plane=strain",
       "structures[0].material.plane: a 3-D solid has the full 3-D law; plane is 2-D only"},
      {"structures[0].mesh.kind=rectangle",
       "structures[0].mesh.kind: a 3-D scene's mesh is a box or gmsh (rectangle is 2-D)"},
      {"structures[0].clamped=[x_min]", "structures[0].clamped: unknown boundary tag 'x_min' (a "
                                        "box has left, right, bottom, top, back, front)"},
  };
  for (const auto& [set, what] : cases) {
    INFO(set);
    CHECK_THROWS_WITH(parsed({set}), Catch::Matchers::Equals("b.yaml: --set " + set + ": " + what));
  }
  // As TL-SPH (issue 45): the FE loads do not translate, named at their line.
  CHECK_THROWS_WITH(parsed({"structures[0].type=tlsph"}),
                    Catch::Matchers::Equals("b.yaml:14: structures[0].loads: a TL-SPH solid takes "
                                            "no constant loads: with loads the entry is of type "
                                            "fem only"));
  // 2-D again, the scene's 3-D gravity is refused at its own line.
  CHECK_THROWS_WITH(parsed({"dimension=2"}),
                    Catch::Matchers::Equals("b.yaml:2: gravity: expected [x, y]: the scene is 2-D "
                                            "(give dimension: 3 for [x, y, z])"));
  CHECK_THROWS_WITH(parse_scene("time: {end: 1, dt: 1}\noutput:\n  interval: 1\n  probes:\n"
                                "    - {name: z, quantity: displacement_z, structure: b}\n",
                                "t.yaml", {}),
                    Catch::Matchers::Equals("t.yaml:5: output.probes[0].quantity: displacement_z "
                                            "needs a 3-D scene (dimension: 3)"));
}

TEST_CASE("apps: fsi check refuses a bad 3-D key with exit status 2", "[apps][scene][3d]") {
  std::ostringstream out, err;
  const std::string scene = FSI_SOURCE_DIR "/data/scenes/cantilever_3d.yaml";
  CHECK(run_cli({"check", scene, "--set", "structures[0].mesh.origin=[0, 0]"}, out, err, false) ==
        2);
  CHECK(err.str() == scene + ": --set structures[0].mesh.origin=[0, 0]: structures[0].mesh.origin: "
                             "expected [x, y, z]: the scene is 3-D (dimension: 3)\n");
}

TEST_CASE("apps: the 3-D box scene builds its T10 mesh and probes the tip", "[apps][scene][3d]") {
  const Scene s = parsed();
  const auto part = find_structure_plugin("fem")->build(s, 0);
  const auto& model = dynamic_cast<const fem_plugin::FemModelT10&>(*part);
  CHECK(model.structure().mesh().num_elements() == 12);     // 6 per cell
  CHECK(model.structure().mesh().num_nodes() == 5 * 3 * 3); // half-spacing lattice
  CHECK(model.structure().mesh().node_set("left").size() == 3 * 3);
  // The tip load of -1 N along z: after a step the tip at (1, 0.1, 0.1) (node 44) moves down z.
  auto& moved = *part;
  moved.advance(0.0, 1e-3);
  const double tip_z = *model.probe(s.output.probes[0]);
  CHECK(tip_z == model.structure().displacement()[3 * 44 + 2]);
  CHECK(tip_z < -1e-9);
}

TEST_CASE("apps: a 3-D scene reads a Gmsh T10 mesh with its physical surfaces",
          "[apps][scene][3d]") {
  // The unit cube of tests/structure_fem/data/gmsh (surfaces "clamped" and "loaded").
  const std::string cube = FSI_SOURCE_DIR "/tests/structure_fem/data/gmsh/cube_41.msh";
  const std::string text = "dimension: 3\ntime: {end: 0.002, dt: 0.001}\noutput: {interval: "
                           "0.001}\nstructures:\n  - name: cube\n    mesh: {kind: gmsh, file: " +
                           cube +
                           "}\n    material: {youngs_modulus: 1.0e6, poisson_ratio: 0.3, "
                           "density: 1000.0}\n    clamped: [clamped]\n    loads: [{boundary: "
                           "loaded, pressure: 1.0e3}]\n";
  const Scene s = parse_scene(text, "g.yaml", {});
  const auto part = find_structure_plugin("fem")->build(s, 0);
  const auto& model = dynamic_cast<const fem_plugin::FemModelT10&>(*part);
  const fsi::fem::TetMesh mesh = fsi::fem::read_gmsh_t10(cube);
  CHECK(model.structure().mesh().num_elements() == mesh.num_elements());
  CHECK(model.structure().mesh().num_nodes() == mesh.num_nodes());
  // The pressure pushes the loaded face in: the external forces sum to -p A n (A = 1 m^2).
  const fsi::fem::Vector& f = model.structure().external_forces();
  const fsi::Vec3 total(f(Eigen::seqN(0, f.size() / 3, 3)).sum(),
                        f(Eigen::seqN(1, f.size() / 3, 3)).sum(),
                        f(Eigen::seqN(2, f.size() / 3, 3)).sum());
  CHECK(total.norm() == Approx(1.0e3).epsilon(1e-12));
  const Scene bad = parse_scene(text, "g.yaml", {"structures[0].clamped=[nope]"});
  CHECK_THROWS_WITH(find_structure_plugin("fem")->validate(bad, 0),
                    Catch::Matchers::Equals("g.yaml:5: structures[0].mesh: " + cube +
                                            ": missing physical group \"nope\" (the file names: "
                                            "clamped, loaded, solid)"));
}

TEST_CASE("apps: sliding faces of a 3-D scene hold the displacement along their normal",
          "[apps][scene][3d]") {
  // Uniaxial tension t along y of a 0.3 x 0.5 x 0.2 box sliding on its bottom, left and back
  // faces: u = t/E (-nu x, y, -nu z) exactly (linear in X, which T10 holds); t/E = 1e-7, so the
  // geometric nonlinearity of St. Venant-Kirchhoff is about 1e-7 of u.
  const double t = 1.0, E = 1e7, nu = 0.3, W = 0.3, H = 0.5, D = 0.2;
  const Scene s = parse_scene(
      t10_box_scene, "b.yaml",
      {"gravity=[0, 0, 0]", "structures[0].mesh.width=0.3", "structures[0].mesh.height=0.5",
       "structures[0].mesh.depth=0.2", "structures[0].mesh.elements_y=3",
       "structures[0].mesh.elements_z=2", "structures[0].clamped=[]",
       "structures[0].sliding=[bottom, left, back]",
       "structures[0].loads=[{boundary: top, force: [0, " + std::to_string(t * W * D) + ", 0]}]",
       "output.probes=[]"});
  const auto part = find_structure_plugin("fem")->build(s, 0);
  auto& structure = dynamic_cast<fem_plugin::FemModelT10&>(*part).structure();
  structure.solve_static();
  const auto& X = structure.mesh().X;
  double error = 0.0;
  for (std::size_t k = 0; k < X.size(); ++k) {
    const fsi::Vec3 exact = t / E * fsi::Vec3(-nu * X[k].x(), X[k].y(), -nu * X[k].z());
    error = std::max(
        error,
        (structure.displacement().segment<3>(3 * static_cast<Eigen::Index>(k)) - exact).norm());
  }
  CHECK(error < 1e-5 * t / E * H);
  // A face off the coordinate planes cannot slide by one component; an unknown tag is named.
  CHECK_THROWS_WITH(parse_scene(t10_box_scene, "b.yaml", {"structures[0].sliding=[lid]"}),
                    Catch::Contains("sliding: unknown boundary tag 'lid'"));
}

TEST_CASE("apps: a 3-D scene's clamped_rigid_motion turns the body rigidly, stress-free",
          "[apps][scene][3d]") {
  // The 1 x 0.1 x 0.1 beam's left face turned about y (axis given unnormalised) through its
  // centre c by theta(t) = 1 rad sin(2 pi t / 4 s): solved statically at t = 1 s (theta = 1 rad),
  // every node is at c + R (X - c) and the stress vanishes (F = R: E = 0); a positive turn
  // about +y carries the tip to -z. Then one step from t = 0.5 s: the clamped nodes' v and a are
  // the central differences of their prescribed u.
  const Scene s = parse_scene(
      t10_box_scene, "b.yaml",
      {"gravity=[0, 0, 0]", "structures[0].loads=[]",
       "structures[0].clamped_rigid_motion={kind: sinusoid, axis: [0, 2, 0], pivot: [0, "
       "0.05, 0.05], amplitude: 1.0, period: 4.0}",
       "output.probes=[]"});
  const auto part = find_structure_plugin("fem")->build(s, 0);
  auto& structure = dynamic_cast<fem_plugin::FemModelT10&>(*part).structure();
  const fsi::Vec3 c(0.0, 0.05, 0.05), y(0.0, 1.0, 0.0);
  const auto u_at = [&](const fsi::Vec3& X, double t) -> fsi::Vec3 { // the prescribed motion
    return (Eigen::AngleAxisd(std::sin(2.0 * M_PI * t / 4.0), y).toRotationMatrix() -
            fsi::Mat3::Identity()) *
           (X - c);
  };
  structure.solve_static({6, 1.0});
  const auto& X = structure.mesh().X;
  double deviation = 0.0;
  for (std::size_t k = 0; k < X.size(); ++k)
    deviation =
        std::max(deviation, (structure.displacement().segment<3>(3 * static_cast<Eigen::Index>(k)) -
                             u_at(X[k], 1.0))
                                .norm());
  const double stress = structure.von_mises().cwiseAbs().maxCoeff();
  WARN("clamped_rigid_motion 1 rad about y: largest deviation from the rigid rotation "
       << deviation << " m, largest von Mises / E " << stress / 1e7);
  CHECK(deviation < 1e-12); // m; the tip moves 0.96 m
  CHECK(stress < 1e-9 * 1e7);
  for (std::size_t k = 0; k < X.size(); ++k)
    if ((X[k] - fsi::Vec3(1.0, 0.05, 0.05)).norm() < 1e-12) // the tip's centre: -L sin(1 rad)
      CHECK(structure.displacement()[3 * static_cast<Eigen::Index>(k) + 2] < -0.8);

  structure.solve_static({1, 0.5});
  structure.advance(1e-3);
  const double t = structure.time(), h = 1e-4;
  double v_error = 0.0, a_error = 0.0;
  for (const int k : structure.mesh().node_set("left")) {
    const fsi::Vec3& Xk = X[static_cast<std::size_t>(k)];
    const fsi::Vec3 v = (u_at(Xk, t + h) - u_at(Xk, t - h)) / (2.0 * h);
    const fsi::Vec3 a = (u_at(Xk, t + h) - 2.0 * u_at(Xk, t) + u_at(Xk, t - h)) / (h * h);
    v_error = std::max(v_error, (structure.velocity().segment<3>(3 * k) - v).norm());
    a_error = std::max(a_error, (structure.acceleration().segment<3>(3 * k) - a).norm());
  }
  WARN("clamped nodes at t = " << t << " s: v within " << v_error << " m/s, a within " << a_error
                               << " m/s^2 of the central differences of u");
  CHECK(v_error < 1e-6); // |v| up to 0.08 m/s; the differences err by ~h^2
  CHECK(a_error < 1e-5); // |a| up to 0.16 m/s^2

  // Bad input, one line each: a zero axis; the 2-D wall key in 3-D; no clamp to turn.
  CHECK_THROWS_WITH(
      parse_scene(t10_box_scene +
                      "    clamped_rigid_motion: {kind: sinusoid, axis: [0, 0, 0], amplitude: "
                      "1, period: 1}\n",
                  "b.yaml", {}),
      "b.yaml:15: structures[0].clamped_rigid_motion.axis: is zero");
  CHECK_THROWS_WITH(parse_scene(t10_box_scene, "b.yaml", {"structures[0].clamped_motion=tank"}),
                    Catch::Contains("structures[0].clamped_motion: names a 2-D wall; 3-D scenes "
                                    "have none: move the clamp with clamped_rigid_motion"));
  CHECK_THROWS_WITH(
      parse_scene(t10_box_scene, "b.yaml",
                  {"structures[0].clamped=[]",
                   "structures[0].clamped_rigid_motion={kind: sinusoid, axis: "
                   "[0, 1, 0], amplitude: 1, period: 1}"}),
      Catch::Contains("structures[0].clamped_rigid_motion: needs clamped boundary tags to move"));
  // A TL-SPH solid made from the entry (--set type=tlsph) would drop the turn: refused.
  CHECK_THROWS_WITH(
      parse_scene(t10_box_scene, "b.yaml",
                  {"structures[0].loads=[]", "structures[0].type=tlsph",
                   "structures[0].clamped_rigid_motion={kind: sinusoid, axis: [0, 1, 0], "
                   "amplitude: 1, period: 1}"}),
      Catch::Contains("structures[0].clamped_rigid_motion: a 3-D TL-SPH solid's clamps are "
                      "fixed: with a moving clamp the entry is of type fem only"));
}
