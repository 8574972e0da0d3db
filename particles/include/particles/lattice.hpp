#pragma once
// Cell-centred lattice points filling a box: the initial particles of a box region (the SPH
// fluid's fill_rectangle and fill_box, the TL-SPH solid's fill_box), in 2-D and 3-D.
#include "fsi/core/types.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fsi::particles {

/// The whole lattice layers of spacing dp in [lo, hi] along one axis (a length a hair under a
/// multiple of dp, 1e-9 of dp, keeps its last layer).
inline long lattice_layers(double lo, double hi, double dp) {
  return static_cast<long>(std::floor((hi - lo) / dp + 1e-9));
}

/// Calls visit(p) for the points p = lo + (i + 1/2, j + 1/2[, k + 1/2]) dp inside the box
/// [lo, hi] in order, x fastest: dp/2 from the sides that are whole multiples of dp long. None if
/// a side is shorter than dp. Returns their count.
template <int D, class Visit>
std::size_t for_each_lattice_point(const VecD<D>& lo, const VecD<D>& hi, double dp, Visit visit) {
  std::array<long, D> n{};
  std::size_t total = 1;
  for (int c = 0; c < D; ++c) {
    n[static_cast<std::size_t>(c)] = lattice_layers(lo[c], hi[c], dp);
    if (n[static_cast<std::size_t>(c)] <= 0) return 0;
    total *= static_cast<std::size_t>(n[static_cast<std::size_t>(c)]);
  }
  std::array<long, D> index{};
  for (std::size_t m = 0; m < total; ++m) {
    VecD<D> offset;
    for (int c = 0; c < D; ++c)
      offset[c] = static_cast<double>(index[static_cast<std::size_t>(c)]) + 0.5;
    visit(VecD<D>(lo + dp * offset));
    for (std::size_t c = 0; c < D && ++index[c] == n[c]; ++c) index[c] = 0;
  }
  return total;
}

/// The points of for_each_lattice_point as a list.
template <int D> std::vector<VecD<D>> lattice_box(const VecD<D>& lo, const VecD<D>& hi, double dp) {
  std::size_t total = 1;
  for (int c = 0; c < D; ++c)
    total *= static_cast<std::size_t>(std::max(0L, lattice_layers(lo[c], hi[c], dp)));
  std::vector<VecD<D>> out;
  out.reserve(total);
  for_each_lattice_point<D>(lo, hi, dp, [&out](const VecD<D>& p) { out.push_back(p); });
  return out;
}

} // namespace fsi::particles
