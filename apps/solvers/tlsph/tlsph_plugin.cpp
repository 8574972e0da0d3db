// The TL-SPH solid as a plug-in: its scene keys (tlsph_scene.cpp), its checks against the scene,
// its model, fields, probes and memory footprint.
#include "tlsph/tlsph_plugin.hpp"

#include "fsi/core/format.hpp"
#include "fsi_app/fluid_regions.hpp"
#include "fsi_app/wall_motion.hpp"
#include "structure_geometry.hpp"
#include "tlsph/tlsph_model.hpp"
#include "tlsph/tlsph_model3.hpp"

#include <algorithm>
#include <limits>
#include <sstream>

namespace fsi::app::tlsph_plugin {

namespace {

void check(const Scene& scene, std::size_t index, Section& s, std::vector<Section>& probes) {
  const StructureBlock& block = scene.structures[index];
  const TlsphSpec& t = block.as<TlsphSpec>();
  const bool three_d = scene.dimension == 3;
  if (!three_d)
    check_clamped_motion(scene, t.clamped_motion, !t.clamped.empty(), "clamped boxes", s);
  if (scene.fluid && t.options.interface_tags.empty()) // a fluid and a structure are coupled
    s.fail("interface", "a structure coupled to the fluid needs the sides it is wetted on");
  for (std::size_t i = 0; i < scene.output.probes.size(); ++i) {
    const ProbeSpec& p = scene.output.probes[i];
    if (p.structure != block.name) continue;
    if (!(three_d ? p.point3.has_value() : p.point.has_value()))
      probes[i].fail("point", "required key missing (the particle nearest to it, or the kernel "
                              "interpolation at it, is probed)");
    if (!three_d) check_frame_probe(p, t.clamped_motion, probes[i]);
  }
}

// Per particle: the FieldSet arrays (about 40 doubles and flags), the reference neighbour rows
// (64 x 4 B) and the per-pair gradients (64 x 24 B), a saved state for iterative coupling.
// 3-D: about 60 doubles, and 56 pairs a row (h = 1.15 dp) of 168 B each (neighbour and reverse
// index, grad0 W V, |dW| / r V, g~, the 9-term fit operator, k and the residual).
Footprint footprint(const Scene& scene, std::size_t index) {
  const TlsphSpec& t = scene.structures[index].as<TlsphSpec>();
  Footprint e;
  e.key = "dp";
  const double dp = t.options.dp;
  if (scene.dimension == 3) {
    e.count = (t.box.max - t.box.min).prod() / (dp * dp * dp);
    e.bytes = e.count * (60 * 8 + 56 * 168);
    e.counts = significant(e.count, 3) + " solid particles (region volume / dp^3)";
  } else {
    e.count = polygon_area(t.outline) / (dp * dp);
    e.bytes = e.count * (40 * 8 + 64 * 4 + 64 * 24 + 20 * 8);
    e.counts = significant(e.count, 3) + " solid particles (region area / dp^2)";
  }
  if (e.count > std::numeric_limits<std::uint32_t>::max())
    e.overflows.emplace_back("dp", e.counts + ": more than the 2^32 particle indices hold");
  return e;
}

// A lattice of a few thousand particles: built.
StructureOutline validate(const Scene& scene, std::size_t index) {
  if (scene.dimension == 3) { // the 3-D interface (no 2-D area)
    const TlsphModel3 model(scene, scene.structures[index]);
    StructureOutline o;
    o.interface3 = model.interface_mesh3();
    return o;
  }
  const TlsphModel model(scene, scene.structures[index]);
  return {model.interface_mesh(), model.occupied_area()};
}

std::unique_ptr<StructurePart> build(const Scene& scene, std::size_t index) {
  if (scene.dimension == 3) return make_structure_part<TlsphModel3>(scene, index);
  return make_structure_part<TlsphModel>(scene, index);
}

} // namespace

StructurePlugin plugin() {
  return {"tlsph",
          "total-Lagrangian SPH solid with kernel gradient correction (RKGC paper, eqs. 6-14)",
          read_tlsph,
          check,
          build,
          validate,
          footprint,
          {"displacement", "velocity", "von_mises", "det_F"},
          {"displacement_x", "displacement_y", "displacement_z", "displacement_x_tank",
           "displacement_y_tank"},
          tlsph_from_fem};
}

} // namespace fsi::app::tlsph_plugin
