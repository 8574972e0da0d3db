#pragma once
// The FE structure's scene entry (structures[].type: fem), as the plug-in reads it.
#include "fsi_app/scene.hpp"
#include "fsi_app/scene_reader.hpp"
#include "structure_fem/structure.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fsi::app::fem_plugin {

struct MeshSpec {
  std::string kind; ///< rectangle | gmsh (2-D); box | gmsh (3-D)
  Vec2 origin = Vec2::Zero();
  Vec3 origin3 = Vec3::Zero();      ///< box: the corner with the smallest coordinates
  double width = 0.0, height = 0.0; ///< along x, y
  double depth = 0.0;               ///< box: along z
  int elements_x = 0, elements_y = 0;
  int elements_z = 0;               ///< box: hexahedral cells along z (each split into 6 T10)
  std::string diagonals = "rising"; ///< rising | mirrored (fem::Diagonals)
  std::filesystem::path file;
};

struct PointLoadSpec {
  std::string boundary;       ///< boundary tag the load is spread over
  Vec2 force = Vec2::Zero();  ///< N (per unit thickness) in total
  Vec3 force3 = Vec3::Zero(); ///< 3-D: N in total
  double pressure = 0.0;      ///< 3-D: Pa against the outward normal
};

struct StructureSpec final : SolverSpec {
  MeshSpec mesh;
  /// What structure_fem and materials/ declare (visit_options): material, newmark, newton and
  /// the linear solver; gravity and clamped conditions are set from the scene when built.
  fem::StructureOptions options;
  std::vector<std::string> clamped; ///< boundary tags held fixed
  std::vector<std::string> sliding; ///< 3-D: tags sliding in their coordinate plane
  std::string clamped_motion;       ///< wall whose rigid motion the clamped nodes follow
  std::optional<MotionSpec> clamped_rigid_motion; ///< 3-D: the clamped faces' rigid motion
  int clamped_rigid_motion_line = 0;
  std::vector<std::string> interface; ///< boundary tags wetted by the fluid
  std::vector<PointLoadSpec> loads;
};

/// Reads the keys of one structures entry (type and name excepted) into a StructureSpec.
std::shared_ptr<const SolverSpec> read_structure(Section& s);

} // namespace fsi::app::fem_plugin
