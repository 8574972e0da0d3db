// The SPH fluid as a plug-in: its scene keys (sph_scene.cpp), its checks against the scene, its
// model, fields, probes and memory footprint.
#include "sph/sph_plugin.hpp"

#include "sph/sph_model.hpp"

#include "fsi/core/error.hpp"
#include "fsi_app/fluid_regions.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace fsi::app::sph_plugin {

namespace {

std::string count(double n) {
  std::ostringstream out;
  out.precision(3);
  out << n;
  return out.str();
}

bool inside(const sph::SphOptions& o, const Vec2& p) {
  return p.x() >= o.domain_min.x() && p.x() <= o.domain_max.x() && p.y() >= o.domain_min.y() &&
         p.y() <= o.domain_max.y();
}

// Against the scene: the regions and pressure probes lie in the domain (given or derived), a
// wall_force probe gives the total only.
void check(const Scene& scene, Section& s, std::vector<Section>& probes) {
  const SphSpec& f = scene.fluid->as<SphSpec>();
  const sph::SphOptions o = sph_options(scene);
  for (std::size_t i = 0; i < f.regions.size(); ++i)
    for (const Vec2& p : f.regions[i])
      if (!inside(o, p))
        s.fail(f.domain_max.x() > f.domain_min.x() ? "domain" : "regions",
               "fluid region " + std::to_string(i) + " reaches outside the domain");
  for (std::size_t i = 0; i < scene.output.probes.size(); ++i) {
    const ProbeSpec& p = scene.output.probes[i];
    if (p.quantity == "pressure" && p.point && !inside(o, *p.point))
      probes[i].fail("point", "the pressure point is outside the fluid domain");
    if ((p.quantity == "wall_force_x" || p.quantity == "wall_force_y") && p.part != "total")
      probes[i].fail("part", "fluid type sph gives the total wall force only (part: total)");
  }
  try {
    o.validate();
  } catch (const InputError& e) {
    s.fail("", e.what());
  }
}

// Shoelace area of a closed polygon.
double polygon_area(const std::vector<Vec2>& p) {
  double twice = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    twice += p[i].x() * p[(i + 1) % p.size()].y() - p[(i + 1) % p.size()].x() * p[i].y();
  return 0.5 * std::abs(twice);
}

// Per fluid particle: 17 registered reals and an index (about 140 B) held twice (the state saved
// for iterative coupling), about 21 pairs of 36 B (index, e_ij, dW_ij, r_ij), the cell grid's
// 8 B, sort scratch 8 B and output buffers 32 B; the walls are not counted (a few % more).
Footprint footprint(const Scene& scene) {
  const SphSpec& f = scene.fluid->as<SphSpec>();
  Footprint e;
  for (const auto& region : f.regions) e.count += polygon_area(region) / (f.l0 * f.l0);
  const sph::SphOptions o = sph_options(scene);
  const double cell = 2.0 * o.h();
  const Vec2 span = o.domain_max - o.domain_min;
  const double cells = (std::ceil(span.x() / cell) + 2) * (std::ceil(span.y() / cell) + 2);
  e.bytes = e.count * (2 * 140 + 21 * 36 + 8 + 8 + 32) + 2 * cells * 4;
  e.key = 4 * cells > e.bytes / 2 && f.domain_max.x() > f.domain_min.x() ? "domain" : "l0";
  e.counts =
      count(e.count) + " particles (fluid region area / l0^2) and " + count(cells) + " cells";
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
  p.name = "sph";
  p.doc = "weakly compressible Riemann-SPH with RKGC, dual-criteria steps (RKGC paper)";
  p.read = read_sph;
  p.check = check;
  p.build = [](const Scene& scene, const std::vector<InterfaceMesh>& interfaces,
               const std::vector<Polygon>& solid) -> std::unique_ptr<FluidPart> {
    return std::make_unique<SphModel>(scene, interfaces, solid);
  };
  p.validate = [](const Scene& scene, const std::vector<InterfaceMesh>& interfaces,
                  const std::vector<Polygon>& solid) {
    const SphSpec& f = scene.fluid->as<SphSpec>();
    try {
      sph_options(scene).validate();
      for (const auto& mesh : interfaces) sph::InterfaceBoundary(mesh, f.l0, f.interface_layers);
    } catch (const InputError& e) {
      fail_at(scene, scene.fluid->line, "fluid", e.what());
    }
    fill_regions(scene, f.regions, f.l0, solid);
  };
  p.footprint = footprint;
  p.fields = {"velocity", "pressure", "density", "wkgc_indicator"};
  p.probe_quantities = {"surge_front", "pressure",     "kinetic_energy",
                        "mean_speed",  "wall_force_x", "wall_force_y"};
  return p;
}

} // namespace fsi::app::sph_plugin
