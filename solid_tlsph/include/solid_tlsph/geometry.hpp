#pragma once
// Seeding a TL-SPH solid: particles on a square (cubic) lattice of spacing dp filling a polygon
// (a box in 3-D), each with volume dp^D, and in 2-D the polygon's outline with a tag per edge
// (the coupling interface is built from the surface particles of tagged edges,
// solid_tlsph/solid.hpp).
#include <string>
#include <vector>

#include "fsi/core/types.hpp"

namespace fsi::tlsph {

/// The reference configuration of a solid.
template <int D> struct BasicSolidGeometry {
  std::vector<VecD<D>> X0; ///< particle reference positions [m]
  std::vector<double> V0;  ///< particle reference volumes [m^D; 2-D: m^2 per unit thickness]
  /// 2-D: the body's outline, counter-clockwise (solid on the left); may be empty when the
  /// caller passes particles only (then no interface). 3-D: empty.
  std::vector<VecD<D>> outline;
  std::vector<std::string> outline_tags; ///< tag of edge outline[i] -> outline[i + 1 mod n]
  /// 3-D: {lo, hi} of the box the particles fill (fill_box), whose faces, tagged "x-", "x+",
  /// "y-", "y+", "z-", "z+", carry the interface; empty: no interface.
  std::vector<VecD<D>> box;
};
using SolidGeometry = BasicSolidGeometry<2>;
using SolidGeometry3 = BasicSolidGeometry<3>;

/// True if X is inside the polygon (even-odd rule; points on an edge count as inside only when
/// the crossing test says so, which never happens for lattice points at dp/2 from the edges).
bool inside_polygon(const std::vector<Vec2>& polygon, const Vec2& X);

/// Particles at the lattice points origin + (i + 1/2, j + 1/2) dp inside a counter-clockwise
/// polygon, volume dp^2. `tags` names each edge (size = polygon size; empty: all "boundary").
/// Throws InputError for dp <= 0, fewer than 3 vertices, a clockwise polygon or a tag count
/// that does not match.
SolidGeometry fill_polygon(const std::vector<Vec2>& polygon, std::vector<std::string> tags,
                           double dp, const Vec2& origin = Vec2::Zero());

/// The rectangle [lo, hi] filled at dp from lo (a whole number of layers when the sides are
/// multiples of dp); edges tagged "bottom", "right", "top", "left".
SolidGeometry fill_rectangle(const Vec2& lo, const Vec2& hi, double dp);

/// The box [lo, hi] filled at the lattice points lo + (i + 1/2, j + 1/2, k + 1/2) dp inside it,
/// volume dp^3, x fastest; no outline, box = {lo, hi}. Throws InputError for dp <= 0 or hi <= lo.
SolidGeometry3 fill_box(const Vec3& lo, const Vec3& hi, double dp);

} // namespace fsi::tlsph
