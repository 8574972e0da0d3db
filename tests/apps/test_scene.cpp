// Scene parsing: a valid scene reads back its values; each class of bad input gives one line
// `FILE:LINE: KEY: what` and exit status 2; overrides apply and fail the same way.
#include "emps/emps_spec.hpp"
#include "fem/fem_spec.hpp"
#include "fsi/core/error.hpp"
#include "fsi_app/cli.hpp"
#include "fsi_app/scene.hpp"
#include "sph/sph_spec.hpp"
#include "test_data.hpp"
#include "tlsph/tlsph_spec.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

using namespace fsi::app;

namespace {

struct CliResult {
  int status;
  std::string out, err;
};

CliResult cli(std::vector<std::string> args) {
  std::ostringstream out, err;
  const int status = run_cli(args, out, err, false);
  return {status, out.str(), err.str()};
}

} // namespace

TEST_CASE("apps: a valid scene reads back its values", "[apps][scene]") {
  const Scene s = load_scene(test::data_dir + "valid_structure.yaml", {});
  CHECK(s.name == "valid_structure");
  CHECK(s.gravity.y() == -10.0);
  CHECK(s.time.end == 0.01);
  REQUIRE(s.time.dt);
  CHECK(*s.time.dt == 1e-3);
  CHECK_FALSE(s.time.courant);
  REQUIRE(s.structures.size() == 1);
  CHECK(s.structures[0].type == "fem"); // default
  const auto& b = s.structures[0].as<fem_plugin::StructureSpec>();
  CHECK(b.mesh.kind == "rectangle");
  CHECK(b.mesh.elements_x == 4);
  CHECK(b.options.material.youngs_modulus == 2e6);
  CHECK(b.options.material.poisson_ratio == 0.25);
  CHECK(b.options.material.plane == fsi::materials::PlaneModel::plane_strain); // default
  CHECK(b.options.newmark.beta == 0.25);
  CHECK(b.options.newmark.gamma == 0.5);
  CHECK(b.options.newton.max_iterations == 20);                                  // default
  CHECK(b.options.linear_solver.kind == fsi::fem::LinearSolverKind::ldlt_or_lu); // default
  CHECK(b.clamped == std::vector<std::string>{"left"});
  REQUIRE(s.output.probes.size() == 1);
  CHECK(s.output.probes[0].point->y() == 0.1);
  CHECK(s.output.fields == std::vector<std::string>{"velocity", "pressure", "pnd", "free_surface",
                                                    "density", "wkgc_indicator", "displacement",
                                                    "von_mises", "det_F"});
  // default: every plug-in's fields
  CHECK_FALSE(s.fluid);
}

TEST_CASE("apps: overrides replace entries before validation", "[apps][scene]") {
  const Scene s = load_scene(
      test::data_dir + "valid_structure.yaml",
      {"time.end=0.5", "structures[0].material.density=2000", "structures[0].linear_solver=cg"});
  CHECK(s.time.end == 0.5);
  const auto& b = s.structures[0].as<fem_plugin::StructureSpec>();
  CHECK(b.options.material.density == 2000.0);
  CHECK(b.options.linear_solver.kind == fsi::fem::LinearSolverKind::cg_incomplete_cholesky);
}

TEST_CASE("apps: a denormal or tiny structure density is refused by its range", "[apps][scene]") {
  // Issue 41 item 11: 5e-324 passed "> 0" and the mass matrix failed to factorise mid-run.
  for (const std::string value : {"5e-324", "1e-300", "1e-4"}) {
    INFO(value);
    const auto r = cli({"check", test::data_dir + "valid_structure.yaml", "--set",
                        "structures[0].material.density=" + value});
    CHECK(r.status == 2);
    CHECK(r.err.find(": structures[0].material.density: must be in [0.001, 1e+06], got ") !=
          std::string::npos);
  }
}

TEST_CASE("apps: a mesh path that is a folder, FIFO or device says what it is", "[apps][scene]") {
  // Issue 41 item 11: each said "file not found".
  const auto fifo = std::filesystem::temp_directory_path() / "fsi_test_mesh_fifo.msh";
  std::filesystem::remove(fifo);
  REQUIRE(mkfifo(fifo.c_str(), 0644) == 0);
  const std::string folder = std::filesystem::temp_directory_path().string();
  for (const auto& [path, what] :
       {std::pair<std::string, std::string>{folder, folder + " is a folder; give a file"},
        {fifo.string(), fifo.string() + " is not a regular file (a FIFO, device or socket)"},
        {"/dev/zero", "/dev/zero is not a regular file (a FIFO, device or socket)"}}) {
    INFO(path);
    const auto r = cli({"check", test::data_dir + "valid_structure.yaml", "--set",
                        "structures[0].mesh={kind: gmsh, file: " + path + "}"});
    CHECK(r.status == 2);
    CHECK(r.err.find(": structures[0].mesh.file: " + what) != std::string::npos);
  }
  std::filesystem::remove(fifo);
}

