#pragma once
// The SPH fluid's scene block (fluid.type: sph), as the plug-in reads it. Keys that mean what the
// EMPS fluid's keys mean carry the same names (density, viscosity, l0, sound_speed, regions,
// domain, damping_time), so one scene runs with either fluid by `--set fluid.type=...`.
#include "fluid_sph/options.hpp"
#include "fsi_app/fluid_regions.hpp"
#include "fsi_app/scene.hpp"
#include "fsi_app/scene_reader.hpp"

#include <memory>
#include <string>
#include <vector>

namespace fsi::app::sph_plugin {

struct SphSpec final : SolverSpec {
  sph::SphOptions options;             ///< the keys fluid_sph declares (visit_options)
  int interface_layers = 4;            ///< rows of boundary points behind a structure's interface
  double interface_spacing = 1.0;      ///< their lattice spacing, in l0
  bool interface_acceleration = false; ///< the interface's mean acceleration in eq. 16
  ParticleArea area; ///< without a domain: walls and regions with a margin of 8 l0
};

/// Reads the keys of the fluid block (type excepted) into an SphSpec. A key of another fluid
/// type is an error naming it and that type.
std::shared_ptr<const SolverSpec> read_sph(Section& s);

} // namespace fsi::app::sph_plugin
