#include "fsi_app/wall_motion.hpp"

#include "fsi/core/error.hpp"
#include "geometry_erp/csv_table.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fsi::app {

namespace {

/// The motion's profile: a rotation's angle, or a translation s(t) `direction`.
std::shared_ptr<const erp::Motion> make_profile(const MotionSpec& m, const Vec2& direction) {
  const bool rotation = m.dof == "rotation";
  if (m.kind == "sinusoid") {
    if (rotation) return std::make_shared<erp::SinusoidRotation>(m.amplitude, m.period, m.phase);
    return std::make_shared<erp::SinusoidTranslation>(m.amplitude * direction, m.period, m.phase);
  }
  if (!rotation)
    return std::make_shared<erp::TableTranslation>(m.table.string(), m.table_scale * direction);
  return std::make_shared<erp::TableRotation>(m.table.string(), m.table_scale);
}

} // namespace

std::shared_ptr<const erp::Motion> make_motion(const WallSpec& wall) {
  const MotionSpec& m = *wall.motion;
  return make_profile(m, m.dof == "x" ? Vec2(1, 0) : Vec2(0, 1));
}

erp::RigidMotion3 make_motion3(const MotionSpec& m) {
  const auto profile = make_profile(m, Vec2(1, 0)); // s(t) in d.x() (RigidMotion3)
  if (m.dof == "rotation") return erp::RigidMotion3::rotation(profile, m.axis, m.pivot3);
  return erp::RigidMotion3::translation(profile, m.dof == "x"   ? Vec3::UnitX()
                                                 : m.dof == "y" ? Vec3::UnitY()
                                                                : Vec3::UnitZ());
}

void check_motion_table(const Scene& scene, const MotionSpec& m, int line, const std::string& key) {
  if (m.kind != "table") return;
  const std::string file = m.table.string();
  const int columns = 2; // time and one value (rotation, or translation along one axis)
  erp::CsvTable table;
  try {
    table = erp::read_csv_table(file, columns);
  } catch (const InputError& e) {
    fail_at(scene, line, key, e.what());
  }
  const double first = table.columns[0].front(), last = table.columns[0].back();
  const double end = scene.time.end;
  if (!m.hold && (first > 0.0 || last < end * (1.0 - 1e-12))) {
    std::ostringstream what;
    what << file << ": covers t = " << first << " .. " << last << " s, the run needs 0 .. " << end
         << " s (extend it, lower time.end, or give hold: true to hold its end values)";
    fail_at(scene, line, key, what.str());
  }
}

void check_motion_tables(const Scene& scene) {
  for (std::size_t i = 0; i < scene.walls.size(); ++i) {
    const WallSpec& w = scene.walls[i];
    if (w.motion)
      check_motion_table(scene, *w.motion, w.line, "walls[" + std::to_string(i) + "].motion.table");
  }
}

const WallSpec& moving_wall(const Scene& scene, const std::string& name, int line,
                            const std::string& key) {
  const auto it = std::find_if(scene.walls.begin(), scene.walls.end(),
                               [&](const WallSpec& w) { return w.name == name; });
  if (it == scene.walls.end()) fail_at(scene, line, key, "no wall named '" + name + "'");
  if (!it->motion) fail_at(scene, line, key, "wall '" + name + "' has no motion");
  return *it;
}

Vec2 WallFrame::displacement(const Vec2& X, const Vec2& x, double t) const {
  const erp::RigidKinematics k = motion->at(t);
  const Vec2 r = x - pivot - k.d;
  const Vec2 local(std::cos(k.theta) * r.x() + std::sin(k.theta) * r.y(),
                   -std::sin(k.theta) * r.x() + std::cos(k.theta) * r.y());
  return local + pivot - X;
}

std::optional<WallFrame> wall_frame(const Scene& scene, const std::string& wall, int line,
                                    const std::string& key) {
  if (wall.empty()) return std::nullopt;
  const WallSpec& w = moving_wall(scene, wall, line, key);
  return WallFrame{make_motion(w), w.motion->pivot};
}

void check_clamped_motion(const Scene& scene, const std::string& wall, bool clamped,
                          const std::string& clamps, Section& s) {
  if (wall.empty()) return;
  if (!clamped) s.fail("clamped_motion", "needs " + clamps + " to move");
  const auto w = std::find_if(scene.walls.begin(), scene.walls.end(),
                              [&](const WallSpec& x) { return x.name == wall; });
  if (w == scene.walls.end()) s.fail("clamped_motion", "no wall named '" + wall + "'");
  if (!w->motion) s.fail("clamped_motion", "wall '" + wall + "' has no motion");
}

void check_frame_probe(const ProbeSpec& probe, const std::string& wall, Section& s) {
  if (probe.quantity.ends_with("_tank") && wall.empty())
    s.fail("quantity", "'" + probe.quantity + "' needs structure '" + probe.structure +
                           "' to have a clamped_motion");
}

} // namespace fsi::app
