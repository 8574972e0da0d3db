// Building the 3-D SPH fluid's moving boundary on a large interface mesh (InterfaceBoundary3):
// the top face of a T10 plate 0.2 x 0.2 x 0.02 m in n x n x 1 cells (2 n^2 six-node faces, as
// data/scenes/hydrostatic_plate_3d.yaml's structure), dp = 0.2 m / 40, four layers, and the
// signed distance of the fill's 40 x 40 x 8 lattice above and below it at the reference positions
// (SphModel3's fill test) through the grid of faces and by the scan over all faces. Counter
// faces: the mesh's face count.
#include "fluid_sph/interface_boundary3.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/interface_mesh.hpp"

#include <benchmark/benchmark.h>

using namespace fsi;

namespace {

InterfaceMesh3 plate_top(int n) {
  fem::BoxMeshOptions o;
  o.origin = Vec3(0.0, 0.0, -0.02), o.size = Vec3(0.2, 0.2, 0.02), o.cells = {n, n, 1};
  return fem::interface_of(fem::make_box_mesh(o), {"z_max"}).mesh;
}

constexpr double dp = 0.005;

std::vector<Vec3> lattice() {
  std::vector<Vec3> q;
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 40; ++j)
      for (int i = 0; i < 40; ++i) q.emplace_back((i + 0.5) * dp, (j + 0.5) * dp, (k - 3.5) * dp);
  return q;
}

void build(benchmark::State& state) {
  const InterfaceMesh3 m = plate_top(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const sph::InterfaceBoundary3 b(m, dp, 4);
    benchmark::DoNotOptimize(b.size());
  }
  state.counters["faces"] = static_cast<double>(m.faces.size());
}

void fill(benchmark::State& state, bool grid) {
  const InterfaceMesh3 m = plate_top(static_cast<int>(state.range(0)));
  const sph::InterfaceBoundary3 b(m, dp, 4);
  const std::vector<Vec3> q = lattice();
  for (auto _ : state) {
    double sum = 0.0;
    for (const Vec3& p : q) sum += grid ? b.signed_distance(p) : b.signed_distance(m.X0, p);
    benchmark::DoNotOptimize(sum);
  }
  state.counters["faces"] = static_cast<double>(m.faces.size());
}

} // namespace

BENCHMARK(build)->Arg(10)->Arg(40)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(fill, grid, true)->Arg(10)->Arg(40)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(fill, all_faces, false)->Arg(10)->Arg(40)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
