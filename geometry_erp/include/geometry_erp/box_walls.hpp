#pragma once
// A box of triangles: the six (or, open at the top, five) faces of [lo, hi], two triangles each,
// with the fluid inside (a tank, normals into the box) or outside (an obstacle, normals out of
// it), as TriangleWallSet expects.
#include "geometry_erp/triangle_wall_set.hpp"

namespace fsi::erp {

/// Adds the box's faces to `walls` (group `group`); `open_top` leaves out the face z = hi.z.
/// Throws fsi::InputError on an empty box.
TriangleRange add_box_tank(TriangleWallSet& walls, const Vec3& lo, const Vec3& hi, bool open_top,
                           int group);

/// Adds a closed box obstacle, its six faces with normals out of the box (its edges and corners
/// convex seen from the fluid). Throws fsi::InputError on an empty box.
TriangleRange add_box_obstacle(TriangleWallSet& walls, const Vec3& lo, const Vec3& hi, int group);

} // namespace fsi::erp
