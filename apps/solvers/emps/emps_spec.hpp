#pragma once
// The EMPS fluid's scene block (fluid.type: emps), as the plug-in reads it.
#include "fsi_app/scene.hpp"
#include "fsi_app/scene_reader.hpp"

#include <memory>
#include <vector>

namespace fsi::app::emps_plugin {

struct FluidSpec final : SolverSpec {
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

/// Reads the keys of the fluid block (type excepted) into a FluidSpec.
std::shared_ptr<const SolverSpec> read_fluid(Section& s);

} // namespace fsi::app::emps_plugin
