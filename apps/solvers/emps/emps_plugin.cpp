// The EMPS fluid as a plug-in: its scene keys (emps_scene.cpp), its model, its fields, probes and
// memory footprint.
#include "emps/emps_plugin.hpp"

#include "emps/emps_model.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace fsi::app::emps_plugin {

namespace {

std::string count(double n) {
  std::ostringstream out;
  out.precision(3);
  out << n;
  return out.str();
}

// Shoelace area of a closed polygon.
double polygon_area(const std::vector<Vec2>& p) {
  double twice = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2& a = p[i];
    const Vec2& b = p[(i + 1) % p.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * std::abs(twice);
}

// Bytes per fluid particle, array by array (fluid_emps and geometry_erp headers); `capacity` is
// the neighbour-row length of EmpsFluid.
double bytes_per_particle(double capacity) {
  const double particles = 6 * 8 + 1 + 4;          // Particles SoA: x y vx vy p pnd, surface, id
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
  Footprint e;
  for (const auto& region : f.regions)
    e.count += polygon_area(region) / (f.options.l0 * f.options.l0);
  const emps::FluidOptions o = fluid_options(scene);
  const double reach = (1.0 + o.skin) * o.re_over_l0; // as EmpsFluid sizes its rows
  const double capacity = std::ceil(2.0 * M_PI * reach * reach) + 16;
  const double h = o.r_e() * (1.0 + o.skin); // CellGrid cell size
  const Vec2 span = o.domain_max - o.domain_min;
  const double cells = (std::ceil(span.x() / h) + 3) * (std::ceil(span.y() / h) + 3);
  e.bytes = e.count * bytes_per_particle(capacity) + cells * 4;
  const bool grid_larger = 4 * cells > e.bytes / 2 && f.domain_given;
  e.key = grid_larger ? "domain" : "l0";
  e.counts =
      count(e.count) + " particles (fluid region area / l0^2) and " + count(cells) + " cells";
  // Particle ids and neighbour indices are 32-bit, cell indices int.
  if (e.count > std::numeric_limits<std::uint32_t>::max())
    e.overflows.emplace_back("l0", count(e.count) +
                                       " particles: more than the 2^32 particle indices hold");
  if (cells > std::numeric_limits<int>::max())
    e.overflows.emplace_back("l0", count(cells) + " cells over the fluid domain: more than 2^31");
  return e;
}

} // namespace

FluidPlugin plugin() {
  FluidPlugin p;
  p.name = "emps";
  p.doc = "explicit MPS with ERP polygon walls (Mitsume 2023)";
  p.read = read_fluid;
  p.check = [](const Scene&, Section&, std::vector<Section>&) {
  }; // every rule is local to the block (read_fluid)
  p.build = [](const Scene& scene, const std::vector<InterfaceMesh>& interfaces,
               const std::vector<Polygon>& solid) -> std::unique_ptr<FluidPart> {
    return std::make_unique<EmpsModel>(scene, interfaces, solid);
  };
  p.validate = [](const Scene& scene, const std::vector<InterfaceMesh>& interfaces,
                  const std::vector<Polygon>& solid) {
    erp::WallSet walls; // the interfaces as ERP walls (eqs. 47-51) check their meshes
    for (const auto& mesh : interfaces) erp::InterfaceWalls(walls, mesh, 0);
    const FluidSpec& f = scene.fluid->as<FluidSpec>();
    fill_regions(scene, f.regions, f.options.l0, solid);
  };
  p.footprint = footprint;
  p.fields = {"velocity", "pressure", "pnd", "free_surface"};
  p.probe_quantities = {"surge_front", "pressure", "mean_pressure", "mean_speed", "kinetic_energy"};
  return p;
}

} // namespace fsi::app::emps_plugin
