// Prints the relative PND error (n_i + z(r) - n0) / n0 of a particle moved off its lattice site,
// the rest of the fluid lattice in place (wall at y = 0, fluid rows at y = l0/2 + k l0, columns
// x = i l0): moved by delta normal to the wall from its site in row k (r = l0/2 + k l0 + delta),
// and in row 0 also moved by s l0 along the wall (z assumes the particle on a column).
// Usage: print_wall_weight_deviation [r_e / l0 ...]   (default 2.1 3.1 4.0)
#include "geometry_erp/wall_weight.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <vector>

using namespace fsi::erp;

int main(int argc, char** argv) {
  std::vector<double> ratios{2.1, 3.1, 4.0};
  if (argc > 1) {
    ratios.clear();
    for (int a = 1; a < argc; ++a) ratios.push_back(std::atof(argv[a]));
  }
  const double l0 = 1.0;
  const int half = 12, rows = 14;
  for (const double ratio : ratios) {
    const double r_e = ratio * l0;
    const fsi::particles::MpsWeight w(r_e);
    const WallWeightTable z(l0, r_e, w);
    const double n0 = lattice_n0(l0, r_e, w);
    std::printf("r_e = %.2f l0, n0 = %.10f, lambda0 = %.10f l0^2\n", ratio, n0,
                lattice_lambda0(l0, r_e, w) / (l0 * l0));
    std::printf(
        "| delta / l0 | r / l0 (row 0) | row 0 | row 1 | row 2 | row 0, s = 0.25 | row 0, s = 0.5 "
        "|\n|---|---|---|---|---|---|---|\n");
    for (const double delta : {-0.4, -0.3, -0.2, -0.1, -0.05, 0.0, 0.05, 0.1, 0.2, 0.3, 0.4}) {
      std::printf("| %+.2f | %.2f |", delta, 0.5 + delta);
      for (const auto& [k, s] : {std::pair{0, 0.0}, {1, 0.0}, {2, 0.0}, {0, 0.25}, {0, 0.5}}) {
        const double r = 0.5 * l0 + k * l0 + delta * l0;
        double n_i = 0.0; // the other particles of the fluid block, own site left empty
        for (int row = 0; row < rows; ++row)
          for (int i = -half; i <= half; ++i)
            if (row != k || i != 0) n_i += w(std::hypot(i * l0 - s * l0, 0.5 * l0 + row * l0 - r));
        std::printf(" %+.3e |", (n_i + z(r) - n0) / n0);
      }
      std::printf("\n");
    }
    std::printf("\n");
  }
  return 0;
}
