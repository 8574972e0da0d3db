#pragma once
// The ERP wall: a 2D polygon soup of flat segments over shared nodes (eqs. 18-19, 45-49).
//
// Fluid side convention: a segment runs from node a to node b and the fluid is on its LEFT.
// Its fluid normal is the left normal n = e_z x (b - a) / |b - a| = (-(b-a)_y, (b-a)_x) / |b - a|.
// So a closed polyline listed counter-clockwise holds fluid inside (a tank) and one listed
// clockwise keeps fluid outside (an obstacle).
//
// Nodes are struct-of-arrays: position x, velocity v, acceleration a, all writable every step.
// Every segment carries a group id chosen by the caller, to tell which source it came from.
#include "fsi/core/node_motion.hpp"
#include "fsi/core/types.hpp"
#include "geometry_erp/motion.hpp"

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace fsi {
class StateArchive;
}

namespace fsi::erp {

/// Polygon nodes L, struct-of-arrays.
using WallNodes = NodeMotion;

/// Polygon segments s, struct-of-arrays: node[s] = {a, b}, fluid on the left of a -> b.
struct WallSegments {
  std::vector<std::array<int, 2>> node;
  std::vector<int> group;
  std::size_t size() const { return node.size(); }
};

/// A convex corner: a node joining an incoming segment (ending there) and an outgoing one
/// (starting there) that turn towards the solid, so the solid's angle is 180 degrees - turn.
struct ConvexJoint {
  int in_segment, out_segment;
  Vec2 n_in, n_out; ///< the two faces' fluid normals
  double turn;      ///< angle between the faces' directions, radians
};

/// Joints turning by less than this are the gentle bends of a curved wall, not corners: 30 deg.
inline constexpr double convex_joint_min_turn = 0.5235987755982988;

/// Indices of what one add_* call created.
struct WallRange {
  int first_node = 0, node_count = 0, first_segment = 0, segment_count = 0;
};

class WallSet {
public:
  /// A fixed polyline through `points`; closed joins the last point to the first. Throws
  /// fsi::InputError on fewer than two points or a zero-length segment.
  WallRange add_polyline(std::span<const Vec2> points, bool closed, int group);

  /// A polyline moving rigidly with `motion` about `pivot` (motion.hpp); `points` are the
  /// reference positions X. Nodes are placed at time t = 0.
  WallRange add_rigid_polyline(std::span<const Vec2> points, bool closed, int group, Vec2 pivot,
                               std::shared_ptr<const Motion> motion);

  /// Sets x, v, a of every rigid polyline's nodes to the prescribed motion at time t.
  void move_rigid(double t);

  /// Checkpoint of the node states x, v, a (rigid motions are functions of t, FE interface nodes
  /// are set by the coupler; both are stored as they are). Segments are geometry, not state.
  void write_state(StateArchive& archive, const std::string& prefix) const;
  /// Throws InputError when the archive has another node count.
  void read_state(const StateArchive& archive, const std::string& prefix);

  /// Low-level construction (used by InterfaceWalls): one node at rest; one segment a -> b.
  int add_node(const Vec2& x);
  int add_segment(int a, int b, int group);

  WallNodes& nodes() { return nodes_; }
  const WallNodes& nodes() const { return nodes_; }
  const WallSegments& segments() const { return segments_; }

  /// Unit fluid (left) normal of segment s at the current node positions.
  Vec2 segment_normal(int s) const;
  /// Angle-weighted pseudo-normal of node L: in 2D every incident segment spans an angle pi at the
  /// node, so it is the normalised sum of the incident segments' fluid normals. Falls back to
  /// `fallback_segment`'s normal where that sum vanishes (a segment folded back onto another).
  Vec2 node_normal(int L, int fallback_segment) const;
  /// True for the free end of an open polyline (a node on one segment only): beyond it there is
  /// no solid, so a particle whose nearest wall point is such a node is never behind the wall.
  bool open_end(int L) const { return incident_[static_cast<std::size_t>(L)].size() == 1; }
  /// Node L as a convex corner at the current positions: exactly two incident segments, one
  /// ending and one starting at L, turning right (towards the solid) by more than
  /// convex_joint_min_turn; nullopt otherwise.
  std::optional<ConvexJoint> convex_joint(int L) const;

private:
  struct RigidPolyline {
    int first_node, node_count;
    std::vector<Vec2> X; // reference positions
    Vec2 pivot;
    std::shared_ptr<const Motion> motion;
  };

  WallNodes nodes_;
  WallSegments segments_;
  std::vector<std::vector<int>> incident_; // segments touching each node
  std::vector<RigidPolyline> rigid_;
};

} // namespace fsi::erp
