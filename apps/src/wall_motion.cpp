#include "fsi_app/wall_motion.hpp"

#include <algorithm>

namespace fsi::app {

std::shared_ptr<const erp::Motion> make_motion(const WallSpec& wall) {
  const MotionSpec& m = *wall.motion;
  const bool rotation = m.dof == "rotation";
  const Vec2 direction = m.dof == "x" ? Vec2(1, 0) : Vec2(0, 1);
  if (m.kind == "sinusoid") {
    if (rotation) return std::make_shared<erp::SinusoidRotation>(m.amplitude, m.period, m.phase);
    return std::make_shared<erp::SinusoidTranslation>(m.amplitude * direction, m.period, m.phase);
  }
  if (!rotation)
    return std::make_shared<erp::TableTranslation>(m.table.string(), m.table_scale * direction);
  return std::make_shared<erp::TableRotation>(m.table.string(), m.table_scale);
}

const WallSpec& moving_wall(const Scene& scene, const std::string& name, int line,
                            const std::string& key) {
  const auto it = std::find_if(scene.walls.begin(), scene.walls.end(),
                               [&](const WallSpec& w) { return w.name == name; });
  if (it == scene.walls.end()) fail_at(scene, line, key, "no wall named '" + name + "'");
  if (!it->motion) fail_at(scene, line, key, "wall '" + name + "' has no motion");
  return *it;
}

} // namespace fsi::app
