#include "particles/periodic_grid.hpp"

#include <cmath>
#include <stdexcept>

namespace fsi::particles {

template <int D>
BasicPeriodicGrid<D>::BasicPeriodicGrid(const VecD<D>& lo, const VecD<D>& hi, double cell,
                                        const std::array<bool, D>& periodic)
    : period_(hi - lo), periodic_(periodic) {
  VecD<D> first, inv_side;
  std::array<int, D> n;
  for (int a = 0; a < D; ++a) {
    const auto k = static_cast<std::size_t>(a);
    // Periodic: floor(L / cell) cells of side L / n >= cell. Otherwise one spare cell each side.
    n[k] = periodic[k] ? static_cast<int>(std::floor(period_[a] / cell))
                       : static_cast<int>(std::ceil(period_[a] / cell)) + 2;
    if (periodic[k] && n[k] < 3)
      throw std::invalid_argument("PeriodicGrid: a periodic direction needs >= 3 cells");
    first[a] = periodic[k] ? lo[a] : lo[a] - cell;
    inv_side[a] = periodic[k] ? n[k] / period_[a] : 1.0 / cell;
  }
  this->set_axes(first, inv_side, n);
}

template <int D> double BasicPeriodicGrid<D>::wrap(int axis, double v) const {
  if (!periodic_[static_cast<std::size_t>(axis)]) return v;
  const double lo = this->lo_[axis], L = period_[axis];
  if (v < lo) v += L;
  if (v >= lo + L) v -= L;
  return v;
}

template class BasicPeriodicGrid<2>;
template class BasicPeriodicGrid<3>;

} // namespace fsi::particles
