#pragma once
// One wall segment's geometry as the locators cache it at update().
#include "fsi/core/types.hpp"

namespace fsi::erp {

struct SegmentGeometry {
  Vec2 a, b, ab;      // end points (nodes a and b at update()) and b - a
  double length2;     // |b - a|^2
  double inv_length2; // 1 / |b - a|^2
  int id;             // segment index in the WallSet
};

} // namespace fsi::erp
