#pragma once
// The scene: what one scene file describes, in SI units, after strict validation. Plain data; the
// solvers get their own option structs built from it (apps/src/build_*.cpp), never this.
#include "fsi/core/types.hpp"

#include <filesystem>
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
  std::string quantity;      ///< displacement_x|y, displacement_x|y_tank, surge_front, pressure,
                             ///< mean_pressure, mean_speed, kinetic_energy
  std::string structure;     ///< for displacement probes
  std::optional<int> node;   ///< FE node index, or
  std::optional<Vec2> point; ///< reference position of a node / a fluid point
  std::optional<Vec2> box_min, box_max; ///< mean_pressure: the box averaged over
  std::string part = "total";           ///< wall_force: total|pressure|repulsive|viscous
  int line = 0;                         ///< scene line, for late messages
};

struct OutputSpec {
  double interval = 0.0;           ///< s between frames
  std::vector<std::string> fields; ///< particle and mesh fields written to fields.h5
  std::vector<ProbeSpec> probes;
};

struct MotionSpec {
  std::string kind;            ///< sinusoid | table
  std::string dof;             ///< rotation | x | y
  Vec2 pivot = Vec2::Zero();   ///< rotation centre (reference configuration)
  double amplitude = 0.0;      ///< rad for rotation, m for translation
  double period = 1.0;         ///< s
  double phase = 0.0;          ///< rad
  std::filesystem::path table; ///< CSV time,value (value in the unit of `unit`)
  double table_scale = 1.0;    ///< multiplies the table values into rad or m (unit and scale)
};

struct WallSpec {
  std::string name;
  int line = 0;
  std::vector<Vec2> polyline;
  bool closed = false;
  std::optional<MotionSpec> motion;
};

struct FluidSpec {
  int line = 0;
  double density = 1000.0;                ///< kg/m^3
  double viscosity = 0.0;                 ///< kinematic, m^2/s; 0 skips the viscous loop
  double l0 = 0.0;                        ///< initial particle spacing, m
  double re_over_l0 = 3.1;                ///< effective radius r_e / l0
  double sound_speed = 0.0;               ///< c of eq. 15, m/s
  double beta = 1.0;                      ///< free-surface threshold of eq. 17
  double alpha_rep = 0.0;                 ///< repulsive coefficient of eq. 27, N/m^3
  std::string wall_condition;             ///< no_slip | slip
  std::string wall_density;               ///< added | scaled
  std::string wall_contact = "paper";     ///< paper | damped | viscous
  double wall_damping = 1.0;              ///< damped: rate in units of c / l0
  double wall_viscosity = 0.05;           ///< viscous: alpha of the near-wall pair viscosity
  double artificial_viscosity = 0.0;      ///< alpha of the closing-pair viscosity alpha c l0
  bool corner_faces = true;               ///< a concave corner's second face (z, mirrors)
  bool convex_corners = true;             ///< the solid's wedge in pnd and wall pressure
  std::vector<std::vector<Vec2>> regions; ///< closed polygons filled with particles
  Vec2 domain_min = Vec2::Zero();         ///< particles leaving this box are removed (and counted)
  Vec2 domain_max = Vec2::Zero();
  double damping_time = 0.0; ///< initial velocity damping phase (hydrostatic starts), s
};

struct MeshSpec {
  std::string kind; ///< rectangle | gmsh
  Vec2 origin = Vec2::Zero();
  double width = 0.0, height = 0.0;
  int elements_x = 0, elements_y = 0;
  std::filesystem::path file;
};

struct PointLoadSpec {
  std::string boundary;      ///< boundary tag whose nodes share the force equally
  Vec2 force = Vec2::Zero(); ///< N (per unit thickness) in total
};

struct StructureSpec {
  std::string name;
  int line = 0; ///< scene line of this entry, for messages after parsing
  MeshSpec mesh;
  double youngs_modulus = 0.0, poisson_ratio = 0.0, density = 0.0;
  std::string plane;                  ///< strain | stress
  std::string material_model;         ///< saint_venant_kirchhoff | neo_hookean
  std::vector<std::string> clamped;   ///< boundary tags held fixed
  std::string clamped_motion;         ///< wall whose rigid motion the clamped nodes follow
  std::vector<std::string> interface; ///< boundary tags wetted by the fluid
  double newmark_beta = 0.3025, newmark_gamma = 0.6;
  double newton_tolerance = 1e-8, increment_tolerance = 1e-10;
  int newton_max_iterations = 20;
  int newton_substep_levels = 0; ///< retries of a failed step with 2^level sub-steps
  std::string linear_solver;     ///< cg | cholmod | umfpack | ldlt
  std::vector<PointLoadSpec> loads;
};

struct CouplingSpec {
  std::string scheme;       ///< css | bgs | one_way_fluid | one_way_structure
  std::string predictor;    ///< none | second_order
  std::string acceleration; ///< none | constant | aitken | iqn-ils
  double tolerance = 1e-4;  ///< eq. 69
  int max_iterations = 200;
  double omega = 0.5; ///< initial / constant relaxation
  int reuse = 8;      ///< IQN-ILS: past time steps kept
  bool stop_on_unconverged = false;
  int substeps = 1; ///< fluid steps per structure step
  int line = 0;     ///< scene line of the block
  // Recording and one-way replay (interface.h5, see output/interface_history.hpp).
  bool record_interface = false;  ///< write DIR/interface.h5
  std::filesystem::path motion{}; ///< one_way_fluid: the recorded interface motion
  std::filesystem::path loads{};  ///< one_way_structure: the recorded interface loads
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
  Vec2 gravity = Vec2::Zero();
  TimeSpec time;
  OutputSpec output;
  std::optional<FluidSpec> fluid;
  std::vector<WallSpec> walls;
  std::vector<StructureSpec> structures;
  std::optional<CouplingSpec> coupling;
  std::optional<CheckpointSpec> checkpoint; ///< absent: checkpoints only on SIGINT/SIGTERM
  std::vector<std::string> overrides;       ///< `key=value` as given on the command line
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
