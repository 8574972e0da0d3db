#include "particles/cell_binning.hpp"

#include "binning.hpp"

namespace fsi::particles {

template <int D>
void CellBinning<D>::set_axes(const VecD<D>& lo, const VecD<D>& inv_side,
                              const std::array<int, D>& n) {
  lo_ = lo;
  inv_side_ = inv_side;
  n_ = n;
  std::size_t cells = 1;
  for (const int k : n) cells *= static_cast<std::size_t>(k);
  start_.assign(cells + 1, 0);
}

template <int D> int CellBinning<D>::cell(int axis, double v) const {
  return detail::cell_index(v, lo_[axis], inv_side_[axis], cells(axis));
}

template <int D> void CellBinning<D>::bin(const Coords<D>& x, std::size_t n) {
  detail::sort_by_cell(
      n,
      [&](std::size_t i) {
        // (cz ny + cy) nx + cx: x fastest.
        int c = cell(D - 1, x[D - 1][i]);
        for (int a = D - 2; a >= 0; --a)
          c = c * cells(a) + cell(a, x[static_cast<std::size_t>(a)][i]);
        return static_cast<std::uint32_t>(c);
      },
      cell_, start_, order_);
}

template class CellBinning<2>;
template class CellBinning<3>;

} // namespace fsi::particles
