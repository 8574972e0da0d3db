#pragma once
// The prescribed rigid motion of a scene wall, shared by the walls it moves and by structures
// clamped to it (structures[].clamped_motion) and probes in its frame (displacement_*_tank).
#include "fsi_app/scene.hpp"
#include "fsi_app/scene_reader.hpp"
#include "geometry_erp/motion.hpp"
#include "geometry_erp/motion3.hpp"

#include <memory>
#include <optional>
#include <string>

namespace fsi::app {

/// The motion of a wall that has a motion block (the table, if any, read here: InputError with
/// the table's file and line).
std::shared_ptr<const erp::Motion> make_motion(const WallSpec& wall);

/// A 3-D motion block (fluid.tank_motion): kind, dof (rotation, x, y or z), axis and pivot
/// as [x, y, z], and the profile keys of a wall's motion (scene.cpp).
MotionSpec read_motion3(Section s);

/// The 3-D rigid motion of a read_motion3 block (the table, if any, read here: InputError with
/// the table's file and line).
erp::RigidMotion3 make_motion3(const MotionSpec& m);

/// Reads the motion's table (if any) and checks it covers 0 .. time.end unless it holds:
/// fail_at(line, key) with the table's message.
void check_motion_table(const Scene& scene, const MotionSpec& m, int line, const std::string& key);

/// Reads every motion table of the scene's walls and checks that it covers the run, 0 ..
/// time.end (unless the motion says hold: true). InputError `SCENE:LINE: walls[i].motion.table:
/// TABLE[:ROW]: what`, before any model is built.
void check_motion_tables(const Scene& scene);

/// The wall called `name`; fail_at(line, key) if there is none or it has no motion.
const WallSpec& moving_wall(const Scene& scene, const std::string& name, int line,
                            const std::string& key);

/// The moving frame of a wall with a motion (a structure's clamped_motion wall): that wall's rigid
/// motion about its pivot.
struct WallFrame {
  std::shared_ptr<const erp::Motion> motion;
  Vec2 pivot;
  /// The displacement, in this frame's axes, of the material point with reference position X
  /// that is at x at time t: X_t - X for the frame-fixed point X_t = R^T (x - p - d) + p that it
  /// is at now (the rigid motion undone).
  Vec2 displacement(const Vec2& X, const Vec2& x, double t) const;
};

/// The frame of the wall a structure's clamped_motion names (`wall`; empty: nullopt, clamped in
/// place); fail_at(line, key) if there is no such wall or it has no motion.
std::optional<WallFrame> wall_frame(const Scene& scene, const std::string& wall, int line,
                                    const std::string& key);

/// A structure's `clamped_motion` key in its block `s`: it names a wall with a motion and the
/// structure has clamps (`clamps`: what they are, for the message) to move with it.
void check_clamped_motion(const Scene& scene, const std::string& wall, bool clamped,
                          const std::string& clamps, Section& s);

/// A probe of a structure whose clamped_motion wall is `wall`: a frame quantity
/// (displacement_*_tank) needs one (the probe's section `s` fails otherwise).
void check_frame_probe(const ProbeSpec& probe, const std::string& wall, Section& s);

} // namespace fsi::app
