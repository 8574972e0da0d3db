// The small-load cantilever solved by CalculiX (CPE6, *STATIC) on the same mesh and loads.
#include <catch2/catch.hpp>

#include <unistd.h>

#include "calculix.hpp"
#include "cantilever.hpp"

using namespace fem_test;

TEST_CASE("fem: cantilever tip deflection agrees with CalculiX", "[structure_fem][calculix]") {
  if (!ccx_available()) {
    WARN("ccx not found: skipped");
    return;
  }
  const Beam b; // L = 1, h = 0.1, plane strain, nu = 0.3, 40 x 4 quads
  const double P = 1.0e4;
  const Mesh mesh = beam_mesh(b);
  const int tip = tip_node(mesh, b);
  const Vector f = tip_load(mesh, b, P);
  const auto ccx =
      run_ccx_static({&mesh, b.E, b.nu, mesh.node_set("left"), f, {tip}}, "cantilever");
  const double ours = static_tip_deflection(b, P);
  const double theirs = -ccx.at(tip).y();
  WARN("tip deflection: structure_fem " << ours << ", CalculiX " << theirs
                                        << ", relative difference " << (ours - theirs) / theirs);
  CHECK_THAT(ours, Catch::Matchers::WithinRel(theirs, 0.005));
}
