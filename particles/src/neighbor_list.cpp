#include "particles/neighbor_list.hpp"

#include "fsi/core/parallel.hpp"

#include <algorithm>
#include <limits>

namespace fsi::particles {

bool NeighborList::build(const CellGrid& grid, const double* x, const double* y, std::size_t n,
                         double radius, std::size_t capacity) {
  capacity_ = capacity;
  if (index_.size() < n * capacity) index_.resize(n * capacity);
  count_.resize(n);
  x_build_.assign(x, x + n);
  y_build_.assign(y, y + n);
  const double r2 = radius * radius;
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  const std::size_t bad = parallel_reduce_balanced(
      n, none,
      [&](std::size_t i) {
        std::uint32_t* out = &index_[i * capacity];
        std::size_t c = 0;
        const double xi = x[i], yi = y[i];
        bool full = false;
        grid.for_each_near(xi, yi, [&](std::uint32_t j) {
          const double dx = x[j] - xi, dy = y[j] - yi;
          if (j == i || dx * dx + dy * dy >= r2) return;
          if (c < capacity)
            out[c++] = j;
          else
            full = true;
        });
        count_[i] = static_cast<std::uint32_t>(c);
        return full ? i : none;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  overflow_ = bad;
  built_n_ = bad == none ? n : 0;
  return bad == none;
}

bool NeighborList::valid(const double* x, const double* y, std::size_t n, double half_skin) const {
  if (built_n_ != n || n == 0) return false;
  const double limit = half_skin * half_skin;
  const double worst = parallel_reduce(
      n, 0.0,
      [&](std::size_t i) {
        const double dx = x[i] - x_build_[i], dy = y[i] - y_build_[i];
        return dx * dx + dy * dy;
      },
      [](double a, double b) { return std::max(a, b); });
  return worst < limit;
}

double NeighborList::mean_count() const {
  if (count_.empty()) return 0.0;
  double s = 0.0;
  for (auto c : count_) s += c;
  return s / static_cast<double>(count_.size());
}

} // namespace fsi::particles
