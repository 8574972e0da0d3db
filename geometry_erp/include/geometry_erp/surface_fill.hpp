#pragma once
// Initial fluid particles on the cubic lattice inside a closed triangle surface (issue 43: fluid
// regions given as closed STL or Gmsh surfaces).
#include "fsi/core/types.hpp"

#include <array>
#include <span>
#include <vector>

namespace fsi::erp {

/// The lattice points lo + ((i + 1/2) l0, (j + 1/2) l0, (k + 1/2) l0), lo the lowest corner of the
/// surface's bounding box, inside the closed surface of `triangles` (indices into `points`,
/// either orientation): a ray from the point along +x crosses it an odd number of times. Ties,
/// where a ray meets an edge or a vertex in the projection onto the y-z plane, are resolved by
/// the top-left rule on edge functions computed once per edge in a fixed direction, so an edge
/// shared by two triangles on either side of it is counted once (and a silhouette edge twice or
/// not at all, leaving the parity as it is); triangles parallel to x do not count, and a hit at
/// the point's own x does not count (a point on the surface is outside). Ordered by k, j, i.
std::vector<Vec3> fill_closed_surface(std::span<const Vec3> points,
                                      std::span<const std::array<int, 3>> triangles, double l0);

} // namespace fsi::erp
