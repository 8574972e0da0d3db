#pragma once
// Initial fluid particles on a square lattice inside a region.
#include "fsi/core/types.hpp"
#include "geometry_erp/wall_set.hpp"

#include <vector>

namespace fsi::erp {

using Polygon = std::vector<Vec2>;

/// Lattice points origin + ((i + 1/2) l0, (j + 1/2) l0), integers i, j, that are strictly inside
/// one of `regions`, not inside or on any of `holes` (all closed polygons, either orientation,
/// closing edge implied), and at least l0/2 - 1e-9 l0 from every edge of the regions and holes and
/// from every segment of `walls` (optional). Ordered by row (j), then column (i).
std::vector<Vec2> fill_lattice(const Vec2& origin, double l0, const std::vector<Polygon>& regions,
                               const std::vector<Polygon>& holes = {},
                               const WallSet* walls = nullptr);

} // namespace fsi::erp
