// Large deformation: a cantilever under a dead end load P (k = P L^2 / EI = 1, 2, 5) against
// Euler's elastica (inextensible, shear-free), measured as structure_fem's elastica test
// measures it: the mid-height point of the free end, deflection v and shortening u over L.
// The test beam is slender enough for Euler's elastica to describe it (L/H = 20: its converged
// FE solution is within a few tenths of a percent, asserted below); the thick beam (L/H = 10) is
// checked against the FE solution of the same continuum, its distance from Euler's elastica
// printed. Static solutions by dynamic relaxation (mass damping 2 omega_1, critical for the
// first mode), each load from the last equilibrium, stopped when the end point has settled.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "../structure_fem/cantilever.hpp"
#include "common.hpp"

using namespace tlsph_test;

namespace {

const std::vector<double> loads{1.0, 2.0, 5.0}; // k = P L^2 / EI

/// L = 1, H = L / slenderness, nu = 0, plane stress, EI = 1 (E = 12 / H^3).
Beam elastic_beam(double slenderness, int layers) {
  Beam b;
  b.L = 1.0, b.H = b.L / slenderness, b.nu = 0.0, b.rho = 1000.0;
  b.E = 12.0 / (b.H * b.H * b.H);
  b.plane = fsi::materials::PlaneModel::plane_stress;
  b.layers = layers;
  return b;
}

/// End point (v, u) over L: deflection and shortening.
struct EndPoint {
  double v, u;
};

EndPoint euler(double k) {
  const Vec2 p = elastica_point(k, 1.0);
  return {p.y(), 1.0 - p.x()};
}

double rel(double a, double ref) {
  return a / ref - 1.0;
}

/// structure_fem's T6 solution of the same beam (ey layers of quads through the thickness,
/// square ones), the mid-height node of the free end.
std::vector<EndPoint> fem_end_points(const Beam& b, int ey) {
  fem_test::Beam fb;
  fb.L = b.L, fb.h = b.H, fb.E = b.E, fb.nu = b.nu, fb.rho = b.rho, fb.plane = b.plane;
  fb.ey = ey, fb.ex = static_cast<int>(std::lround(ey * b.L / b.H));
  fsi::fem::Structure s(fem_test::beam_mesh(fb), fem_test::beam_options(fb));
  const int tip = fem_test::tip_node(s.mesh(), fb);
  const auto start = s.save();
  std::vector<EndPoint> out;
  for (const double k : loads) {
    s.restore(start);
    s.set_external_forces(fem_test::tip_load(s.mesh(), fb, k)); // P = k with EI = L = 1
    s.solve_static({static_cast<int>(std::ceil(2 * k))});
    out.push_back({-s.displacement()[2 * tip + 1], -s.displacement()[2 * tip]});
  }
  return out;
}

/// TL-SPH with the library's defaults, the load on the tip column, each k relaxed from the
/// last equilibrium until the end point moves by < 1e-6 of itself per 1 / omega_1.
std::vector<EndPoint> tlsph_end_points(const Beam& b, int* chunks = nullptr) {
  auto o = beam_options(b);
  o.mass_damping = 2.0 * b.omega1();
  TlsphSolid s(beam_geometry(b), o);
  const auto tip = tip_column(s, b);
  std::vector<EndPoint> out;
  if (chunks) *chunks = 0;
  for (const double k : loads) {
    std::vector<Vec2> f(s.size(), Vec2::Zero());
    for (const auto i : tip) f[i] = Vec2(0.0, -k / static_cast<double>(tip.size())); // EI = L = 1
    s.set_external_forces(f);
    const int n = relax_until(
        s, b.omega1(), [&](const TlsphSolid& t) { return end_face_displacement(t, b); }, 1e-6);
    REQUIRE(n > 0);
    if (chunks) *chunks += n;
    const Vec2 u = end_face_displacement(s, b);
    out.push_back({-u.y(), -u.x()});
  }
  return out;
}

/// Least-squares slope of log |e| against log(H/dp).
double observed_order(const std::vector<int>& layers, const std::vector<double>& e) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(e.size());
  for (std::size_t i = 0; i < e.size(); ++i) {
    const double x = std::log(layers[i]), y = std::log(std::abs(e[i]));
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return -(n * sxy - sx * sy) / (n * sxx - sx * sx);
}

} // namespace

TEST_CASE("tlsph: elastica reference reproduces Mattiasson's tip values",
          "[solid_tlsph][elastica]") {
  const Vec2 k1 = elastica_point(1.0, 1.0), k10 = elastica_point(10.0, 1.0);
  CHECK_THAT(k1.y(), Catch::Matchers::WithinAbs(0.30172, 2e-5));
  CHECK_THAT(1.0 - k1.x(), Catch::Matchers::WithinAbs(0.05643, 2e-5));
  CHECK_THAT(k10.y(), Catch::Matchers::WithinAbs(0.81061, 2e-5));
  CHECK_THAT(1.0 - k10.x(), Catch::Matchers::WithinAbs(0.55500, 2e-5));
}

