// Issue 6, test 3, with the real solvers: a water column resting on a clamped elastic plate
// settles to the static deflection that the FEM gives for the same plate under the hydrostatic
// load rho g H applied directly as a uniform traction on its top edge (plus its own weight).
#include "emps/emps_spec.hpp"
#include "fem/fem_model.hpp"
#include "fsi_app/coupled_model.hpp"
#include "fsi_app/scene.hpp"
#include "structure_fem/loads.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using namespace fsi;
using namespace fsi::app;
using namespace fsi::app::fem_plugin;
using fsi::app::emps_plugin::FluidSpec;

TEST_CASE("apps: water column on a clamped plate settles to the FEM deflection under rho g H",
          "[apps][coupled]") {
  const Scene scene = load_scene(FSI_TEST_DATA "/hydrostatic_plate_small.yaml", {});
  const StructureBlock& plate = scene.structures.front();
  const FluidSpec& fluid = scene.fluid->as<FluidSpec>();
  const ProbeSpec& mid_span = scene.output.probes.front();

  // Reference: the plate alone, rho g H on the top edge and gravity, solved statically.
  const double H = fluid.area.regions.front()[2].y() - fluid.area.regions.front()[0].y();
  auto alone = build_structure(scene, plate);
  const double q = fluid.options.density * -scene.gravity.y() * H; // Pa
  alone->set_external_forces(fem::edge_traction_forces(alone->mesh(), "top", Vec2(0.0, -q)));
  alone->solve_static();
  const int node = probe_node(scene, alone->mesh(), mid_span);
  const double w_fem = alone->displacement()[2 * node + 1];

  // Coupled: the fluid is damped until damping_time; the deflection is averaged after it.
  CoupledModel model(scene);
  const double dt = *scene.time.dt, t_settled = fluid.options.damping_time;
  const long steps = std::lround(scene.time.end / dt);
  double sum = 0.0;
  long samples = 0;
  for (long k = 0; k < steps; ++k) {
    model.advance(static_cast<double>(k) * dt, dt);
    if (static_cast<double>(k + 1) * dt > t_settled) sum += *model.probe(mid_span), ++samples;
  }
  const double w_coupled = sum / static_cast<double>(samples);
  INFO("coupled " << w_coupled << " m, FEM under rho g H " << w_fem << " m");
  CHECK(w_fem < -1e-4); // a deflection large enough to measure (about 0.56 mm)
  CHECK(w_coupled == Approx(w_fem).epsilon(0.05));
  CHECK(model.scheme().summary().unconverged == 0);
}
