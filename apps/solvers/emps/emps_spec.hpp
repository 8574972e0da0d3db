#pragma once
// The EMPS fluid's scene block (fluid.type: emps), as the plug-in reads it.
#include "fluid_emps/options.hpp"
#include "fsi_app/fluid_regions.hpp"
#include "fsi_app/scene.hpp"
#include "fsi_app/scene_reader.hpp"
#include "geometry_erp/stl_reader.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace fsi::app::emps_plugin {

struct FluidSpec final : SolverSpec {
  emps::FluidOptions options; ///< the keys fluid_emps declares (visit_options)
  ParticleArea area;          ///< without a domain: walls and regions with a margin of 4 r_e
};

/// An axis-aligned box [min, max], m, and the line of its block (3-D scenes).
using Box = BoxRegion;

/// The fluid block of a 3-D scene (dimension: 3): boxes of water in a tank of triangles, the
/// closed box `tank` or the surface of `tank_file`, read and checked as the scene is read.
struct FluidSpec3 final : SolverSpec {
  emps::FluidOptions3 options;                 ///< the same keys as in 2-D (visit_options)
  std::optional<Box> tank;                     ///< a closed box of 12 triangles, normals into it
  std::optional<erp::StlSurface> tank_surface; ///< tank_file's triangles, normals into the fluid
  std::string tank_path;                       ///< tank_file as resolved, for messages
  int tank_line = 0;                           ///< the line of tank or tank_file
  std::optional<MotionSpec> tank_motion;       ///< the tank's rigid motion (read_motion3)
  int tank_motion_line = 0;
  std::vector<Box> regions; ///< boxes filled at spacing l0 (l0/2 from their faces)
  std::optional<erp::StlSurface> region_surface; ///< region_file's closed surface, filled too
  std::string region_path;                       ///< region_file as resolved, for messages
  int region_line = 0;
  std::optional<Box> domain; ///< particles leaving it are removed; absent: walls and regions
  bool periodic_z = false;   ///< the fluid and the tank wrap along z over the tank's depth
  std::string periodic;      ///< with periodic_z: `FILE:LINE: fluid.periodic_z: what` (mpirun)
  std::string periodic_structures; ///< with periodic_z: the same, refusing structures
};

/// Reads the keys of the fluid block (type excepted) into a FluidSpec (in a 3-D scene, a
/// FluidSpec3 through read_fluid3).
std::shared_ptr<const SolverSpec> read_fluid(Section& s);

/// The 3-D block's own keys (tank or tank_file, regions and domain as boxes); what 3-D does not
/// have yet is refused by name (emps_scene3.cpp).
std::shared_ptr<const SolverSpec> read_fluid3(Section& s);
/// The keys tank and tank_file: documented in either dimension, read in 3-D.
void read_tank(Section& s, FluidSpec3& f);
/// The key region_file, a fluid region as a closed surface (STL or .msh; an open one is refused):
/// documented in either dimension, read in 3-D.
void read_region_file(Section& s, FluidSpec3& f);

} // namespace fsi::app::emps_plugin
