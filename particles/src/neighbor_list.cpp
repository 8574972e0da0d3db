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

/// |x_j - p|^2, summed x first (in 2-D: dx dx + dy dy).
template <int D> double squared_distance(const Coords<D>& x, std::size_t j, const VecD<D>& p) {
  double d = x[0][j] - p[0];
  double s = d * d;
  for (int a = 1; a < D; ++a) {
    d = x[static_cast<std::size_t>(a)][j] - p[a];
    s += d * d;
  }
  return s;
}

template <int D> VecD<D> position(const Coords<D>& x, std::size_t i) {
  VecD<D> p;
  for (int a = 0; a < D; ++a) p[a] = x[static_cast<std::size_t>(a)][i];
  return p;
}

// Particle i's row: the particles j != i of the cell block around it within r2, in the block's
// order; c counts them. Returns false if more than `capacity` were found.
template <int D>
bool row_scalar(const BasicCellGrid<D>& grid, const Coords<D>& x, std::uint32_t i, double r2,
                std::uint32_t* out, std::size_t capacity, std::size_t& c) {
  const VecD<D> xi = position<D>(x, i);
  bool full = false;
  grid.for_each_near(xi, [&](std::uint32_t j) {
    if (j == i || squared_distance<D>(x, j, xi) >= r2) return;
    if (c < capacity)
      out[c++] = j;
    else
      full = true;
  });
  return !full;
}

#ifdef FSI_HAVE_AVX512
// row_scalar eight candidates at a time: gathered positions, a mask of r^2 < r2 and j != i, and
// the kept indices compressed into the row in their order. r^2 is accumulated from the last axis
// down (in 2-D: fma(dx, dx, dy dy)). No lambdas here: they would not inherit the AVX-512 target.
template <int D>
FSI_TARGET_AVX512 bool row_avx512(const BasicCellGrid<D>& grid, const Coords<D>& x, std::uint32_t i,
                                  double r2, std::uint32_t* out, std::size_t capacity,
                                  std::size_t& c) {
  __m512d xi[D];
  for (std::size_t a = 0; a < D; ++a) xi[a] = _mm512_set1_pd(x[a][i]);
  const __m512d limit = _mm512_set1_pd(r2);
  const __m256i self = _mm256_set1_epi32(static_cast<int>(i));
  const std::uint32_t* order = grid.order().data();
  bool full = false;
  const typename BasicCellGrid<D>::Block block = grid.block_near(position<D>(x, i));
  for (int r = 0; r < block.rows; ++r) {
    const int row = block.row[static_cast<std::size_t>(r)];
    const std::uint32_t b = grid.begin(block.x1 + 1, row);
    for (std::uint32_t k = grid.begin(block.x0, row); k < b; k += 8) {
      const std::uint32_t left = b - k;
      const __mmask8 live = left >= 8 ? __mmask8(0xFF) : __mmask8((1u << left) - 1u);
      const __m256i j = _mm256_maskz_loadu_epi32(live, order + k);
      const __m512d zero = _mm512_setzero_pd();
      __m512d d[D];
      for (std::size_t a = 0; a < D; ++a)
        d[a] = _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, live, j, x[a], 8), xi[a]);
      __m512d d2 = _mm512_mul_pd(d[D - 1], d[D - 1]);
      for (int a = D - 2; a >= 0; --a) d2 = _mm512_fmadd_pd(d[a], d[a], d2);
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

template <int D>
bool BasicNeighborList<D>::build(const BasicCellGrid<D>& grid, const Coords<D>& x, std::size_t n,
                                 double radius, std::size_t capacity, bool vector) {
  capacity_ = capacity;
  if (index_.size() < n * capacity) index_.resize(n * capacity);
  count_.resize(n);
  for (std::size_t a = 0; a < D; ++a) build_[a].assign(x[a], x[a] + n);
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
        const bool fits = use_vector ? row_avx512<D>(grid, x, ii, r2, out, capacity, c)
                                     : row_scalar<D>(grid, x, ii, r2, out, capacity, c);
#else
        const bool fits = row_scalar<D>(grid, x, ii, r2, out, capacity, c);
#endif
        count_[i] = static_cast<std::uint32_t>(c);
        return fits ? none : i;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  overflow_ = bad;
  built_n_ = bad == none ? n : 0;
  return bad == none;
}

template <int D>
bool BasicNeighborList<D>::valid(const Coords<D>& x, std::size_t n, double half_skin) const {
  if (built_n_ != n || n == 0) return false;
  const double limit = half_skin * half_skin;
  Coords<D> at_build;
  for (std::size_t a = 0; a < D; ++a) at_build[a] = build_[a].data();
  const double worst = parallel_reduce(
      n, 0.0, [&](std::size_t i) { return squared_distance<D>(x, i, position<D>(at_build, i)); },
      [](double a, double b) { return std::max(a, b); });
  return worst < limit;
}

template <int D> double BasicNeighborList<D>::mean_count() const {
  if (count_.empty()) return 0.0;
  double s = 0.0;
  for (auto c : count_) s += c;
  return s / static_cast<double>(count_.size());
}

template class BasicNeighborList<2>;
template class BasicNeighborList<3>;

} // namespace fsi::particles
