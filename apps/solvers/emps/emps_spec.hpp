#pragma once
// The EMPS fluid's scene block (fluid.type: emps), as the plug-in reads it.
#include "fluid_emps/options.hpp"
#include "fsi_app/fluid_regions.hpp"
#include "fsi_app/scene.hpp"
#include "fsi_app/scene_reader.hpp"

#include <memory>
#include <vector>

namespace fsi::app::emps_plugin {

struct FluidSpec final : SolverSpec {
  emps::FluidOptions options; ///< the keys fluid_emps declares (visit_options)
  ParticleArea area;          ///< without a domain: walls and regions with a margin of 4 r_e
};

/// Reads the keys of the fluid block (type excepted) into a FluidSpec.
std::shared_ptr<const SolverSpec> read_fluid(Section& s);

} // namespace fsi::app::emps_plugin
