#include "particles/cell_grid.hpp"

#include <cmath>

namespace fsi::particles {

template <int D>
BasicCellGrid<D>::BasicCellGrid(const VecD<D>& lo, const VecD<D>& hi, double h) : h_(h) {
  std::array<int, D> n;
  for (int a = 0; a < D; ++a)
    n[static_cast<std::size_t>(a)] = static_cast<int>(std::ceil((hi[a] - lo[a]) / h)) + 3;
  this->set_axes(lo - VecD<D>::Constant(h), VecD<D>::Constant(1.0 / h), n);
}

template class BasicCellGrid<2>;
template class BasicCellGrid<3>;

} // namespace fsi::particles
