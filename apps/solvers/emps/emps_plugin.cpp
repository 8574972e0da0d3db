// The EMPS fluid as a plug-in: its scene keys (emps_scene.cpp, 3-D: emps_scene3.cpp), its model
// (3-D: EmpsModel3, picked by scene.dimension; coupled in 3-D through build3), its fields,
// probes and memory footprint.
#include "emps/emps_plugin.hpp"

#include "emps/emps_model.hpp"
#include "emps/emps_model3.hpp"
#include "fsi_app/fluid_regions.hpp"

#include <cmath>

namespace fsi::app::emps_plugin {

namespace {

// Bytes per fluid particle: the registered particle arrays (emps::Particles), then the solver's
// other arrays one by one (fluid_emps and geometry_erp headers); `capacity` is the neighbour-row
// length of EmpsFluid.
double bytes_per_particle(double capacity) {
  const auto particles = static_cast<double>(emps::Particles().fields.bytes_per_particle());
  const double saved_state = particles;            // EmpsFluid::State for coupling iterations
  const double lattice = 16;                       // fill_lattice positions
  const double neighbours = capacity * 4 + 4 + 16; // index_ rows, count_, x_build_ y_build_
  const double cell_grid = 4 + 4;                  // cell_, order_
  const double wall_hits = 4 + 16 + 64 + 1 + 4 + 16 + 48; // erp::WallHits
  const double wall_forces = 8 + 16 + 64;                 // WallForces
  const double work = 16 + 32 + 1;                        // scratch_, visc_wall_ 2x, keep_
  const double output = 16 + 16 + 8;                      // EmpsModel frame buffers
  return particles + saved_state + lattice + neighbours + cell_grid + wall_hits + wall_forces +
         work + output;
}

Footprint footprint(const Scene& scene) {
  if (scene.dimension == 3) return footprint3(scene);
  const FluidSpec& f = scene.fluid->as<FluidSpec>();
  const emps::FluidOptions o = fluid_options(scene);
  const double reach = (1.0 + o.skin) * o.re_over_l0; // as EmpsFluid sizes its rows
  const double capacity = std::ceil(2.0 * M_PI * reach * reach) + 16;
  return particle_footprint(f.area, o.l0, bytes_per_particle(capacity),
                            {o.domain_min, o.domain_max}, {o.r_e() * (1.0 + o.skin), 3, 4});
}

// Against the scene: the regions and the fluid probes lie in the domain (given or derived).
void check(const Scene& scene, Section& s, std::vector<Section>& probes) {
  if (scene.dimension == 3) {
    for (std::size_t i = 0; i < scene.output.probes.size(); ++i)
      if (scene.output.probes[i].quantity.starts_with("wall_force"))
        probes[i].fail("quantity",
                       scene.output.probes[i].quantity + " is a probe of 2-D scenes for type emps");
    return check3(scene, s, probes);
  }
  const emps::FluidOptions o = fluid_options(scene);
  check_in_domain(scene, s, probes, scene.fluid->as<FluidSpec>().area,
                  {o.domain_min, o.domain_max});
  for (std::size_t i = 0; i < scene.output.probes.size(); ++i) {
    const std::string& q = scene.output.probes[i].quantity;
    if (q == "particles" || q == "wall_gap" || q == "water_height" || q == "wall_pressure")
      probes[i].fail("quantity", q + " is a probe of 3-D scenes (dimension: 3) for type emps");
  }
}

// The interfaces as ERP walls (eqs. 47-51) check their meshes; the regions are filled.
void validate(const Scene& scene, const std::vector<InterfaceMesh>& interfaces,
              const std::vector<Polygon>& solid) {
  if (scene.dimension == 3) return validate3(scene);
  erp::WallSet walls;
  for (const auto& mesh : interfaces) erp::InterfaceWalls(walls, mesh, 0);
  const FluidSpec& f = scene.fluid->as<FluidSpec>();
  fill_regions(scene, f.area.regions, f.options.l0, solid);
}

} // namespace

FluidPlugin plugin() {
  return {"emps",
          "explicit MPS with ERP polygon walls (Mitsume 2023)",
          read_fluid,
          check,
          [](const Scene& scene, const std::vector<InterfaceMesh>& interfaces,
             const std::vector<Polygon>& solid, const Ranks& ranks) -> std::unique_ptr<FluidPart> {
            if (scene.dimension == 3)
              return std::make_unique<EmpsModel3>(scene, std::vector<InterfaceMesh3>{}, ranks);
            return make_fluid_part<EmpsModel>(scene, interfaces, solid, ranks);
          },
          validate,
          footprint,
          {"velocity", "pressure", "pnd", "free_surface"},
          {"surge_front", "pressure", "mean_pressure", "mean_speed", "kinetic_energy", "particles",
           "wall_gap", "water_height", "wall_pressure", "wall_force_x", "wall_force_y"},
          [](const Scene& scene, const std::vector<InterfaceMesh3>& interfaces,
             const Ranks& ranks) -> std::unique_ptr<FluidPart> {
            return std::make_unique<EmpsModel3>(scene, interfaces, ranks);
          },
          [](const Scene& scene, const std::vector<InterfaceMesh3>& interfaces) {
            validate3(scene, interfaces);
          }};
}

} // namespace fsi::app::emps_plugin
