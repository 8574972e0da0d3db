#pragma once
// The scene: what one scene file describes, in SI units, after strict validation. Plain data; the
// solver blocks are parsed by their plug-ins (apps/solvers/<type>/), which also build the solvers
// from them: no solver library sees this.
#include "coupling/options.hpp"
#include "fsi/core/types.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fsi::app {

struct TimeSpec {
  double end = 0.0;              ///< s
  std::optional<double> dt;      ///< fixed step, s
  std::optional<double> courant; ///< adaptive step from a Courant number (fluid scenes)
};

struct ProbeSpec {
  std::string name;
  std::string quantity;       ///< displacement_x|y|z, displacement_x|y_tank, surge_front, pressure,
                              ///< mean_pressure, mean_speed, kinetic_energy
  std::string structure;      ///< for displacement probes
  std::optional<int> node;    ///< FE node index, or
  std::optional<Vec2> point;  ///< reference position of a node / a fluid point
  std::optional<Vec3> point3; ///< the same in a 3-D scene
  std::optional<Vec2> box_min, box_max;   ///< mean_pressure: the box averaged over
  std::optional<Vec3> box3_min, box3_max; ///< the same in a 3-D scene
  std::string part = "total";             ///< wall_force: total|pressure|repulsive|viscous
  bool interpolate = false;               ///< tlsph: kernel interpolation at point, not nearest
  std::optional<double> radius;           ///< wall_pressure: the wall patch's radius, m
  double pnd_fraction = 0.5;              ///< water_height: counts pnd >= pnd_fraction n0
  int line = 0;                           ///< scene line, for late messages
  std::string key;                        ///< its path in messages, `output.probes[2]`
};

struct OutputSpec {
  double interval = 0.0;           ///< s between frames
  std::vector<std::string> fields; ///< particle and mesh fields written to fields.h5
  std::vector<ProbeSpec> probes;
};

struct MotionSpec {
  std::string kind;            ///< sinusoid | table
  std::string dof;             ///< rotation | x | y (| z in 3-D)
  Vec2 pivot = Vec2::Zero();   ///< rotation centre (reference configuration)
  Vec3 pivot3 = Vec3::Zero();  ///< 3-D: a point of the rotation axis (reference configuration)
  Vec3 axis = Vec3::UnitZ();   ///< 3-D: the rotation axis
  double amplitude = 0.0;      ///< rad for rotation, m for translation
  double period = 1.0;         ///< s
  double phase = 0.0;          ///< rad
  std::filesystem::path table; ///< CSV time,value (value in the unit of `unit`)
  double table_scale = 1.0;    ///< multiplies the table values into rad or m (unit and scale)
  bool hold = false;           ///< a table shorter than the run holds its end values
};

struct WallSpec {
  std::string name;
  int line = 0;
  std::vector<Vec2> polyline;
  bool closed = false;
  std::optional<MotionSpec> motion;
};

/// A solver's own block of the scene, as its plug-in parsed it (apps/solvers/<type>/).
struct SolverSpec {
  virtual ~SolverSpec() = default;
};

/// The fluid block: `type` names the plug-in, `spec` holds what that plug-in read.
struct FluidBlock {
  std::string type;
  int line = 0;
  std::shared_ptr<const SolverSpec> spec;
  template <class T> const T& as() const { return dynamic_cast<const T&>(*spec); }
};

/// One entry of `structures`.
struct StructureBlock {
  std::string type;
  std::string name;
  int line = 0;
  std::string key; ///< its path in messages, `structures[0]` (as `--set` spells it)
  std::shared_ptr<const SolverSpec> spec;
  template <class T> const T& as() const { return dynamic_cast<const T&>(*spec); }
};

struct CouplingSpec {
  coupling::CouplingOptions options; ///< declared once, by coupling/ (visit_options)
  int line = 0;                      ///< scene line of the block
  // Recording and one-way replay (interface.h5, see output/interface_history.hpp).
  bool record_interface = false;  ///< write DIR/interface.h5
  std::filesystem::path motion{}; ///< a scheme that replays a motion: the recorded motion
  std::filesystem::path loads{};  ///< a scheme that replays loads: the recorded loads
};

/// Periodic checkpoints (docs/reliability.md): DIR/checkpoint_<step>.h5 after every
/// interval_steps steps and/or every interval_minutes of wall time, the newest `keep` kept.
struct CheckpointSpec {
  std::optional<long> interval_steps;
  std::optional<double> interval_minutes;
  int keep = 2;
  int line = 0;
};

struct Scene {
  std::filesystem::path path;
  std::string name;
  int dimension = 2; ///< 2 or 3: points, vectors and meshes of this dimension
  TimeSpec time;
  Vec2 gravity = Vec2::Zero();
  Vec3 gravity3 = Vec3::Zero(); ///< dimension 3
  OutputSpec output;
  std::optional<FluidBlock> fluid;
  std::vector<WallSpec> walls;
  std::vector<StructureBlock> structures;
  std::optional<CouplingSpec> coupling;
  std::optional<CheckpointSpec> checkpoint; ///< absent: checkpoints only on SIGINT/SIGTERM
  std::vector<std::string> overrides;       ///< `key=value` as given on the command line
  /// FNV-1a of the scene tree after the overrides, without time.end (the one key a restart may
  /// change): a restart of an edited scene is refused (issue 41).
  std::uint64_t digest = 0;
};

/// `FILE:LINE: KEY: what` for problems found after parsing (e.g. while building a mesh).
[[noreturn]] void fail_at(const Scene& scene, int line, const std::string& key,
                          const std::string& what);

/// Reads and validates a scene file with `--set key.path=value` overrides applied first.
/// Throws fsi::InputError (`FILE:LINE: KEY: what`) on the first problem.
Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides);

/// The same for scene text already in memory; `file` names it in messages and relative paths
/// resolve against its directory.
Scene parse_scene(const std::string& text, const std::filesystem::path& file,
                  const std::vector<std::string>& overrides);

/// The scene-file reference (Markdown), generated from the same declarations load_scene uses.
std::string scene_reference();

} // namespace fsi::app
