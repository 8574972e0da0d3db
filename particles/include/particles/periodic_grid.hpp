#pragma once
// Cell-linked list in D = 2 or 3 dimensions with optional periodic directions: particles binned by
// a counting sort into cells of side >= `cell` over [lo, hi); in a periodic direction the cells
// tile the period exactly and the 3^D block wraps, each neighbour coming with the image shift to
// add to its position. Non-periodic directions clamp to the edge cells (as BasicCellGrid). Needs >=
// 3 cells along a periodic direction (a particle is then found at most once around any point).
#include "particles/cell_binning.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace fsi::particles {

template <int D> class BasicPeriodicGrid : public CellBinning<D> {
public:
  BasicPeriodicGrid() = default;
  /// Throws std::invalid_argument if a periodic direction holds fewer than 3 cells.
  BasicPeriodicGrid(const VecD<D>& lo, const VecD<D>& hi, double cell,
                    const std::array<bool, D>& periodic);
  BasicPeriodicGrid(const VecD<D>& lo, const VecD<D>& hi, double cell, bool periodic_x,
                    bool periodic_y) requires(D == 2)
      : BasicPeriodicGrid(lo, hi, cell, {periodic_x, periodic_y}) {}

  /// v wrapped into [lo, hi) along `axis` if it is periodic; unchanged otherwise.
  double wrap(int axis, double v) const;
  double wrap_x(double x) const { return wrap(0, x); }
  double wrap_y(double y) const { return wrap(1, y); }

  /// f(j, s) for each binned particle j in the (wrapped) 3^D block around p: the image of j near
  /// the point is at x_j + s (s[a] is -L_a, 0 or L_a). Cells x fastest, then y, then z.
  template <class F> void for_each_near(const VecD<D>& p, F&& f) const {
    std::array<int, D> c;
    for (int a = 0; a < D; ++a) c[static_cast<std::size_t>(a)] = cell(a, p[a]);
    std::array<double, D> s{};
    visit<D - 1>(c, s, 0, f);
  }
  /// The 2-D form: f(j, sx, sy), the image of j at (x_j + sx, y_j + sy).
  template <class F> void for_each_near(double px, double py, F&& f) const requires(D == 2) {
    for_each_near(VecD<D>(px, py),
                  [&](std::uint32_t j, const std::array<double, D>& s) { f(j, s[0], s[1]); });
  }

  using CellBinning<D>::cell;

private:
  using CellBinning<D>::n_;
  using CellBinning<D>::start_;
  using CellBinning<D>::order_;

  /// Cell index r along an axis of n cells: wrapped into [0, n) with the image shift s (-L, 0 or
  /// L) if the axis is periodic; false if r is off a non-periodic axis.
  static bool wrap_cell(int& r, double& s, int n, double L, bool periodic) {
    if (!periodic) return r >= 0 && r < n;
    if (r < 0) r += n, s = -L;
    if (r >= n) r -= n, s = L;
    return true;
  }
  /// The three cells around c along axis A (outermost first), then the axes below; `base` is the
  /// linear index of the cells chosen along the axes above A.
  template <int A, class F>
  void visit(const std::array<int, D>& c, std::array<double, D>& s, std::size_t base, F& f) const {
    constexpr auto a = static_cast<std::size_t>(A);
    for (int d = -1; d <= 1; ++d) {
      int r = c[a] + d;
      double sa = 0.0;
      if (!wrap_cell(r, sa, n_[a], period_[A], periodic_[a])) continue;
      s[a] = sa;
      const std::size_t index =
          base * static_cast<std::size_t>(n_[a]) + static_cast<std::size_t>(r);
      if constexpr (A == 0) {
        for (std::uint32_t k = start_[index]; k < start_[index + 1]; ++k)
          f(order_[k], static_cast<const std::array<double, D>&>(s));
      } else {
        visit<A - 1>(c, s, index, f);
      }
    }
  }

  VecD<D> period_ = VecD<D>::Zero();
  std::array<bool, D> periodic_{};
};

extern template class BasicPeriodicGrid<2>;
extern template class BasicPeriodicGrid<3>;

/// The 2-D grid of the 2-D SPH fluid.
using PeriodicGrid = BasicPeriodicGrid<2>;

} // namespace fsi::particles
