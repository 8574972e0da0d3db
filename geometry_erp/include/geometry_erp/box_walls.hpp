#pragma once
// A box tank of triangles: the six (or, open at the top, five) faces of [lo, hi], two triangles
// each, with the fluid inside (normals into the box), as TriangleWallSet expects.
#include "geometry_erp/triangle_wall_set.hpp"

namespace fsi::erp {

/// Adds the box's faces to `walls` (group `group`); `open_top` leaves out the face z = hi.z.
/// Throws fsi::InputError on an empty box.
TriangleRange add_box_tank(TriangleWallSet& walls, const Vec3& lo, const Vec3& hi, bool open_top,
                           int group);

} // namespace fsi::erp
