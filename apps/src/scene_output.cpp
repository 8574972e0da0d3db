// The output and checkpoint blocks of a scene file: fields, probes, frames, checkpoints.
#include "scene_blocks.hpp"

#include "fsi/core/format.hpp"
#include "fsi_app/solver_plugin.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace fsi::app {

namespace {

// Field names and probe quantities are the plug-ins' (each declares its own); a quantity of a
// structure plug-in needs the probe's `structure` key.
template <class Plugins>
void add_unique(std::vector<std::string>& out, const Plugins& plugins,
                std::vector<std::string> Plugins::value_type::*list) {
  for (const auto& p : plugins)
    for (const auto& name : p.*list)
      if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
}

std::vector<std::string> field_names() {
  std::vector<std::string> out;
  add_unique(out, fluid_plugins(), &FluidPlugin::fields);
  add_unique(out, structure_plugins(), &StructurePlugin::fields);
  return out;
}

std::vector<std::string> structure_quantities() {
  std::vector<std::string> out;
  add_unique(out, structure_plugins(), &StructurePlugin::probe_quantities);
  return out;
}

std::vector<std::string> probe_quantities() {
  std::vector<std::string> out;
  add_unique(out, fluid_plugins(), &FluidPlugin::probe_quantities);
  add_unique(out, structure_plugins(), &StructurePlugin::probe_quantities);
  return out;
}
const std::vector<std::string> kForceParts = {"total", "pressure", "repulsive", "viscous"};

ProbeSpec read_probe(Section s) {
  ProbeSpec p;
  p.line = s.line();
  p.key = s.path();
  p.name = s.text("name", "column name in probes.csv (letters, digits, _)");
  p.quantity =
      s.choice("quantity", probe_quantities(), "",
               "what is sampled: a node's displacement; a node's displacement in the "
               "frame of the wall its structure is clamped to (clamped_motion: the "
               "rigid motion undone, x and y along the tank's axes); the surge front "
               "(largest x of particles with pnd >= n0/2, i.e. not spray); the pressure "
               "at a point (MPS-weighted mean within r_e); mean_pressure, the plain mean "
               "over the particles inside the box min..max; mean_speed and "
               "kinetic_energy (J per m of depth; 3-D: J) of all particles; velocity_x|y|z, "
               "the kernel-weighted velocity at a point (type sph); wall_force_x|y, "
               "the fluid's force on the coupled structure (on all walls without one), "
               "N/m, of the last step; (3-D, type emps) particles, their count, wall_gap, "
               "the smallest distance of a particle centre to its nearest wall, m, and "
               "water_height, a wave gauge at point: the top (centre + l0/2) of the highest "
               "particle with pnd >= n0/2 (pnd_fraction) within l0 of the vertical through "
               "point, above it, m, and wall_pressure, the pressure the wall sees at point (on a "
               "wall triangle): the particles' wall force on the point's plane per area, "
               "Wendland-weighted within radius, Pa");
  p.structure = s.text("structure", "", "structure name, for displacement probes");
  p.node = s.optional_integer("node", Range::non_negative(), "FE node index (or give point)");
  const std::string point_doc = "reference position of the FE node or the TL-SPH point, or the "
                                "fluid point, m (dimension 3: [x, y, z])";
  if (s.context().dimension == 3 && !s.context().documenting())
    p.point3 = s.optional_vec3("point", point_doc);
  else
    p.point = s.optional_vec2("point", point_doc);
  const std::string min_doc = "mean_pressure: lower-left corner of the box, m ([x, y, z] in 3-D)";
  const std::string max_doc = "mean_pressure: upper-right corner of the box, m ([x, y, z] in 3-D)";
  if (s.context().dimension == 3 && !s.context().documenting()) {
    p.box3_min = s.optional_vec3("min", min_doc);
    p.box3_max = s.optional_vec3("max", max_doc);
  } else {
    p.box_min = s.optional_vec2("min", min_doc);
    p.box_max = s.optional_vec2("max", max_doc);
  }
  p.part = s.choice("part", kForceParts, "total",
                    "wall_force: the wall term carried: pressure (mirror, eqs. 25-26), repulsive "
                    "(eq. 27 and wall damping), viscous (eq. 24) or their total");
  p.interpolate = s.boolean("interpolate", false,
                            "(type tlsph) displacement at point by the kernel interpolation of "
                            "the particles' displacements (linear correction, reference "
                            "configuration); false: the particle nearest to point (type fem: "
                            "the node at point either way, the FE interpolation there)");
  p.radius = s.optional_real("radius", Range::positive(),
                             "wall_pressure: radius of the wall patch averaged over, m "
                             "(absent: the fluid's r_e)");
  const auto pnd_fraction =
      s.optional_real("pnd_fraction", Range::left_open(0.0, 1.0),
                      "water_height: a particle counts when its pnd >= pnd_fraction n0 "
                      "(absent: 0.5, the bulk, not the spray nor a front's thin tip)");
  p.pnd_fraction = pnd_fraction.value_or(0.5);
  if (!s.context().documenting()) {
    const bool ok_name = !p.name.empty() && std::all_of(p.name.begin(), p.name.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
    if (!ok_name) s.fail("name", "'" + p.name + "' is not a valid column name");
    if (p.name == "time") // probes.csv's first column, and the Python result's time key
      s.fail("name",
             "'time' is reserved (the first column of probes.csv); name the probe otherwise");
    const auto on = structure_quantities();
    const bool on_structure = std::find(on.begin(), on.end(), p.quantity) != on.end();
    if (on_structure && p.structure.empty()) s.fail("structure", "required key missing");
    if (p.interpolate && !on_structure)
      s.fail("interpolate", "only a structure's displacement probes interpolate");
    if ((p.quantity == "displacement_z" || p.quantity == "velocity_z") &&
        s.context().dimension != 3)
      s.fail("quantity", p.quantity + " needs a 3-D scene (dimension: 3)");
    const bool at_point = p.quantity == "pressure" || p.quantity == "water_height" ||
                          p.quantity == "wall_pressure" || p.quantity.starts_with("velocity_");
    if (p.radius && p.quantity != "wall_pressure")
      s.fail("radius", "only a wall_pressure probe has a radius");
    if (pnd_fraction && p.quantity != "water_height")
      s.fail("pnd_fraction", "only a water_height probe has a pnd_fraction");
    if (at_point && !p.point && !p.point3) s.fail("point", "required key missing");
    if (p.quantity == "mean_pressure") {
      if (!p.box_min && !p.box3_min) s.fail("min", "required key missing");
      if (!p.box_max && !p.box3_max) s.fail("max", "required key missing");
      if (p.box3_min && !((*p.box3_max - *p.box3_min).minCoeff() > 0.0))
        s.fail("max", "must lie above min on every axis");
      if (p.box_min && (p.box_max->x() <= p.box_min->x() || p.box_max->y() <= p.box_min->y()))
        s.fail("max", "must lie above and right of min");
    }
  }
  s.finish();
  return p;
}

/// The most frames a run may write (docs/reliability.md, issue 41).
constexpr double kMaxFrames = 1e5;

} // namespace

OutputSpec read_output(Section s, double end_time, std::vector<Section>& probe_sections) {
  OutputSpec o;
  o.interval = s.real("interval", Range::positive(), "simulated time between frames, s");
  const std::vector<std::string> known = field_names();
  o.fields = s.names("fields", known,
                     "fields written to fields.h5 (particle positions and mesh geometry always)");
  for (const auto& f : o.fields)
    if (std::find(known.begin(), known.end(), f) == known.end()) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      s.fail("fields", "unknown field '" + f + "' (known: " + list + ")");
    }
  std::set<std::string> names;
  probe_sections = s.list("probes", "sampled every frame into probes.csv");
  for (auto& probe : probe_sections) {
    o.probes.push_back(read_probe(probe));
    if (!s.context().documenting() && !names.insert(o.probes.back().name).second)
      probe.fail("name", "duplicate probe name '" + o.probes.back().name + "'");
  }
  if (!s.context().documenting() && o.interval > end_time)
    s.fail("interval", "is larger than time.end");
  // Issue 41: 1e-12 s with Courant stepping wrote 2,029 frames (42 MB) in 25 s towards 1e12;
  // what cannot finish is refused before step 0 (each frame is also at least one step).
  if (!s.context().documenting() && !(end_time / o.interval <= kMaxFrames))
    s.fail("interval", "time.end / output.interval = " + significant(end_time / o.interval, 3) +
                           " frames; a run writes at most " + significant(kMaxFrames, 3) +
                           " (give a larger interval)");
  s.finish();
  return o;
}

CheckpointSpec read_checkpoint_spec(Section s) {
  CheckpointSpec c;
  c.line = s.line();
  if (auto n = s.optional_integer("interval_steps", Range::closed(1, 1e9),
                                  "write a checkpoint after every this many steps"))
    c.interval_steps = *n;
  c.interval_minutes = s.optional_real("interval_minutes", Range::positive(),
                                       "write a checkpoint after this much wall time, minutes");
  c.keep = s.integer("keep", 2, Range::closed(1, 1000), "newest checkpoints kept on disk");
  s.finish();
  if (!s.context().documenting() && !c.interval_steps && !c.interval_minutes)
    s.fail("", "give interval_steps, interval_minutes or both");
  return c;
}

} // namespace fsi::app