TEST_CASE("apps: a closed wall polyline whose last point is its first is refused naming it",
          "[apps][scene]") {
  const std::string scene = test::data_dir + "tiny_fluid.yaml";
  const auto r = cli({"check", scene, "--set",
                      "walls[2]={name: box, closed: true, polyline: [[0.3, 0.0], [0.4, 0.0], "
                      "[0.4, 0.1], [0.3, 0.0]]}"});
  CHECK(r.status == 2);
  CHECK(r.err.find(": walls[2].polyline: the last point 3 is the first (closed: true joins them "
                   "by a zero-length segment); drop the last point\n") != std::string::npos);
}

TEST_CASE("apps: each class of bad input names file, line and key, exit status 2",
          "[apps][scene]") {
  struct Case {
    std::string file, prefix, what;
  };
  const std::vector<Case> cases = {
      {"bad_unknown_key.yaml", ":25: structures[0].material.colour: ", "unknown key"},
      {"bad_misspelt_key.yaml", ":21: structures[0].material.density: ", "'densty' on line 24"},
      {"bad_wrong_type.yaml", ":4: time.end: ", "expected a real number, got 'soon'"},
      {"bad_missing_key.yaml",
       ":21: structures[0].material.youngs_modulus: ", "required key missing"},
      {"bad_density.yaml",
       ":24: structures[0].material.density: ", "must be in [0.001, 1e+06], got -1200"},
      {"bad_youngs.yaml", ":22: structures[0].material.youngs_modulus: ", "must be > 0, got 0"},
      {"bad_dt.yaml", ":5: time.dt: ", "must be > 0, got 0"},
      {"bad_poisson.yaml",
       ":23: structures[0].material.poisson_ratio: ", "must be in (-1, 0.5), got 0.5"},
      {"bad_spacing.yaml", ":9: fluid.l0: ", "larger than fluid region 0"},
      {"bad_mesh_missing.yaml", ":17: structures[0].mesh.file: ", "file not found"},
      {"bad_probe_node.yaml", ":12: output.probes[0].node: ", "node 45 does not exist"},
      {"bad_probe_point.yaml", ":12: output.probes[0].point: ", "no node of structure 'beam'"},
      {"bad_yaml_syntax.yaml", ":4: yaml: ", "end of sequence"},
      // A TL-SPH region from a Gmsh mesh (structures[].region.file).
      {"bad_tlsph_mesh_missing.yaml", ":11: structures[0].region.file: ", "file not found"},
      {"bad_tlsph_mesh_no_triangles.yaml",
       ":11: structures[0].region.file: ", "the mesh has no T6 elements"},
      {"bad_tlsph_mesh_hole.yaml",
       ":11: structures[0].region.file: ", "the boundary is more than one loop"},
      {"bad_tlsph_mesh_pinched.yaml",
       ":11: structures[0].region.file: ", "the boundary touches itself at node 3 (0.01, 0.01)"},
      {"bad_tlsph_mesh_two_groups.yaml", ":11: structures[0].region.file: ",
       "is in two physical groups, 'left' and 'wall' (a side has one tag)"},
      {"bad_tlsph_mesh_tag.yaml", ":14: structures[0].interface: ",
       "no region edge is tagged 'wall' (the region's tags: bottom, left, right, top)"},
  };
  for (const auto& c : cases) {
    INFO(c.file);
    const auto r = cli({"check", test::data_dir + c.file});
    CHECK(r.status == 2);
    CHECK(r.err.rfind(test::data_dir + c.file + c.prefix, 0) == 0);
    CHECK(r.err.find(c.what) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.out.empty());
  }
}

