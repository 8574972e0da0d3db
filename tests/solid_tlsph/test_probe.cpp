// Probes (issue 19: "the particle nearest to it, or the kernel interpolation at it"): under a
// linear displacement field the interpolation with the linear correction is exact to round-off
// at off-lattice points, inside and at the surface and corner; the nearest particle is off by
// |A| times its distance to the point.
#include <catch2/catch.hpp>

#include <cmath>

#include "common.hpp"
#include "fsi/core/error.hpp"

using namespace tlsph_test;

TEST_CASE("tlsph: kernel interpolation is exact for a linear field, the nearest particle is not",
          "[solid_tlsph][probe]") {
  TlsphOptions o;
  o.dp = 0.01;
  TlsphSolid s(fill_rectangle({0.0, 0.0}, {0.3, 0.12}, o.dp), o);
  const LinearField u;
  u.apply(s);
  // Interior, 0.7 dp from the right side, and the corner (all off the lattice).
  for (const Vec2& X : {Vec2(0.1234, 0.0567), Vec2(0.2987, 0.0611), Vec2(0.3, 0.12)}) {
    const Vec2 exact = u.at(X);
    const double interpolated = (s.interpolate_displacement(X) - exact).norm();
    const double nearest = (s.displacement(s.nearest_particle(X)) - exact).norm();
    INFO("X = (" << X.x() << ", " << X.y() << "): interpolated " << interpolated << ", nearest "
                 << nearest);
    CHECK(interpolated < 1e-14); // |u| ~ 0.36: round-off (measured 5.6e-17 to 1.4e-16)
    CHECK(nearest > 5e-5);       // |A (X_p - X)|: the nearest particle is 2.3 mm or more away
  }
  CHECK_THROWS_WITH(s.interpolation_stencil(Vec2(0.5, 0.5)),
                    Catch::Matchers::Contains("is off the solid: its 0 particles within 2h"));
}
