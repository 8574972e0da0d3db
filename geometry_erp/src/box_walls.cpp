#include "geometry_erp/box_walls.hpp"

#include "fsi/core/error.hpp"

#include <string>
#include <vector>

namespace fsi::erp {

namespace {
/// The faces of [lo, hi] but those of the list below whose bit is set in `open`, normals into
/// the box (a tank) or out of it.
TriangleRange add_box(TriangleWallSet& walls, const Vec3& lo, const Vec3& hi, unsigned open,
                      bool into_box, int group) {
  std::vector<Vec3> corner(8); // corner b: x from bit 0, y from bit 1, z from bit 2
  for (int b = 0; b < 8; ++b)
    corner[static_cast<std::size_t>(b)] =
        Vec3(b & 1 ? hi.x() : lo.x(), b & 2 ? hi.y() : lo.y(), b & 4 ? hi.z() : lo.z());
  const Vec3 centre = 0.5 * (lo + hi);
  // The faces as corner quadruples around their edge: z = lo.z, y = lo.y, y = hi.y, x = lo.x,
  // x = hi.x, z = hi.z.
  const int faces[6][4] = {{0, 1, 3, 2}, {0, 1, 5, 4}, {2, 3, 7, 6},
                           {0, 2, 6, 4}, {1, 3, 7, 5}, {4, 5, 7, 6}};
  std::vector<std::array<int, 3>> triangles;
  for (int f = 0; f < 6; ++f) {
    if (open >> f & 1u) continue;
    const int* q = faces[f];
    for (const std::array<int, 3> t : {std::array<int, 3>{q[0], q[1], q[2]}, {q[0], q[2], q[3]}}) {
      const Vec3 &a = corner[static_cast<std::size_t>(t[0])],
                 &b = corner[static_cast<std::size_t>(t[1])],
                 &c = corner[static_cast<std::size_t>(t[2])];
      const bool inward = (b - a).cross(c - a).dot(centre - a) > 0.0;
      triangles.push_back(inward == into_box ? t : std::array<int, 3>{t[0], t[2], t[1]});
    }
  }
  return walls.add_triangles(corner, triangles, group);
}
} // namespace

TriangleRange add_box_tank(TriangleWallSet& walls, const Vec3& lo, const Vec3& hi, bool open_top,
                           int group) {
  if (!(hi.array() > lo.array()).all()) throw InputError("box tank: empty box");
  return add_box(walls, lo, hi, open_top ? 1u << 5 : 0u, true, group);
}

TriangleRange add_box_slab(TriangleWallSet& walls, const Vec3& lo, const Vec3& hi, int group) {
  if (!(hi.array() > lo.array()).all()) throw InputError("box slab: empty box");
  return add_box(walls, lo, hi, 1u << 0 | 1u << 5, true, group);
}

TriangleRange add_box_obstacle(TriangleWallSet& walls, const Vec3& lo, const Vec3& hi, int group,
                               int open_bottom) {
  if (!(hi.array() > lo.array()).all()) throw InputError("box obstacle: empty box");
  if (open_bottom < -1 || open_bottom > 2)
    throw InputError("box obstacle: no axis " + std::to_string(open_bottom));
  const int bottom_face[3] = {3, 1, 0}; // the face x = lo.x, y = lo.y, z = lo.z in the list
  return add_box(walls, lo, hi, open_bottom < 0 ? 0u : 1u << bottom_face[open_bottom], false,
                 group);
}

} // namespace fsi::erp
