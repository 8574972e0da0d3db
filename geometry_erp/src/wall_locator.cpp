#include "geometry_erp/wall_locator.hpp"

#include "geometry_erp/aabb_locator.hpp"
#include "geometry_erp/grid_locator.hpp"

namespace fsi::erp {

void FaceHits::resize(std::size_t n) {
  segment.resize(n);
  t.resize(n);
  r.resize(n);
  x_wall.resize(n);
  n_wall.resize(n);
  v_wall.resize(n);
}

void WallHits::resize(std::size_t n) {
  for (FaceHits& f : face) f.resize(n);
  a_wall.resize(n);
  crossed.resize(n);
}

std::unique_ptr<WallLocator> make_wall_locator(const WallSet& walls, double r_e, LocatorKind kind) {
  if (kind == LocatorKind::aabb_tree) return std::make_unique<AabbLocator>(walls, r_e);
  return std::make_unique<GridLocator>(walls, r_e);
}

} // namespace fsi::erp