TEST_CASE("apps: a structure's key is spelt as --set spells it in late messages too",
          "[apps][scene]") {
  // Mesh problems found while building the model name structures[i], not structures.<name>.
  const std::string scene = test::data_dir + "valid_structure.yaml";
  auto r = cli({"check", scene, "--set", "structures[0].mesh.width=1e300"});
  CHECK(r.status == 2);
  CHECK(r.err.rfind(scene + ":14: structures[0].mesh: rectangle mesh: ", 0) == 0);
  const std::string order1 = FSI_SOURCE_DIR "/tests/structure_fem/data/gmsh/plate_order1.msh";
  r = cli({"check", scene, "--set", "structures[0].mesh={kind: gmsh, file: " + order1 + "}"});
  CHECK(r.status == 2);
  CHECK(r.err.rfind(scene + ":14: structures[0].mesh: ", 0) == 0);
  CHECK(r.err.find("structures.beam") == std::string::npos);
}

TEST_CASE("apps: a bad override fails like a bad scene entry", "[apps][scene]") {
  const std::string scene = test::data_dir + "valid_structure.yaml";
  auto r = cli({"check", scene, "--set", "structures[0].material.density=abc"});
  CHECK(r.status == 2);
  CHECK(r.err == scene + ": --set structures[0].material.density=abc: "
                         "structures[0].material.density: expected a real number, got 'abc'\n");
  r = cli({"check", scene, "--set", "time.foo=1"});
  CHECK(r.status == 2);
  CHECK(r.err.find("time.foo: unknown key") != std::string::npos);
  r = cli({"check", scene, "--set", "structures[3].name=x"});
  CHECK(r.status == 2);
  CHECK(r.err.find("list index 3 does not exist") != std::string::npos);
  r = cli({"check", scene, "--set", "time.end"});
  CHECK(r.status == 2);
  CHECK(r.err.find("expected key.path=value") != std::string::npos);
}

TEST_CASE("apps: a block named after a solver type holds its keys: any pair by two overrides",
          "[apps][scene]") {
  const std::string scene = test::data_dir + "tiny_any_pair.yaml";
  for (const std::string fluid : {"emps", "sph"})
    for (const std::string structure : {"fem", "tlsph"}) {
      INFO(fluid + " + " + structure);
      const Scene s = load_scene(scene, {"fluid.type=" + fluid, "structures[0].type=" + structure});
      REQUIRE(s.fluid->type == fluid);
      REQUIRE(s.structures[0].type == structure);
      // The chosen type's block is read as keys of the solver block.
      if (fluid == "emps")
        CHECK(dynamic_cast<const emps_plugin::FluidSpec&>(*s.fluid->spec)
                  .options.wall.contact.alpha_rep == 1.0e7);
      else
        CHECK(dynamic_cast<const sph_plugin::SphSpec&>(*s.fluid->spec).options.dp == 4.0e-3);
      if (structure == "fem") {
        const auto& fem = dynamic_cast<const fem_plugin::StructureSpec&>(*s.structures[0].spec);
        CHECK(fem.mesh.width == 0.012);
        CHECK(fem.clamped == std::vector<std::string>{"bottom"});
      } else {
        const auto& tl = dynamic_cast<const tlsph_plugin::TlsphSpec&>(*s.structures[0].spec);
        CHECK(tl.options.dp == 2.0e-3);
        REQUIRE(tl.clamped.size() == 1);
        CHECK(tl.clamped[0].max.y() == 0.0);
      }
      CHECK(cli({"check", scene, "--set", "fluid.type=" + fluid, "--set",
                 "structures[0].type=" + structure})
                .status == 0);
    }
  // The other types' blocks are checked by their plug-ins: a bad value there is named by its path.
  auto r = cli({"check", scene, "--set", "fluid.sph.correction=bogus"});
  CHECK(r.status == 2);
  CHECK(r.err == scene + ": --set fluid.sph.correction=bogus: fluid.sph.correction: expected one "
                         "of none, rkgc, got 'bogus'\n");
  r = cli({"check", scene, "--set", "structures[0].tlsph.dp=-1"});
  CHECK(r.err == scene + ": --set structures[0].tlsph.dp=-1: structures[0].tlsph.dp: must be > 0, "
                         "got -1\n");
  // A key both in the block and in the chosen type's block, or one read before it: named twice.
  r = cli({"check", scene, "--set", "fluid.emps.l0=0.01"});
  CHECK(r.status == 2);
  CHECK(r.err == scene + ": --set fluid.emps.l0=0.01: fluid.emps.l0: also given as fluid.l0 (" +
                     scene + ":23); give it once\n");
  r = cli({"check", scene, "--set", "fluid.type=sph", "--set", "fluid.sph.type=emps"});
  CHECK(r.err.find("fluid.sph.type: also given as fluid.type") != std::string::npos);
  std::ifstream in(scene);
  std::stringstream text;
  text << in.rdbuf();
  std::string untyped = text.str();
  untyped.erase(untyped.find("  type: emps\n"), 13); // the fluid's type by default
  try {
    parse_scene(untyped, "scene.yaml", {"fluid.emps.type=sph"});
    FAIL("a type inside the type's block was accepted");
  } catch (const fsi::InputError& e) {
    CHECK(std::string(e.what()) == "scene.yaml: --set fluid.emps.type=sph: fluid.emps.type: "
                                   "belongs in fluid itself (it is read before fluid.emps)");
  }
  // An EMPS key outside the emps block while the type is sph: named with where it could go.
  r = cli({"check", FSI_SOURCE_DIR "/data/scenes/dam_break_rigid.yaml", "--set", "fluid.type=sph"});
  CHECK(r.err.find("fluid.alpha_rep: is a key of fluid type emps, not of sph (remove it, or move "
                   "it into a block fluid.emps: to keep it for that type)") != std::string::npos);
}

