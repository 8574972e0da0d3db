#pragma once
// The readers of a scene file's blocks, which read_scene (scene.cpp) puts together: one file
// each for the output, motions and walls, coupling, the solver blocks and the checks across
// blocks; every key is declared in them, once.
#include "fsi_app/scene.hpp"
#include "fsi_app/scene_reader.hpp"

#include <optional>
#include <string>
#include <vector>

namespace fsi::app {

/// The output block, its probes' sections into probe_sections (scene_output.cpp).
OutputSpec read_output(Section s, double end_time, std::vector<Section>& probe_sections);
/// The checkpoint block (scene_output.cpp).
CheckpointSpec read_checkpoint_spec(Section s);
/// A 2-D wall with its motion, if any (scene_motion.cpp).
WallSpec read_wall(Section s);
/// The coupling block, a replayed file checked against `time` (scene_coupling.cpp).
CouplingSpec read_coupling(Section s, const TimeSpec& time);
/// A fluid or structure block: its type's plug-in reads it, other types' blocks are checked and
/// set aside (scene_solvers.cpp; Plugin FluidPlugin with FluidBlock, StructurePlugin with
/// StructureBlock).
template <class Plugin, class Block>
void read_solver_block(Section& s, const std::vector<Plugin>& plugins, Block& block,
                       const std::string& what);
/// Checks that need the whole scene (scene_checks.cpp).
void cross_check(Section& top, const Scene& scene, std::optional<Section>& fluid_section,
                 std::vector<Section>& structure_sections, std::vector<Section>& probe_sections);
/// The whole scene; in documentation mode (ctx.collector) every key's declaration (scene.cpp).
Scene read_scene(Section top);

} // namespace fsi::app
