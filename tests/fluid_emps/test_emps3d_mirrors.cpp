// The ERP pressure gradient of the 3-D walls at rest (#43): on a lattice filling a closed box of
// triangles, the fluid sum (eq. 10) and the wall mirrors (eqs. 25-26) under a given pressure field
// against its exact gradient, by the number of walls within r_e (faces, concave edges, corners).
#include "fluid_emps/space_wall_terms.hpp"
#include "geometry_erp/box_walls.hpp"
#include "test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace fsi;

namespace {

/// <grad p>_i of every particle of a lattice at rest filling [0, L]^3 (L = n l0, l0 = 0.01 m)
/// under the pressure field p(x): the fluid sum (eq. 10) and the face mirrors (eqs. 25-26), with
/// or without the images behind two and three walls (SpaceWallTerms::corner_mirror_pressure).
std::vector<Vec3> lattice_gradient(int n, const std::function<double(const Vec3&)>& p_of,
                                   bool corner_images, std::vector<Vec3>& x, double& r_e) {
  const double l0 = 0.01, L = n * l0;
  const emps::FluidOptions3 o = emps::test::water<3>(l0, -0.05, 0.15);
  r_e = o.r_e();
  const double n0 = erp::lattice_n0<3>(l0, r_e, particles::MpsWeight(r_e));
  erp::TriangleWallSet walls;
  erp::add_box_tank(walls, Vec3::Zero(), Vec3::Constant(L), false, 0);
  x = emps::test::block(n, n, n, l0);
  emps::Particles3 p;
  p.resize(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (int a = 0; a < 3; ++a) p.position[a][i] = x[i][a];
    p.p[i] = p_of(x[i]);
  }
  particles::BasicCellGrid<3> grid(o.domain_min, o.domain_max, 1.1 * r_e);
  grid.bin(p.position.coords(), p.size());
  const erp::TriangleLocator locator(walls, r_e);
  emps::SpaceHits hits;
  erp::ConvexFaces convex; // a tank has no convex edge
  emps::test::query_faces(locator, p, hits, convex);
  const emps::SpaceWallTerms terms(o, n0, p, grid, hits, convex);
  const particles::MpsWeight w(r_e);
  std::vector<Vec3> grad(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    Vec3 fluid = Vec3::Zero(); // eq. 10 over every other particle
    for (std::size_t j = 0; j < x.size(); ++j) {
      const Vec3 d = x[j] - x[i];
      const double r2 = d.squaredNorm();
      if (j != i && r2 < r_e * r_e) fluid += (p.p[j] + p.p[i]) * w.inside(std::sqrt(r2)) / r2 * d;
    }
    grad[i] = 3.0 / n0 * fluid;
    for (std::size_t k = 0; k < emps::max_faces3; ++k)
      if (hits[k].triangle[i] >= 0) grad[i] += terms.mirror_pressure(i, k);
    if (corner_images) grad[i] += terms.corner_mirror_pressure(i);
  }
  return grad;
}

/// Worst |<grad p>_i - grad p| / rho g over the particles with 0, 1, 2, 3 walls within r_e (see
/// lattice_gradient). With `vertical` only the walls x = 0, L and y = 0, L count and particles
/// within r_e of the floor or the lid are left out.
std::array<double, 4> gradient_residual(int n, const std::function<double(const Vec3&)>& p_of,
                                        const Vec3& grad_p, bool corner_images,
                                        bool vertical = false) {
  const double L = n * 0.01, rho_g = 1000.0 * 9.81;
  std::vector<Vec3> x;
  double r_e = 0;
  const std::vector<Vec3> grad = lattice_gradient(n, p_of, corner_images, x, r_e);
  std::array<double, 4> worst{};
  for (std::size_t i = 0; i < x.size(); ++i) {
    const bool lid_or_floor = std::min(x[i][2], L - x[i][2]) < r_e;
    if (vertical && lid_or_floor) continue;
    const int walls_near = emps::test::walls_near(x[i], L, r_e);
    const auto near = static_cast<std::size_t>(std::min(walls_near, 3));
    worst[near] = std::max(worst[near], (grad[i] - grad_p).norm() / rho_g);
  }
  return worst;
}

} // namespace

TEST_CASE("emps 3-D walls: at rest under a uniform pressure the ERP gradient vanishes at faces, "
          "edges and corners only with the images behind two and three walls",
          "[emps][walls3d]") {
  const double P = 1000.0 * 9.81 * 0.1; // rho g L
  const auto uniform = [&](const Vec3&) { return P; };
  const std::array<double, 4> with = gradient_residual(10, uniform, Vec3::Zero(), true);
  const std::array<double, 4> without = gradient_residual(10, uniform, Vec3::Zero(), false);
  INFO("worst |<grad p>_i| / rho g with 0, 1, 2, 3 walls near: with the images "
       << with[0] << ", " << with[1] << ", " << with[2] << ", " << with[3] << "; without "
       << without[0] << ", " << without[1] << ", " << without[2] << ", " << without[3]);
  for (const double e : with) CHECK(e < 1e-10);
  CHECK(without[1] < 1e-10); // one face: its mirror images all of the missing half
  CHECK(without[2] > 1.0);   // an edge: the quadrant behind both walls pushes on no one
  CHECK(without[3] > 1.0);   // a corner: the quadrants and the octant
}

