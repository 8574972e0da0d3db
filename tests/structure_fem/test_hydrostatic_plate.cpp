// The hydrostatic plate's continuum deflection: the FE ladder and CalculiX (CPE6, same mesh and
// loads) give the plane-strain plate's own mid-span deflection (hydrostatic_plate.hpp).
#include <catch2/catch.hpp>

#include "calculix.hpp"
#include "hydrostatic_plate.hpp"

using namespace fem_test;

namespace {

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
