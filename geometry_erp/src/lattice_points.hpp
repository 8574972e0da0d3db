#pragma once
// The points of the D-dimensional cubic lattice around a particle, for the lattice constants
// (wall_weight.cpp: n0, lambda0) and the lattice's operator spectra (lattice_spectrum.cpp).
#include <array>
#include <cmath>

namespace fsi::erp {

/// Lattice index bound that covers every point within r_e.
inline int reach(double l0, double r_e) {
  return static_cast<int>(std::ceil(r_e / l0)) + 1;
}

/// f(m, r) for every point x_j = l0 m != 0 of the lattice of spacing l0 within the cube of
/// half-width reach(l0, r_e), r = |x_j| (x fastest, then y, then z).
template <int D, class F> void for_each_lattice_point(double l0, double r_e, F&& f) {
  const int n = reach(l0, r_e);
  if constexpr (D == 2) {
    for (int j = -n; j <= n; ++j)
      for (int i = -n; i <= n; ++i)
        if (i != 0 || j != 0) f(std::array<int, 2>{i, j}, std::hypot(i * l0, j * l0));
  } else {
    for (int k = -n; k <= n; ++k)
      for (int j = -n; j <= n; ++j)
        for (int i = -n; i <= n; ++i)
          if (i != 0 || j != 0 || k != 0)
            f(std::array<int, 3>{i, j, k}, std::hypot(i * l0, j * l0, k * l0));
  }
}

} // namespace fsi::erp
