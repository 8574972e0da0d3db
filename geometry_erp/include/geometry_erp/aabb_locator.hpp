#pragma once
// CGAL AABB-tree back-end: the segments (lifted to z = 0, as CGAL 5.5 trees are 3D) in a bounding
// box hierarchy; each particle descends only into boxes nearer than its best segment so far,
// starting from r_e. update() rebuilds the tree (CGAL trees cannot be refitted).
#include "geometry_erp/wall_locator.hpp"

#include <memory>

namespace fsi::erp {

class AabbLocator final : public WallLocator {
public:
  AabbLocator(const WallSet& walls, double r_e);
  ~AabbLocator() override;
  void update() override;

private:
  struct Tree; // the CGAL types stay in the source file
  void locate(const QueryPoints& points, WallHits& hits) const override;
  std::unique_ptr<Tree> tree_;
};

} // namespace fsi::erp
