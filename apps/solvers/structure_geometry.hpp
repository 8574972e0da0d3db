#pragma once
// One structure for either structure type by one override (`--set structures[N].type=`, issue 41
// item 12). Where a structures entry gives one type's geometry and not the other's, the other type
// takes it: the TL-SPH solid fills the FE mesh's outline (a rectangle, or a Gmsh mesh's boundary),
// and the FE type meshes a TL-SPH rectangle. Neither solver library knows the other: the
// translation is of scene keys, here, and the plug-ins call it as StructurePlugin::adopt.
#include "fsi_app/scene_reader.hpp"

namespace fsi::app {

/// Rows of particles a TL-SPH solid translated from an FE mesh continues beyond each clamped side,
/// the clamp (the shipped TL-SPH scenes' 4 rows into the support; the library needs 2 or more).
constexpr int kClampRows = 4;

/// adopt of type tlsph. With no `region` (in the entry or its `tlsph` block) but an FE `mesh`
/// (in the entry or its `fem` block), the entry is read as a TL-SPH solid filling the mesh's
/// outline: `region.polygon` the rectangle or the Gmsh mesh's boundary (its edge tags the FE
/// boundary tags); `dp` unless given, the mesh's node spacing (a rectangle: the smaller of
/// width / (2 elements_x) and height / (2 elements_y); a Gmsh mesh: the mean distance from a
/// corner to the mid-node of its element side); each FE `clamped` side, one straight side along
/// an axis, continued kClampRows dp outwards (edges tagged `clamp`) into a `clamped` box. The FE
/// keys TL-SPH has none of (mesh, newmark, newton, linear_solver) move to the `fem` block, checked
/// and set aside. InputError naming the FE key for what does not translate: `loads`, a clamped
/// side that is not one straight side along an axis, a mesh whose boundary is not one loop.
/// 3-D: a T10 `box` mesh becomes the TL-SPH box `region: {min, max}` (dp unless given, the
/// smallest of width / (2 elements_x), height / (2 elements_y), depth / (2 elements_z)), each
/// clamped side continued kClampRows dp outwards into a clamped box; a Gmsh mesh is refused.
void tlsph_from_fem(Section& s);

/// adopt of type fem. With no `mesh` (in the entry or its `fem` block) but a TL-SPH rectangle
/// `region: {min, max}`, the entry is read as an FE rectangle with nodes about dp apart
/// (elements_x = round(width / (2 dp)), at least 1; elements_y alike) and the same side tags; a
/// `clamped` box holding a whole side's strip of the rectangle (the support beyond the body)
/// becomes the clamped side, the mesh ending at the box's face; a `region.file` becomes the
/// Gmsh mesh. The TL-SPH keys FE has none of (region, dp, ...) move to the `tlsph` block.
/// InputError naming the TL-SPH key for what does not translate: a polygon region, a clamped box
/// that is not a side's strip, clamped boxes with a Gmsh region.
void fem_from_tlsph(Section& s);

} // namespace fsi::app
