#include "fsi_app/fluid_regions.hpp"

#include "geometry_erp/fill.hpp"
#include "geometry_erp/wall_set.hpp"

namespace fsi::app {

std::vector<Vec2> fill_regions(const Scene& scene, const std::vector<Polygon>& regions, double l0,
                               const std::vector<Polygon>& solid) {
  std::vector<erp::Polygon> holes = solid;
  std::vector<Vec2> positions;
  // Each region on its own lattice from its lower-left corner, so a region a whole number of l0
  // wide has l0/2 gaps at both sides; earlier regions are holes for later ones (no doubles).
  // Regions and walls are both given in the reference configuration: the fill keeps l0/2 from
  // the walls as written, not as moved to t = 0 (a tank starting at a small angle would
  // otherwise lose a row of particles on one side).
  erp::WallSet reference;
  for (std::size_t w = 0; w < scene.walls.size(); ++w)
    reference.add_polyline(scene.walls[w].polyline, scene.walls[w].closed, static_cast<int>(w));
  for (const auto& region : regions) {
    Vec2 origin = region.front();
    for (const auto& p : region) origin = origin.cwiseMin(p);
    const auto filled = erp::fill_lattice(origin, l0, {region}, holes, &reference);
    positions.insert(positions.end(), filled.begin(), filled.end());
    holes.push_back(region);
  }
  if (positions.empty())
    fail_at(scene, scene.fluid->line, "fluid.regions",
            "no particle fits in the regions at this l0");
  return positions;
}

} // namespace fsi::app
