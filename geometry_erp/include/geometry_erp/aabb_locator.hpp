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
  void query(std::span<const Vec2> x, WallHits& hits) const override;
  void query(std::span<const double> x, std::span<const double> y, WallHits& hits) const override;

private:
  struct Tree; // the CGAL types stay in the source file
  template <class Point> void run(std::size_t n, Point&& point, WallHits& hits) const;
  std::unique_ptr<Tree> tree_;
};

} // namespace fsi::erp
