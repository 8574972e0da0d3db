#pragma once
// A box of triangles: the six (or, open at the top or bottom, five; a slab, four) faces of [lo,
// hi], two triangles each, with the fluid inside (a tank, normals into the box) or outside (an
// obstacle, normals out of it), as TriangleWallSet expects.
#include "geometry_erp/triangle_wall_set.hpp"

namespace fsi::erp {

/// Adds the box's faces to `walls` (group `group`); `open_top` leaves out the face z = hi.z.
/// Throws fsi::InputError on an empty box.
TriangleRange add_box_tank(TriangleWallSet& walls, const Vec3& lo, const Vec3& hi, bool open_top,
                           int group);

/// Adds the four faces of the box [lo, hi] parallel to z (y = lo.y, y = hi.y, x = lo.x,
/// x = hi.x), normals into it, open at both z faces: the tank of a fluid periodic along z, given
/// longer than the period so that no particle within r_e of the period sees its open ends.
/// Throws fsi::InputError on an empty box.
TriangleRange add_box_slab(TriangleWallSet& walls, const Vec3& lo, const Vec3& hi, int group);

/// Adds a box obstacle, its faces with normals out of the box (its edges and corners convex seen
/// from the fluid): all six, or with `open_bottom` = a (0, 1, 2) all but the face x_a = lo_a, a
/// box standing on a floor at x_a = lo_a without its bottom. Throws fsi::InputError on an empty
/// box or an axis out of range.
TriangleRange add_box_obstacle(TriangleWallSet& walls, const Vec3& lo, const Vec3& hi, int group,
                               int open_bottom = -1);

} // namespace fsi::erp
