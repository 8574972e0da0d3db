#pragma once
// The hydrostatic plate (Fourey et al. 2017; data/scenes/hydrostatic_plate.yaml) as a 2D
// plane-strain continuum: 1 x 0.05 m aluminium, both ends clamped, its own weight and the 2 m
// water column's rho_f g H on top. The scenes' acceptance value -6.85e-5 m is the clamped
// Euler-Bernoulli strip, q L^4 / (384 D); a continuum also shears, q L^2 / (8 kappa G h)
// (Timoshenko, kappa = 5/6), +3.6 % at h/L = 1/20.
#include <cmath>

#include "cantilever.hpp"

namespace fem_test {

struct Plate {
  double L = 1.0, h = 0.05, E = 6.75e10, nu = 0.34, rho_s = 2700.0;
  double g = 9.81, rho_f = 1000.0, H = 2.0;
  double q() const { return g * (rho_f * H + rho_s * h); } // load per unit area [Pa]
  double D() const { return E * h * h * h / (12.0 * (1.0 - nu * nu)); }
  double euler_bernoulli() const { return q() * std::pow(L, 4) / (384.0 * D()); }
  double shear() const { return q() * L * L / (8.0 * 5.0 / 6.0 * E / (2.0 * (1.0 + nu)) * h); }
  /// First clamped-clamped bending mode, (4.7300 / L)^2 sqrt(D / (rho_s h)) [rad/s].
  double omega1() const {
    const double kL = 4.730040744862704;
    return kL * kL / (L * L) * std::sqrt(D() / (rho_s * h));
  }
};

inline Mesh plate_mesh(const Plate& p, int ex, int ey) {
  RectangleMeshOptions m;
  m.width = p.L, m.height = p.h, m.elements_x = ex, m.elements_y = ey;
  return make_rectangle_mesh(m);
}

inline Vector water_load(const Mesh& mesh, const Plate& p) {
  return edge_traction_forces(mesh, "top", {0.0, -p.g * p.rho_f * p.H});
}

/// Static mid-span centre-line deflection (positive downwards) of the FE plate, ex x ey quads.
inline double fem_mid_span(const Plate& p, int ex, int ey) {
  StructureOptions o;
  o.material.youngs_modulus = p.E;
  o.material.poisson_ratio = p.nu;
  o.material.density = p.rho_s;
  o.material.plane = PlaneModel::plane_strain;
  o.gravity = {0.0, -p.g};
  o.clamped = {{"left", true, true, {}}, {"right", true, true, {}}};
  o.linear_solver.kind = LinearSolverKind::cholmod;
  Structure s(plate_mesh(p, ex, ey), o);
  s.set_external_forces(water_load(s.mesh(), p));
  s.solve_static();
  return -s.displacement()[2 * node_at(s.mesh(), {0.5 * p.L, 0.5 * p.h}) + 1];
}

} // namespace fem_test
