#pragma once
// The prescribed rigid motion of a scene wall, shared by the walls it moves and by structures
// clamped to it (structures[].clamped_motion) and probes in its frame (displacement_*_tank).
#include "fsi_app/scene.hpp"
#include "fsi_app/scene_reader.hpp"
#include "geometry_erp/motion.hpp"

#include <memory>
#include <string>

namespace fsi::app {

/// The motion of a wall that has a motion block (the table, if any, read here: InputError with
/// the table's file and line).
std::shared_ptr<const erp::Motion> make_motion(const WallSpec& wall);

/// Reads every motion table of the scene's walls and checks that it covers the run, 0 ..
/// time.end (unless the motion says hold: true). InputError `SCENE:LINE: walls[i].motion.table:
/// TABLE[:ROW]: what`, before any model is built.
void check_motion_tables(const Scene& scene);

/// The wall called `name`; fail_at(line, key) if there is none or it has no motion.
const WallSpec& moving_wall(const Scene& scene, const std::string& name, int line,
                            const std::string& key);

/// A structure's `clamped_motion` key in its block `s`: it names a wall with a motion and the
/// structure has clamps (`clamps`: what they are, for the message) to move with it.
void check_clamped_motion(const Scene& scene, const std::string& wall, bool clamped,
                          const std::string& clamps, Section& s);

} // namespace fsi::app
