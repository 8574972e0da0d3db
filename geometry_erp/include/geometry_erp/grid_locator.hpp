#pragma once
// Uniform-grid back-end: segments are binned into square cells of side h >= r_e (every cell their
// bounding box overlaps); a particle checks the segments of its own and the 8 surrounding cells,
// which contain every segment within r_e of it.
#include "geometry_erp/segment_geometry.hpp"
#include "geometry_erp/wall_locator.hpp"

namespace fsi::erp {

class GridLocator final : public WallLocator {
public:
  GridLocator(const WallSet& walls, double r_e);
  void update() override;

  double cell_size() const { return h_; }

private:
  void locate(const QueryPoints& points, WallHits& hits) const override;

  double h_ = 0.0;
  Vec2 lo_ = Vec2::Zero();
  int nx_ = 0, ny_ = 0;
  std::vector<int> cell_begin_;               // CSR offsets into cell_segment_, size nx*ny + 1
  std::vector<SegmentGeometry> cell_segment_; // segments of each cell, with their geometry
};

} // namespace fsi::erp
