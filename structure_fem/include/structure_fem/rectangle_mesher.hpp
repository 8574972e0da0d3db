#pragma once
// Structured T6 mesh of a rectangle.
#include "structure_fem/mesh.hpp"

namespace fsi::fem {

/// How the quads are split into triangles.
enum class Diagonals {
  /// Every quad along its lower-left to upper-right diagonal: the upper-left and lower-right
  /// corners of the rectangle belong to one triangle each.
  rising,
  /// Mirrored about the rectangle's vertical mid-line (the quads of the left half along their
  /// lower-right to upper-left diagonal): both top corners belong to two triangles, so the free
  /// end of a plate clamped at its bottom has no corner node held by a single element.
  mirrored,
};

struct RectangleMeshOptions {
  Vec2 origin{0.0, 0.0}; ///< lower-left corner [m]
  double width = 1.0;    ///< extent in x [m], > 0
  double height = 0.1;   ///< extent in y [m], > 0
  int elements_x = 10;   ///< quads along x, >= 1
  int elements_y = 2;    ///< quads along y, >= 1
  Diagonals diagonals = Diagonals::rising;
};

/// elements_x * elements_y quads, each split along a diagonal (`diagonals`) into two T6
/// (2 * elements_x * elements_y elements, (2 ex + 1)(2 ey + 1) nodes numbered row by row from the
/// origin). Sides are tagged "bottom", "right", "top", "left" (solid on the left).
Mesh make_rectangle_mesh(const RectangleMeshOptions& options);

} // namespace fsi::fem