TEST_CASE("tlsph: the elastica test beam (L/H = 20) is one Euler's elastica describes: its "
          "converged FE solution within 0.6 %; the thick beam (L/H = 10) is not",
          "[solid_tlsph][elastica]") {
  const auto coarse = fem_end_points(elastic_beam(20.0, 8), 4),
             fine = fem_end_points(elastic_beam(20.0, 8), 8),
             thick = fem_end_points(elastic_beam(10.0, 8), 8);
  for (std::size_t i = 0; i < loads.size(); ++i) {
    const EndPoint e = euler(loads[i]);
    INFO("k = " << loads[i] << ": FEM L/H = 20 (T6 160 x 8) v " << fine[i].v << " ("
                << rel(fine[i].v, e.v) << " vs Euler), u " << fine[i].u << " ("
                << rel(fine[i].u, e.u) << "); 80 x 4 vs 160 x 8: v " << rel(coarse[i].v, fine[i].v)
                << ", u " << rel(coarse[i].u, fine[i].u) << "; L/H = 10 (T6 80 x 8) v "
                << rel(thick[i].v, e.v) << ", u " << rel(thick[i].u, e.u));
    // Converged: halving the elements moves the end point by < 0.05 %.
    CHECK_THAT(coarse[i].v, Catch::Matchers::WithinRel(fine[i].v, 5e-4));
    CHECK_THAT(coarse[i].u, Catch::Matchers::WithinRel(fine[i].u, 5e-4));
    CHECK_THAT(fine[i].v, Catch::Matchers::WithinRel(e.v, 6e-3));
    CHECK_THAT(fine[i].u, Catch::Matchers::WithinRel(e.u, 6e-3));
    // The thick continuum's shortening is measurably off Euler's (shear, stretch, 25 % strain).
    CHECK(rel(thick[i].u, e.u) > 0.008);
  }
}

TEST_CASE("tlsph: elastica within 2 % of Euler's at H/dp = 10 (L/H = 20, k = 1, 2, 5); observed "
          "order over H/dp = 6, 8, 10 against the FE solution of the same beam",
          "[solid_tlsph][elastica][slow]") {
  // At H/dp = 8 the shortening at k = 1 is +2.27 % of Euler's, +1.91 % of the FE solution of
  // this beam: 2 % is met from H/dp = 10 (docs/solid_tlsph.md, "Elastica").
  const std::vector<int> layers{6, 8, 10};
  std::vector<std::vector<EndPoint>> sph;
  int chunks = 0;
  for (const int n : layers)
    sph.push_back(tlsph_end_points(elastic_beam(20.0, n), n == 10 ? &chunks : nullptr));
  const auto fem = fem_end_points(elastic_beam(20.0, 8), 8);
  for (std::size_t i = 0; i < loads.size(); ++i) {
    const EndPoint e = euler(loads[i]), p8 = sph[1][i], p = sph[2][i];
    std::vector<double> ev, eu;
    for (const auto& r : sph)
      ev.push_back(rel(r[i].v, fem[i].v)), eu.push_back(rel(r[i].u, fem[i].u));
    const double pv = observed_order(layers, ev), pu = observed_order(layers, eu);
    INFO("k = " << loads[i] << ", H/dp = 10: v " << p.v << " (Euler " << e.v << ", "
                << rel(p.v, e.v) << "), u " << p.u << " (Euler " << e.u << ", " << rel(p.u, e.u)
                << "); H/dp = 8: v " << rel(p8.v, e.v) << ", u " << rel(p8.u, e.u)
                << " vs Euler; vs FEM at H/dp = 6, 8, 10: v " << ev[0] << ", " << ev[1] << ", "
                << ev[2] << " (order " << pv << "), u " << eu[0] << ", " << eu[1] << ", " << eu[2]
                << " (order " << pu
                << "); relaxation chunks (1 / omega_1) at H/dp = 10: " << chunks);
    CHECK_THAT(p.v, Catch::Matchers::WithinRel(e.v, 0.02));
    CHECK_THAT(p.u, Catch::Matchers::WithinRel(e.u, 0.02));
    CHECK(pv > 1.5);
    CHECK(pu > 1.5);
  }
}

TEST_CASE("tlsph: thick elastica beam (L/H = 10) within 2 % of the FE solution of the same "
          "continuum at H/dp = 8",
          "[solid_tlsph][elastica][slow]") {
  const auto sph = tlsph_end_points(elastic_beam(10.0, 8));
  const auto fem = fem_end_points(elastic_beam(10.0, 8), 8);
  for (std::size_t i = 0; i < loads.size(); ++i) {
    const EndPoint e = euler(loads[i]);
    INFO("k = " << loads[i] << ": v " << sph[i].v << " (FEM " << fem[i].v << ", "
                << rel(sph[i].v, fem[i].v) << "; Euler " << rel(sph[i].v, e.v) << "), u "
                << sph[i].u << " (FEM " << fem[i].u << ", " << rel(sph[i].u, fem[i].u) << "; Euler "
                << rel(sph[i].u, e.u) << ")");
    CHECK_THAT(sph[i].v, Catch::Matchers::WithinRel(fem[i].v, 0.02));
    CHECK_THAT(sph[i].u, Catch::Matchers::WithinRel(fem[i].u, 0.02));
  }
}
