// Surge front of the Riemann-SPH dam break on the EMPS scene's geometry
// (data/scenes/dam_break_rigid.yaml): an a x 2a column, a = 0.1 m, against the left wall of a
// 0.8 m tank, dp = 0.0025 m (3,200 particles), c0 = 20 m/s, rkgc, alpha = 0.3. Writes "t,front"
// CSV to stdout every 2 ms to t = 0.3 s; compare Z = front / a against T = t sqrt(2 g / a) with
// ../shared/ref/martin_moyce_1952_front.csv. Optional argument: dp (m).
#include "dam_break_options.hpp"
#include "fluid_sph/sph_fluid.hpp"

#include <cstdio>
#include <cstdlib>

using namespace fsi;

int main(int argc, char** argv) {
  const double dp = argc > 1 ? std::atof(argv[1]) : 0.0025; // 40 across a; 0.00125: 80
  const sph::SphOptions o = sph::dam_break_options<2>(dp, 20.0, 2.0, {-0.05, -0.05}, {0.85, 0.6});
  const std::vector<sph::WallPolyline> tank{{{{0.0, 0.5}, {0.0, 0.0}, {0.8, 0.0}, {0.8, 0.5}}}};
  sph::SphFluid fluid(o, sph::fill_rectangle({0, 0}, {0.1, 0.2}, o.dp), tank);
  std::printf("t,front\n%.4f,%.6f\n", 0.0, fluid.surge_front());
  for (int k = 1; k <= 150; ++k) {
    fluid.advance_to(0.002 * k);
    std::printf("%.4f,%.6f\n", fluid.time(), fluid.surge_front());
  }
  return 0;
}
