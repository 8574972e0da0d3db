#pragma once
// Shared set-up of the cantilever tests: a beam [0, L] x [0, h] clamped on "left", loaded by a
// uniform dead shear traction on "right" (total force -P per unit thickness).
#include <cmath>
#include <stdexcept>

#include "structure_fem/loads.hpp"
#include "structure_fem/rectangle_mesher.hpp"
#include "structure_fem/structure.hpp"

namespace fem_test {

using namespace fsi::fem;

struct Beam {
  double L = 1.0, h = 0.1;
  double E = 2.1e11, nu = 0.3, rho = 7800.0;
  PlaneModel plane = PlaneModel::plane_strain;
  int ex = 40, ey = 4;
};

inline Mesh beam_mesh(const Beam& b) {
  RectangleMeshOptions m;
  m.width = b.L, m.height = b.h, m.elements_x = b.ex, m.elements_y = b.ey;
  return make_rectangle_mesh(m);
}

inline StructureOptions beam_options(const Beam& b) {
  StructureOptions o;
  o.material.youngs_modulus = b.E;
  o.material.poisson_ratio = b.nu;
  o.material.density = b.rho;
  o.material.plane = b.plane;
  o.clamped = {{"left", true, true, {}}};
  return o;
}

inline int node_at(const Mesh& mesh, const fsi::Vec2& x) {
  for (std::size_t k = 0; k < mesh.num_nodes(); ++k)
    if ((mesh.X[k] - x).norm() < 1e-9) return static_cast<int>(k);
  throw std::runtime_error("no node at the requested point");
}

/// Mid-height node of the free end.
inline int tip_node(const Mesh& mesh, const Beam& b) {
  return node_at(mesh, {b.L, 0.5 * b.h});
}

/// Tip load P (downwards) as a uniform shear traction on the free end.
inline Vector tip_load(const Mesh& mesh, const Beam& b, double P) {
  return edge_traction_forces(mesh, "right", {0.0, -P / b.h});
}

/// Effective in-plane modulus: E / (1 - nu^2) in plane strain, E in plane stress.
inline double bending_modulus(const Beam& b) {
  return b.plane == PlaneModel::plane_strain ? b.E / (1.0 - b.nu * b.nu) : b.E;
}

/// Timoshenko beam: tip deflection P L^3 / (3 E' I) + P L / (kappa G A), kappa = 5/6.
inline double timoshenko_tip_deflection(const Beam& b, double P) {
  const double I = b.h * b.h * b.h / 12.0, A = b.h, G = b.E / (2.0 * (1.0 + b.nu));
  return P * b.L * b.L * b.L / (3.0 * bending_modulus(b) * I) + P * b.L / (5.0 / 6.0 * G * A);
}

/// Static tip deflection (positive downwards) of the mid-height tip node under P.
inline double static_tip_deflection(const Beam& b, double P,
                                    LinearSolverKind solver = LinearSolverKind::cholmod) {
  auto options = beam_options(b);
  options.linear_solver.kind = solver;
  Structure s(beam_mesh(b), options);
  s.set_external_forces(tip_load(s.mesh(), b, P));
  s.solve_static();
  return -s.displacement()[2 * tip_node(s.mesh(), b) + 1];
}

} // namespace fem_test