TEST_CASE("apps: docs/scenes.md is the generated scene reference", "[apps][scene]") {
  std::ifstream in(FSI_SOURCE_DIR "/docs/scenes.md");
  REQUIRE(in);
  std::stringstream text;
  text << in.rdbuf();
  CHECK(text.str() == scene_reference());
}

TEST_CASE("apps: the wall model's preset is read before its term keys, which override it",
          "[apps][scene]") {
  const std::string scene = FSI_SOURCE_DIR "/data/scenes/dam_break_rigid.yaml";
  const auto fluid = [&](std::vector<std::string> sets) {
    const Scene s = load_scene(scene, sets);
    return dynamic_cast<const emps_plugin::FluidSpec&>(*s.fluid->spec).options;
  };
  using fsi::emps::WallModel;
  // The preset alone: every wall term but the scene's alpha_rep, and the artificial viscosity,
  // are the preset's, whatever the scene's keys before it.
  fsi::emps::FluidOptions standard;
  fsi::emps::apply_wall_preset(standard, WallModel::standard);
  const auto a = fluid({"fluid.wall_model=default", "fluid.wall_approach_viscosity=0.5"});
  CHECK(a.wall.model == WallModel::standard);
  CHECK(a.wall.pnd.density == fsi::emps::WallDensity::scaled);
  CHECK(a.wall.mirror.same_side);
  CHECK(a.wall.mirror.approach_viscosity == standard.wall.mirror.approach_viscosity);
  CHECK(a.wall.gap_courant == standard.wall.gap_courant);
  CHECK(a.wall.gap_courant > 0.0);
  CHECK(a.artificial_viscosity == standard.artificial_viscosity);
  CHECK(a.artificial_viscosity > 0.0);
  CHECK(a.wall.contact.alpha_rep == 1.0e7); // the scene's
  // A term key overrides the preset wherever it stands in the block or the overrides.
  const auto b = fluid({"fluid.mirror_same_side=false", "fluid.wall_gap_courant=0.25",
                        "fluid.wall_model=default", "fluid.wall_approach_viscosity=0.2",
                        "fluid.artificial_viscosity=0.05"});
  CHECK_FALSE(b.wall.mirror.same_side);
  CHECK(b.wall.gap_courant == 0.25);
  CHECK(b.wall.mirror.approach_viscosity == 0.2);
  CHECK(b.artificial_viscosity == 0.05);
  CHECK(b.wall.pnd.density == fsi::emps::WallDensity::scaled);
  // The scene's preset is default; paper overrides it: the library's terms as printed, with a
  // term key on top.
  CHECK(fluid({}).wall.model == WallModel::standard);
  const auto c = fluid({"fluid.wall_model=paper", "fluid.wall_approach_viscosity=0.5"});
  CHECK(c.wall.model == WallModel::paper);
  CHECK(c.wall.mirror.approach_viscosity == 0.5);
  CHECK_FALSE(c.wall.mirror.same_side);
  CHECK(c.wall.pnd.density == fsi::emps::WallDensity::added);
  CHECK(c.wall.gap_courant == 0.0);
  CHECK(c.artificial_viscosity == 0.0);
  // A name outside the two is refused naming the key.
  const CliResult r = cli({"check", scene, "--set", "fluid.wall_model=tuned"});
  CHECK(r.status == 2);
  CHECK(r.err.find("fluid.wall_model") != std::string::npos);
}
