// The hydrostatic plate (hydrostatic_plate.hpp) as a T10 slab one element thick whose faces
// z_min and z_max slide (u_z = 0): plane strain, so its static mid-span deflection must be the
// 2-D plane-strain T6 result of the same problem (issue 44).
#include <catch2/catch.hpp>

#include "hydrostatic_plate.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/loads.hpp"
#include "structure_fem/structure.hpp"

using namespace fsi::fem;
using fem_test::Plate;

TEST_CASE("T10 slab with sliding faces reproduces the plane-strain T6 plate",
          "[structure_fem][t10][plate]") {
  const Plate p;
  const int ex = 80, ey = 8;
  const double t = p.L / ex; // one cell thick, cubes of the x spacing across
  StructureT10Options o;
  o.material = {p.E, p.nu, p.rho_s};
  o.gravity = {0.0, -p.g, 0.0};
  o.clamped = {{"x_min", {true, true, true}, {}},
               {"x_max", {true, true, true}, {}},
               {"z_min", {false, false, true}, {}},
               {"z_max", {false, false, true}, {}}};
  StructureT10 slab(make_box_mesh({{0.0, 0.0, 0.0}, {p.L, p.h, t}, {ex, ey, 1}}), o);
  slab.set_external_forces(face_traction_forces(slab.mesh(), "y_max", [&](const fsi::Vec3&) {
    return fsi::Vec3(0.0, -p.g * p.rho_f * p.H, 0.0);
  }));
  slab.solve_static();
  // The node at (L/2, h/2, t/2): lattice indices (ex, ey, 1) of the half-spacing lattice.
  const int mid = ex + (2 * ex + 1) * (ey + (2 * ey + 1) * 1);
  REQUIRE((slab.mesh().X[mid] - fsi::Vec3(0.5 * p.L, 0.5 * p.h, 0.5 * t)).norm() < 1e-12);
  const double slab_mid = -slab.displacement()[3 * mid + 1];
  const double plane_strain = fem_test::fem_mid_span(p, ex, ey);
  WARN("hydrostatic plate mid-span: T10 slab "
       << ex << " x " << ey << " x 1 cells " << slab_mid << " m, T6 plane strain " << ex << " x "
       << ey << " quads " << plane_strain << " m, relative " << slab_mid / plane_strain - 1.0);
  CHECK_THAT(slab_mid, Catch::Matchers::WithinRel(plane_strain, 0.005));
}
