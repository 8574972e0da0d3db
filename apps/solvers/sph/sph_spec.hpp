#pragma once
// The SPH fluid's scene block (fluid.type: sph), as the plug-in reads it. Keys that mean what the
// EMPS fluid's keys mean carry the same names (density, viscosity, l0, sound_speed, regions,
// domain, damping_time), so one scene runs with either fluid by `--set fluid.type=...`.
#include "fluid_sph/options.hpp"
#include "fsi_app/fluid_regions.hpp"
#include "fsi_app/scene.hpp"
#include "fsi_app/scene_reader.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fsi::app::sph_plugin {

struct SphSpec final : SolverSpec {
  sph::SphOptions options;             ///< the keys fluid_sph declares (visit_options)
  int interface_layers = 4;            ///< rows of boundary points behind a structure's interface
  double interface_spacing = 1.0;      ///< their lattice spacing, in l0
  bool interface_acceleration = false; ///< the interface's mean acceleration in eq. 16
  ParticleArea area;    ///< without a domain: walls and regions with a margin of 8 l0
  std::string periodic; ///< with inflow: `FILE:LINE: fluid.inflow: what`, refusing mpirun
};

/// An axis-aligned box [min, max], m, and the line of its block.
using Box3 = BoxRegion;

/// The fluid block of a 3-D scene (dimension: 3): boxes of water in an open box tank (y up).
struct SphSpec3 final : SolverSpec {
  sph::SphOptions3 options;   ///< the same keys as in 2-D (visit_options)
  std::optional<Box3> tank;   ///< the tank's inside, open at max.y; absent: no walls
  std::vector<Box3> regions;  ///< boxes filled at spacing l0 (l0/2 from their faces)
  std::optional<Box3> domain; ///< particles leaving it are removed; absent: tank and regions
  bool periodic_z = false;    ///< the fluid and the tank wrap along z over the tank's depth
  std::string periodic;       ///< with periodic_z: `FILE:LINE: fluid.periodic_z: what` (mpirun)
};

/// Reads the keys of the fluid block (type excepted) into an SphSpec (in a 3-D scene, an
/// SphSpec3). A key of another fluid type is an error naming it and that type.
std::shared_ptr<const SolverSpec> read_sph(Section& s);

/// The 3-D block's own keys (tank, regions and domain as boxes); the 2-D-only keys (inflow,
/// interface_*) are refused by name. sph_scene3.cpp.
std::shared_ptr<const SolverSpec> read_sph3(Section& s);

/// The `tank` block: documented in either dimension, read in 3-D.
std::optional<Box3> read_tank(Section& s);

} // namespace fsi::app::sph_plugin
