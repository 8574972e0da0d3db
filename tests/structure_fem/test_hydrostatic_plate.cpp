// The hydrostatic plate (Fourey et al. 2017; data/scenes/hydrostatic_plate.yaml) as a 2D
// plane-strain continuum: 1 x 0.05 m aluminium, both ends clamped, its own weight and the 2 m
// water column's rho_f g H on top. The scenes' acceptance value -6.85e-5 m is the clamped
// Euler-Bernoulli strip, q L^4 / (384 D); a continuum also shears, q L^2 / (8 kappa G h)
// (Timoshenko, kappa = 5/6), +3.6 % at h/L = 1/20. Here the FE ladder and CalculiX (CPE6, same
// mesh and loads) give the continuum's own mid-span deflection.
#include <catch2/catch.hpp>

#include <cmath>

#include "calculix.hpp"
#include "cantilever.hpp"

using namespace fem_test;

namespace {

struct Plate {
  double L = 1.0, h = 0.05, E = 6.75e10, nu = 0.34, rho_s = 2700.0;
  double g = 9.81, rho_f = 1000.0, H = 2.0;
  double q() const { return g * (rho_f * H + rho_s * h); } // load per unit area [Pa]
  double D() const { return E * h * h * h / (12.0 * (1.0 - nu * nu)); }
  double euler_bernoulli() const { return q() * std::pow(L, 4) / (384.0 * D()); }
  double shear() const { return q() * L * L / (8.0 * 5.0 / 6.0 * E / (2.0 * (1.0 + nu)) * h); }
};

Mesh plate_mesh(const Plate& p, int ex, int ey) {
  RectangleMeshOptions m;
  m.width = p.L, m.height = p.h, m.elements_x = ex, m.elements_y = ey;
  return make_rectangle_mesh(m);
}

Vector water_load(const Mesh& mesh, const Plate& p) {
  return edge_traction_forces(mesh, "top", {0.0, -p.g * p.rho_f * p.H});
}

/// Mid-span centre-line deflection (positive downwards) of the FE plate, ex x ey quads.
double fem_mid_span(const Plate& p, int ex, int ey) {
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

double ccx_mid_span(const Plate& p, int ex, int ey, const std::string& name) {
  const Mesh mesh = plate_mesh(p, ex, ey);
  const int mid = node_at(mesh, {0.5 * p.L, 0.5 * p.h});
  std::vector<int> fixed = mesh.node_set("left");
  for (int n : mesh.node_set("right")) fixed.push_back(n);
  const auto u =
      run_ccx_static({&mesh, p.E, p.nu, fixed, water_load(mesh, p), {mid}, p.rho_s, -p.g}, name);
  return -u.at(mid).y();
}

} // namespace

TEST_CASE("fem: the hydrostatic plate's continuum deflection agrees with CalculiX and is "
          "Timoshenko's, not Euler-Bernoulli's",
          "[structure_fem][calculix]") {
  const Plate p;
  const double eb = p.euler_bernoulli(), timoshenko = eb + p.shear();
  const int levels[][2] = {{20, 2}, {40, 4}, {80, 8}, {160, 16}};
  double fine = 0.0;
  for (const auto& l : levels) {
    fine = fem_mid_span(p, l[0], l[1]);
    WARN(l[0] << " x " << l[1] << " quads: mid-span " << fine << " m, " << (fine / eb - 1.0) * 100.0
              << " % over Euler-Bernoulli " << eb << ", " << (fine / timoshenko - 1.0) * 100.0
              << " % over Timoshenko " << timoshenko);
  }
  const double ccx = ccx_mid_span(p, 160, 16, "hydrostatic_plate");
  WARN("CalculiX 160 x 16: " << ccx << " m, " << (ccx / eb - 1.0) * 100.0 << " % over E-B");
  CHECK_THAT(fine, Catch::Matchers::WithinRel(ccx, 0.002));
  CHECK_THAT(fine, Catch::Matchers::WithinRel(timoshenko, 0.01));
  CHECK(fine / eb - 1.0 > 0.025); // the shear term the beam formula leaves out
}
