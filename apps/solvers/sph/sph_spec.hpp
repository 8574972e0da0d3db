#pragma once
// The SPH fluid's scene block (fluid.type: sph), as the plug-in reads it. Keys that mean what the
// EMPS fluid's keys mean carry the same names (density, viscosity, l0, sound_speed, regions,
// domain, damping_time), so one scene runs with either fluid by `--set fluid.type=...`.
#include "fluid_sph/options.hpp"
#include "fsi_app/fluid_regions.hpp"
#include "fsi_app/scene.hpp"
#include "fsi_app/scene_reader.hpp"

#include <memory>
#include <string>
#include <vector>

namespace fsi::app::sph_plugin {

struct SphSpec final : SolverSpec {
  double density = 1000.0;  ///< rho0, kg/m^3
  double viscosity = 0.0;   ///< kinematic nu, m^2/s
  double l0 = 0.0;          ///< initial particle spacing dp, m
  double sound_speed = 0.0; ///< c0 of p = c0^2 (rho - rho0) (eq. 2), m/s
  double h_over_dp = 1.3;   ///< h / dp
  std::string correction;   ///< none | rkgc
  double wkgc_alpha = 0.3;  ///< alpha of eq. 22
  bool free_surface = true; ///< density re-initialisation kind
  bool transport_velocity = false;
  double u_ref = 0.0; ///< reference speed of the advection criterion (0: sound_speed / 10)
  double advection_cfl = 0.25, acoustic_cfl = 0.6;
  int interface_layers = 4;            ///< rows of boundary points behind a structure's interface
  bool interface_acceleration = false; ///< the interface's mean acceleration in eq. 16
  double damping_time = 0.0;
  bool riemann_limiter = true; ///< eq. 5's limiter; false: beta = 1 (settling flows)
  sph::Inflow inflow;          ///< channel inflow buffer (the domain then wraps in x)
  ParticleArea area;           ///< without a domain: walls and regions with a margin of 8 l0
};

/// Reads the keys of the fluid block (type excepted) into an SphSpec. A key of another fluid
/// type is an error naming it and that type.
std::shared_ptr<const SolverSpec> read_sph(Section& s);

} // namespace fsi::app::sph_plugin
