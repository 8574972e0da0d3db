// Convex corners (WallSet::convex_joint): which nodes of a polyline are convex, their turn and
// faces, at the current node positions.
#include "geometry_erp/wall_set.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace fsi;
using namespace fsi::erp;
using Catch::Matchers::WithinAbs;

TEST_CASE("erp: a block's top corners are convex joints, a tank's corners and open ends are not",
          "[erp]") {
  WallSet walls;
  // Tank (counter-clockwise, fluid inside) and a block on its floor (clockwise, fluid outside).
  walls.add_polyline(std::vector<Vec2>{{0.0, 1.0}, {0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}}, false, 0);
  const WallRange block = walls.add_polyline(
      std::vector<Vec2>{{0.4, 0.0}, {0.4, 0.2}, {0.6, 0.2}, {0.6, 0.0}}, false, 1);
  for (int L = 0; L < 4; ++L) CHECK_FALSE(walls.convex_joint(L)); // concave corners, open ends
  CHECK_FALSE(walls.convex_joint(block.first_node));              // open end on the floor
  CHECK_FALSE(walls.convex_joint(block.first_node + 3));
  for (const int k : {1, 2}) {
    const auto joint = walls.convex_joint(block.first_node + k);
    REQUIRE(joint);
    CHECK_THAT(joint->turn, WithinAbs(0.5 * std::numbers::pi, 1e-14));
    CHECK(joint->in_segment == block.first_segment + k - 1);
    CHECK(joint->out_segment == block.first_segment + k);
    CHECK_THAT((joint->n_in - walls.segment_normal(joint->in_segment)).norm(), WithinAbs(0, 1e-15));
    CHECK_THAT((joint->n_out - walls.segment_normal(joint->out_segment)).norm(),
               WithinAbs(0, 1e-15));
  }
  // The node positions are read at call time: tilt the left face so that it turns right into
  // the top by 20 degrees (a curved wall's bend, not a corner), then by 40 degrees.
  auto& x = walls.nodes().x;
  for (const double degrees : {20.0, 40.0}) {
    const double psi = degrees * std::numbers::pi / 180.0;
    x[static_cast<std::size_t>(block.first_node)] =
        Vec2(0.4, 0.2) - 0.2 * Vec2(std::cos(psi), std::sin(psi));
    const auto joint = walls.convex_joint(block.first_node + 1);
    CHECK(bool(joint) == (degrees > 30.0));
    if (joint) CHECK_THAT(joint->turn, WithinAbs(psi, 1e-12));
  }
}
