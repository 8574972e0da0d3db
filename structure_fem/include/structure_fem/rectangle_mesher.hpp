#pragma once
// Structured T6 mesh of a rectangle.
#include "structure_fem/mesh.hpp"

namespace fsi::fem {

struct RectangleMeshOptions {
  Vec2 origin{0.0, 0.0}; ///< lower-left corner [m]
  double width = 1.0;    ///< extent in x [m], > 0
  double height = 0.1;   ///< extent in y [m], > 0
  int elements_x = 10;   ///< quads along x, >= 1
  int elements_y = 2;    ///< quads along y, >= 1
};

/// elements_x * elements_y quads, each split along its lower-left to upper-right diagonal into
/// two T6 (2 * elements_x * elements_y elements, (2 ex + 1)(2 ey + 1) nodes numbered row by row
/// from the origin). Sides are tagged "bottom", "right", "top", "left" (solid on the left).
Mesh make_rectangle_mesh(const RectangleMeshOptions& options);

} // namespace fsi::fem
