#pragma once
// The FE structure's scene entry (structures[].type: fem), as the plug-in reads it.
#include "fsi_app/scene.hpp"
#include "fsi_app/scene_reader.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace fsi::app::fem_plugin {

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

struct StructureSpec final : SolverSpec {
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

/// Reads the keys of one structures entry (type and name excepted) into a StructureSpec.
std::shared_ptr<const SolverSpec> read_structure(Section& s);

} // namespace fsi::app::fem_plugin
