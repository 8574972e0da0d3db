#include "particles/neighbor_list.hpp"

#include "fsi/core/parallel.hpp"
#include "particles/simd.hpp"

#include <algorithm>
#include <limits>

#ifdef FSI_HAVE_AVX512
#include <immintrin.h>
#endif

namespace fsi::particles {
namespace {

// Particle i's row: the particles j != i of the cell block around it within r2, in the block's
// order; c counts them. Returns false if more than `capacity` were found.
bool row_scalar(const CellGrid& grid, const double* x, const double* y, std::uint32_t i, double r2,
                std::uint32_t* out, std::size_t capacity, std::size_t& c) {
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
  return !full;
}

#ifdef FSI_HAVE_AVX512
// row_scalar eight candidates at a time: gathered positions, a mask of r^2 < r2 and j != i, and
// the kept indices compressed into the row in their order.
FSI_TARGET_AVX512 bool row_avx512(const CellGrid& grid, const double* x, const double* y,
                                  std::uint32_t i, double r2, std::uint32_t* out,
                                  std::size_t capacity, std::size_t& c) {
  const __m512d xi = _mm512_set1_pd(x[i]), yi = _mm512_set1_pd(y[i]), limit = _mm512_set1_pd(r2);
  const __m256i self = _mm256_set1_epi32(static_cast<int>(i));
  const std::uint32_t* order = grid.order().data();
  bool full = false;
  const CellGrid::Block block = grid.block_near(x[i], y[i]);
  for (int r = block.y0; r <= block.y1; ++r) {
    const std::uint32_t b = grid.begin(block.x1 + 1, r);
    for (std::uint32_t k = grid.begin(block.x0, r); k < b; k += 8) {
      const std::uint32_t left = b - k;
      const __mmask8 live = left >= 8 ? __mmask8(0xFF) : __mmask8((1u << left) - 1u);
      const __m256i j = _mm256_maskz_loadu_epi32(live, order + k);
      const __m512d zero = _mm512_setzero_pd();
      const __m512d dx = _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, live, j, x, 8), xi);
      const __m512d dy = _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, live, j, y, 8), yi);
      const __m512d d2 = _mm512_fmadd_pd(dx, dx, _mm512_mul_pd(dy, dy));
      __mmask8 keep = _mm512_mask_cmp_pd_mask(live, d2, limit, _CMP_LT_OQ);
      keep = _mm256_mask_cmpneq_epi32_mask(keep, j, self);
      const auto kept = static_cast<std::size_t>(__builtin_popcount(keep));
      if (c + kept > capacity) {
        full = true;
        continue;
      }
      _mm256_mask_compressstoreu_epi32(out + c, keep, j);
      c += kept;
    }
  }
  return !full;
}
#endif

} // namespace

bool NeighborList::build(const CellGrid& grid, const double* x, const double* y, std::size_t n,
                         double radius, std::size_t capacity, bool vector) {
  capacity_ = capacity;
  if (index_.size() < n * capacity) index_.resize(n * capacity);
  count_.resize(n);
  x_build_.assign(x, x + n);
  y_build_.assign(y, y + n);
  const double r2 = radius * radius;
  const bool use_vector = vector && avx512_available();
  (void)use_vector;
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  const std::size_t bad = parallel_reduce_balanced(
      n, none,
      [&](std::size_t i) {
        std::uint32_t* out = &index_[i * capacity];
        std::size_t c = 0;
        const auto ii = static_cast<std::uint32_t>(i);
#ifdef FSI_HAVE_AVX512
        const bool fits = use_vector ? row_avx512(grid, x, y, ii, r2, out, capacity, c)
                                     : row_scalar(grid, x, y, ii, r2, out, capacity, c);
#else
        const bool fits = row_scalar(grid, x, y, ii, r2, out, capacity, c);
#endif
        count_[i] = static_cast<std::uint32_t>(c);
        return fits ? none : i;
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
