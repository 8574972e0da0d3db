// The SPH fluid as a plug-in: its scene keys (sph_scene.cpp), its checks against the scene, its
// model, fields, probes and memory footprint.
#include "sph/sph_plugin.hpp"

#include "sph/sph_model.hpp"
#include "sph/sph_model3.hpp"

#include "fsi/core/error.hpp"
#include "fsi_app/fluid_regions.hpp"

namespace fsi::app::sph_plugin {

namespace {

// Against the scene: the regions and the fluid probes lie in the domain (given or derived), a
// wall_force probe gives the total only.
void check(const Scene& scene, Section& s, std::vector<Section>& probes) {
  if (scene.dimension == 3) return check3(scene, s, probes);
  const SphSpec& f = scene.fluid->as<SphSpec>();
  const sph::SphOptions o = sph_options(scene);
  check_in_domain(scene, s, probes, f.area, {o.domain_min, o.domain_max});
  for (std::size_t i = 0; i < scene.output.probes.size(); ++i) {
    const ProbeSpec& p = scene.output.probes[i];
    if ((p.quantity == "wall_force_x" || p.quantity == "wall_force_y") && p.part != "total")
      probes[i].fail("part", "fluid type sph gives the total wall force only (part: total)");
  }
  try {
    o.validate();
  } catch (const InputError& e) {
    s.fail("", e.what());
  }
}

// Per fluid particle: the registered arrays (sph::FluidParticles) held twice (the state saved
// for iterative coupling), about 21 pairs of 36 B (index, e_ij, dW_ij, r_ij), the cell grid's
// 8 B, sort scratch 8 B and output buffers 32 B; the walls are not counted (a few % more).
Footprint footprint(const Scene& scene) {
  if (scene.dimension == 3) return footprint3(scene);
  const SphSpec& f = scene.fluid->as<SphSpec>();
  const sph::SphOptions o = sph_options(scene);
  const auto particles = static_cast<double>(sph::FluidParticles().fields.bytes_per_particle());
  return particle_footprint(f.area, f.options.dp, 2 * particles + 21 * 36 + 8 + 8 + 32,
                            {o.domain_min, o.domain_max}, {2.0 * o.h(), 2, 8});
}

// The options the fluid accepts, the interfaces' boundary points, the regions filled.
void validate(const Scene& scene, const std::vector<InterfaceMesh>& interfaces,
              const std::vector<Polygon>& solid) {
  if (scene.dimension == 3) return validate3(scene);
  const SphSpec& f = scene.fluid->as<SphSpec>();
  try {
    sph_options(scene).validate();
    for (const auto& mesh : interfaces)
      sph::InterfaceBoundary(mesh, f.options.dp, f.interface_layers,
                             f.interface_spacing * f.options.dp);
  } catch (const InputError& e) {
    fail_at(scene, scene.fluid->line, "fluid", e.what());
  }
  fill_regions(scene, f.area.regions, f.options.dp, solid);
}

} // namespace

FluidPlugin plugin() {
  return {"sph",
          "weakly compressible Riemann-SPH with RKGC, dual-criteria steps (RKGC paper)",
          read_sph,
          check,
          [](const Scene& scene, const std::vector<InterfaceMesh>& interfaces,
             const std::vector<Polygon>& solid, const Ranks& ranks) -> std::unique_ptr<FluidPart> {
            if (scene.dimension == 3)
              return std::make_unique<SphModel3>(scene, std::vector<InterfaceMesh3>{}, ranks);
            return make_fluid_part<SphModel>(scene, interfaces, solid, ranks);
          },
          validate,
          footprint,
          {"velocity", "pressure", "density", "wkgc_indicator"},
          {"surge_front", "pressure", "velocity_x", "velocity_y", "velocity_z", "kinetic_energy",
           "mean_speed", "wall_force_x", "wall_force_y"},
          [](const Scene& scene, const std::vector<InterfaceMesh3>& interfaces,
             const Ranks& ranks) -> std::unique_ptr<FluidPart> {
            return std::make_unique<SphModel3>(scene, interfaces, ranks);
          },
          [](const Scene& scene, const std::vector<InterfaceMesh3>& interfaces) {
            validate3(scene, interfaces);
          }};
}

} // namespace fsi::app::sph_plugin
