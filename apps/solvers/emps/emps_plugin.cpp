// The EMPS fluid as a plug-in: its scene keys (emps_scene.cpp), its model, its fields, probes and
// memory footprint.
#include "emps/emps_plugin.hpp"

#include "emps/emps_model.hpp"
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
  const FluidSpec& f = scene.fluid->as<FluidSpec>();
  const emps::FluidOptions o = fluid_options(scene);
  const double reach = (1.0 + o.skin) * o.re_over_l0; // as EmpsFluid sizes its rows
  const double capacity = std::ceil(2.0 * M_PI * reach * reach) + 16;
  return particle_footprint(f.area, o.l0, bytes_per_particle(capacity),
                            {o.domain_min, o.domain_max}, {o.r_e() * (1.0 + o.skin), 3, 4});
}

// Against the scene: the regions and the fluid probes lie in the domain (given or derived).
void check(const Scene& scene, Section& s, std::vector<Section>& probes) {
  const emps::FluidOptions o = fluid_options(scene);
  check_in_domain(scene, s, probes, scene.fluid->as<FluidSpec>().area,
                  {o.domain_min, o.domain_max});
}

// The interfaces as ERP walls (eqs. 47-51) check their meshes; the regions are filled.
void validate(const Scene& scene, const std::vector<InterfaceMesh>& interfaces,
              const std::vector<Polygon>& solid) {
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
          make_fluid_part<EmpsModel>,
          validate,
          footprint,
          {"velocity", "pressure", "pnd", "free_surface"},
          {"surge_front", "pressure", "mean_pressure", "mean_speed", "kinetic_energy"}};
}

} // namespace fsi::app::emps_plugin
