// The TL-SPH solid as a plug-in: its scene keys (tlsph_scene.cpp), its checks against the scene,
// its model, fields, probes and memory footprint.
#include "tlsph/tlsph_plugin.hpp"

#include "tlsph/tlsph_model.hpp"

#include <algorithm>
#include <limits>
#include <sstream>

namespace fsi::app::tlsph_plugin {

namespace {

void check(const Scene& scene, std::size_t index, Section& s, std::vector<Section>& probes) {
  const StructureBlock& block = scene.structures[index];
  const TlsphSpec& t = block.as<TlsphSpec>();
  if (!t.clamped_motion.empty()) {
    if (t.clamped.empty()) s.fail("clamped_motion", "needs clamped boxes to move");
    const auto w = std::find_if(scene.walls.begin(), scene.walls.end(),
                                [&](const WallSpec& x) { return x.name == t.clamped_motion; });
    if (w == scene.walls.end())
      s.fail("clamped_motion", "no wall named '" + t.clamped_motion + "'");
    if (!w->motion) s.fail("clamped_motion", "wall '" + t.clamped_motion + "' has no motion");
  }
  if (scene.fluid && t.interface.empty()) // a fluid and a structure are coupled
    s.fail("interface", "a structure coupled to the fluid needs the sides it is wetted on");
  for (std::size_t i = 0; i < scene.output.probes.size(); ++i)
    if (scene.output.probes[i].structure == block.name && !scene.output.probes[i].point)
      probes[i].fail("point", "required key missing (the particle nearest to it is probed)");
}

// Per particle: the FieldSet arrays (about 40 doubles and flags), the reference neighbour rows
// (64 x 4 B) and the per-pair gradients (64 x 24 B), a saved state for iterative coupling.
Footprint footprint(const Scene& scene, std::size_t index) {
  const TlsphSpec& t = scene.structures[index].as<TlsphSpec>();
  const Vec2 size = t.region.max - t.region.min;
  Footprint e;
  e.key = "dp";
  e.count = (size.x() / t.dp) * (size.y() / t.dp);
  e.bytes = e.count * (40 * 8 + 64 * 4 + 64 * 24 + 20 * 8);
  std::ostringstream counts;
  counts.precision(3);
  counts << e.count << " solid particles (region area / dp^2)";
  e.counts = counts.str();
  if (e.count > std::numeric_limits<std::uint32_t>::max())
    e.overflows.emplace_back("dp", e.counts + ": more than the 2^32 particle indices hold");
  return e;
}

} // namespace

StructurePlugin plugin() {
  StructurePlugin p;
  p.name = "tlsph";
  p.doc = "total-Lagrangian SPH solid with kernel gradient correction (RKGC paper, eqs. 6-14)";
  p.read = read_tlsph;
  p.check = check;
  p.build = [](const Scene& scene, std::size_t index) -> std::unique_ptr<StructurePart> {
    return std::make_unique<TlsphModel>(scene, scene.structures[index]);
  };
  p.validate = [](const Scene& scene, std::size_t index) { // a lattice of a few thousand: built
    const TlsphModel model(scene, scene.structures[index]);
    return StructureOutline{model.interface_mesh(), model.occupied_area()};
  };
  p.footprint = footprint;
  p.fields = {"displacement", "velocity", "von_mises", "det_F"};
  p.probe_quantities = {"displacement_x", "displacement_y"};
  return p;
}

} // namespace fsi::app::tlsph_plugin
