// Prescribed motions (2-D walls, 3-D tanks and clamps) and the 2-D walls of a scene file.
#include "scene_blocks.hpp"

#include "fsi/core/format.hpp"
#include "fsi_app/wall_motion.hpp"

#include <cmath>
#include <string>

namespace fsi::app {

namespace {

// The keys of a motion's profile s(t) after kind, dof and pivot (read_motion, read_motion3).
void read_profile(Section& s, MotionSpec& m) {
  const bool doc = s.context().documenting();
  if (doc || m.kind == "sinusoid") {
    m.amplitude = s.real("amplitude", Range::any(), "rad for rotation, m for translation");
    m.period = s.real("period", Range::positive(), "s");
    m.phase = s.real("phase", 0.0, Range::any(), "rad");
    // Issue 41: a period so short that 2 pi / period or the acceleration amplitude
    // amplitude (2 pi / period)^2 overflows makes the wall NaN (5e-324 passes "> 0").
    const double omega = 2.0 * M_PI / m.period;
    if (!doc && !(std::isfinite(omega) && std::isfinite(std::abs(m.amplitude) * omega * omega) &&
                  std::isfinite(omega * omega)))
      s.fail("period", significant(m.period, 6) + " s with amplitude " +
                           significant(m.amplitude, 6) +
                           ": the motion's acceleration amplitude * (2 pi / period)^2 is not "
                           "finite; give a longer period");
  }
  if (doc || m.kind == "table") {
    m.table = s.file("table", "CSV with header; columns time (s) and value");
    const std::string unit = s.choice("unit", {"deg", "rad", "m"}, "rad", "unit of the values");
    const double scale =
        s.real("scale", 1.0, Range::any(),
               "factor on the values, e.g. -1 for a table whose positive angles turn clockwise "
               "(the scene's turn counter-clockwise)");
    m.table_scale = scale * (unit == "deg" ? M_PI / 180.0 : 1.0);
    m.hold = s.boolean("hold", false,
                       "hold the table's first value before its first time and its last value "
                       "after its last; without it the table must cover 0 .. time.end");
    if (!doc && (unit == "m") != (m.dof != "rotation"))
      s.fail("unit", "'" + unit + "' does not match dof '" + m.dof + "'");
  }
  s.finish();
}

std::string motion_kind(Section& s) {
  return s.choice("kind", {"sinusoid", "table"}, "",
                  "sinusoid: amplitude sin(2 pi t / period + phase); table: CSV time,value");
}

MotionSpec read_motion(Section s) {
  MotionSpec m;
  m.kind = motion_kind(s);
  m.dof = s.choice("dof", {"rotation", "x", "y"}, "rotation",
                   "rotation about pivot, or translation along x or y");
  m.pivot = s.vec2("pivot", Vec2::Zero(), "rotation centre in the scene frame, m");
  read_profile(s, m);
  return m;
}

} // namespace

WallSpec read_wall(Section s) {
  WallSpec w;
  w.line = s.line();
  w.name = s.text("name", "wall name, for messages");
  w.polyline =
      s.points("polyline", 2, "vertices; the fluid lies on the left of each directed segment");
  w.closed = s.boolean("closed", false, "join the last vertex to the first");
  if (auto m = s.block("motion", "prescribed rigid motion; absent: the wall is static"))
    w.motion = read_motion(*m);
  if (!s.context().documenting())
    for (std::size_t i = 0; i + 1 < w.polyline.size(); ++i)
      if ((w.polyline[i + 1] - w.polyline[i]).norm() == 0.0)
        s.fail("polyline", "points " + std::to_string(i) + " and " + std::to_string(i + 1) +
                               " coincide (zero-length segment)");
  // Issue 41: the closing segment of a closed polyline too (it failed later, naming no key).
  if (!s.context().documenting() && w.closed && w.polyline.size() > 2 &&
      (w.polyline.front() - w.polyline.back()).norm() == 0.0)
    s.fail("polyline", "the last point " + std::to_string(w.polyline.size() - 1) +
                           " is the first (closed: true joins them by a zero-length segment); "
                           "drop the last point");
  s.finish();
  return w;
}

MotionSpec read_motion3(Section s) {
  MotionSpec m;
  m.kind = motion_kind(s);
  m.dof = s.choice("dof", {"rotation", "x", "y", "z"}, "rotation",
                   "rotation about axis through pivot, or translation along x, y or z");
  m.axis =
      s.vec3("axis", Vec3::UnitZ(),
             "rotation axis (normalised; default [0, 0, 1]), right-handed: counter-clockwise seen "
             "from its tip");
  m.pivot3 = s.vec3("pivot", Vec3::Zero(),
                    "a point of the rotation axis in the scene frame (default the origin), m");
  if (!s.context().documenting() && !(m.axis.norm() > 0.0)) s.fail("axis", "is zero");
  read_profile(s, m);
  return m;
}

} // namespace fsi::app