TEST_CASE("emps 3-D walls: at rest under a hydrostatic pressure the ERP gradient balances rho g "
          "beside the vertical walls, their edges included (eq. 26's p_i' = p_i is not hydrostatic "
          "at the floor)",
          "[emps][walls3d]") {
  const double rho_g = 1000.0 * 9.81, H = 0.1;
  const auto hydrostatic = [&](const Vec3& x) { return rho_g * (H - x[2]); };
  const std::array<double, 4> with =
      gradient_residual(10, hydrostatic, Vec3(0, 0, -rho_g), true, true);
  const std::array<double, 4> without =
      gradient_residual(10, hydrostatic, Vec3(0, 0, -rho_g), false, true);

  INFO("worst |<grad p>_i - grad p| / rho g with 0, 1, 2, 3 walls near: with the images "
       << with[0] << ", " << with[1] << ", " << with[2] << ", " << with[3] << "; without "
       << without[0] << ", " << without[1] << ", " << without[2] << ", " << without[3]);
  for (std::size_t k = 0; k < 3; ++k) CHECK(with[k] < 1e-10); // none has three vertical walls
  CHECK(without[1] < 1e-10);
  CHECK(without[2] > 1.0);
}

TEST_CASE("emps 3-D walls: at rest under a hydrostatic pressure the floor's rows lack the same "
          "support beside the side walls as in the floor's interior (the images behind two and "
          "three walls add no imbalance of their own)",
          "[emps][walls3d]") {
  const double rho_g = 1000.0 * 9.81, H = 0.1, l0 = 0.01;
  std::vector<Vec3> x;
  double r_e = 0;
  const std::vector<Vec3> grad = lattice_gradient(
      10, [&](const Vec3& y) { return rho_g * (H - y[2]); }, true, x, r_e);
  // (<grad p>_z + rho g) / rho g, and the largest horizontal residual, per row above the floor
  // (0, 1, 2) and per number of side walls within r_e (0, 1, 2)
  std::array<std::array<double, 3>, 3> lo{}, hi{};
  for (auto& row : lo) row.fill(1e300);
  for (auto& row : hi) row.fill(-1e300);
  double horizontal = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const auto row = static_cast<std::size_t>(x[i][2] / l0);
    if (row > 2) continue;
    std::size_t sides = 0;
    for (int a = 0; a < 2; ++a) sides += std::min(x[i][a], H - x[i][a]) < r_e ? 1 : 0;
    const double e = (grad[i][2] + rho_g) / rho_g;
    lo[row][sides] = std::min(lo[row][sides], e);
    hi[row][sides] = std::max(hi[row][sides], e);
    horizontal = std::max(horizontal, std::hypot(grad[i][0], grad[i][1]) / rho_g);
  }
  INFO("bottom row: " << lo[0][0] << ", " << lo[0][1] << ", " << lo[0][2] << "; second row: "
                      << lo[1][0] << "; third row: " << lo[2][0] << "; horizontal " << horizontal);
  CHECK(horizontal < 1e-10);
  for (std::size_t row = 0; row < 3; ++row)
    for (std::size_t sides = 0; sides < 3; ++sides) {
      CHECK(hi[row][sides] - lo[row][sides] < 1e-10);       // uniform along the row
      CHECK(std::abs(lo[row][sides] - lo[row][0]) < 1e-10); // edges and corners as the interior
    }
  // eq. 26's copy p_i' = p_i: the floor's rows are held up by less than rho g (0.43 rho g on the
  // bottom row), the deficit falling away from the floor (a run carries it by compression and
  // eq. 27; docs/fluid_emps.md "3-D")
  CHECK(lo[0][0] > lo[1][0]);
  CHECK(lo[1][0] > 10 * std::abs(lo[2][0]));
  CHECK(std::abs(lo[2][0]) < 1e-3);
}

TEST_CASE("emps 3-D walls: eq. 10 is blind to a pressure alternating layer by layer in the bulk, "
          "not at the floor (the hydrostatic tank's layered mode, docs/fluid_emps.md)",
          "[emps][walls3d]") {
  // p = rho g L (-1)^k on layer k (z = (k + 1/2) l0) of the lattice filling the closed box: the
  // neighbours at +-m l0 above and below carry the same pressure, so eq. 10's sum cancels in
  // pairs wherever the support is whole; the floor's mirror (eq. 26: the image of layer k
  // carries layer k's pressure) breaks that symmetry.
  const double rho_g = 1000.0 * 9.81, l0 = 0.01, L = 0.1;
  const auto layer = [&](const Vec3& y) { return static_cast<int>(y[2] / l0); };
  std::vector<Vec3> x;
  double r_e = 0;
  const std::vector<Vec3> grad = lattice_gradient(
      10, [&](const Vec3& y) { return rho_g * L * (layer(y) % 2 == 0 ? 1.0 : -1.0); }, true, x,
      r_e);
  double bulk = 0, bottom = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (emps::test::walls_near(x[i], L, r_e) == 0) bulk = std::max(bulk, grad[i].norm());
    if (layer(x[i]) == 0) bottom += grad[i][2] / (rho_g * L);
  }
  bottom /= 100.0; // the bottom layer's 10 x 10
  INFO("bulk |<grad p>| over rho g " << bulk / rho_g << "; bottom layer's mean <grad p>_z over "
                                     << "rho g L / l0: " << bottom * l0);
  CHECK(bulk / rho_g < 1e-10); // the mode costs no force where the support is whole
  CHECK(bottom * l0 < -0.1);   // the floor feels it: the high bottom layer pushed up, ~ P/l0
}
