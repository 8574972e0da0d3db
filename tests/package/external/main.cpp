// The installed fsi package from another project: a cantilever under a tip load through
// fsi::structure_fem against Timoshenko beam theory, then a scene run through fsi::app.
//   cantilever_user SCENE OUT   (SCENE: data/scenes/cantilever.yaml)
#include "fsi/core/error.hpp"
#include "fsi_app/run.hpp"
#include "fsi_app/scene.hpp"
#include "structure_fem/loads.hpp"
#include "structure_fem/rectangle_mesher.hpp"
#include "structure_fem/structure.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace fem = fsi::fem;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: cantilever_user SCENE OUT\n");
    return 2;
  }
  // 1 m x 0.1 m steel beam (plane strain), clamped left, total shear P on the right end.
  const double L = 1.0, h = 0.1, E = 2.1e11, nu = 0.3, P = 1.0e4;
  fem::RectangleMeshOptions m;
  m.width = L, m.height = h, m.elements_x = 40, m.elements_y = 4;
  fem::StructureOptions o;
  o.material.youngs_modulus = E;
  o.material.poisson_ratio = nu;
  o.material.density = 7800.0;
  o.material.plane = fem::PlaneModel::plane_strain;
  o.clamped = {{"left", true, true, {}}};
  fem::Structure beam(fem::make_rectangle_mesh(m), o);
  beam.set_external_forces(fem::edge_traction_forces(beam.mesh(), "right", {0.0, -P / h}));
  beam.solve_static();
  int tip = -1;
  for (std::size_t k = 0; k < beam.mesh().num_nodes(); ++k)
    if ((beam.mesh().X[k] - fsi::Vec2(L, 0.5 * h)).norm() < 1e-9) tip = static_cast<int>(k);
  const double fem_tip = -beam.displacement()[2 * tip + 1];
  // Timoshenko: P L^3 / (3 E' I) + P L / (kappa G A), E' = E / (1 - nu^2), kappa = 5/6.
  const double I = h * h * h / 12.0, G = E / (2.0 * (1.0 + nu));
  const double theory =
      P * L * L * L / (3.0 * E / (1.0 - nu * nu) * I) + P * L / (5.0 / 6.0 * G * h);
  const double error = std::abs(fem_tip - theory) / theory;
  std::printf("tip deflection: FEM %.6e m, Timoshenko %.6e m, relative difference %.3e\n", fem_tip,
              theory, error);

  // The cantilever scene for 50 steps, in this process.
  std::ostringstream log;
  const fsi::app::Scene scene = fsi::app::load_scene(argv[1], {"time.end=0.05"});
  auto models = fsi::app::build_models(scene);
  const fsi::app::RunResult run = fsi::app::run_scene(scene, models, {argv[2], false, &log, {}});
  std::printf("scene %s: %ld steps to t = %g s\n", scene.name.c_str(), run.step, run.time);
  return error < 0.01 && run.step == 50 && run.time == 0.05 ? 0 : 1;
}
