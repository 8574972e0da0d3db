#include "fluid_emps/pair_sums.hpp"

#include "particles/simd.hpp"

#include <array>
#include <cmath>

#ifdef FSI_HAVE_AVX512
#include <immintrin.h>
#endif

namespace fsi::emps {
namespace {

// x_j - x_i and r_ij^2 (summed over the axes in order: in 2-D dx dx + dy dy).
template <int D> struct Offset {
  std::array<double, D> d;
  double r2;
};

template <int D> double dot(const std::array<double, D>& a, const std::array<double, D>& b) {
  double s = a[0] * b[0];
  for (std::size_t k = 1; k < D; ++k) s += a[k] * b[k];
  return s;
}

template <int D> Offset<D> offset(const BasicPairRow<D>& r, const Coords<D>& x, std::uint32_t j) {
  Offset<D> o;
  for (std::size_t a = 0; a < D; ++a) o.d[a] = x[a][j] - r.xi[a];
  o.r2 = dot<D>(o.d, o.d);
  return o;
}

template <int D> PndSum pnd_scalar(const BasicPairRow<D>& r, const Coords<D>& x) {
  PndSum out;
  for (std::uint32_t k = 0; k < r.count; ++k) {
    const Offset<D> o = offset<D>(r, x, r.j[k]);
    if (o.r2 >= r.re2) continue;
    const double s = 1.0 - std::sqrt(o.r2) * r.inv_re;
    out.pnd += s * s;
    ++out.within;
  }
  return out;
}

template <int D>
VecSum<D> gradient_scalar(const BasicPairRow<D>& r, const Coords<D>& x, const double* p,
                          double p_i) {
  VecSum<D> out{};
  for (std::uint32_t k = 0; k < r.count; ++k) {
    const std::uint32_t j = r.j[k];
    const Offset<D> o = offset<D>(r, x, j);
    if (o.r2 >= r.re2 || o.r2 == 0.0) continue;
    const double s = 1.0 - std::sqrt(o.r2) * r.inv_re;
    const double f = (p[j] + p_i) * s * s / o.r2;
    for (std::size_t a = 0; a < D; ++a) out[a] += f * o.d[a];
  }
  return out;
}

// The Laplacian sum, and with `closing_pairs` the closing-pair sum.
template <bool closing_pairs, int D>
ViscousSum<D> viscous_scalar(const BasicPairRow<D>& r, const Coords<D>& x, const Coords<D>& v,
                             const VecSum<D>& v_i) {
  ViscousSum<D> out;
  for (std::uint32_t k = 0; k < r.count; ++k) {
    const std::uint32_t j = r.j[k];
    const Offset<D> o = offset<D>(r, x, j);
    if (o.r2 >= r.re2) continue;
    const double s = 1.0 - std::sqrt(o.r2) * r.inv_re, w = s * s;
    std::array<double, D> dv;
    for (std::size_t a = 0; a < D; ++a) dv[a] = v[a][j] - v_i[a];
    for (std::size_t a = 0; a < D; ++a) out.laplacian[a] += dv[a] * w;
    if constexpr (!closing_pairs) continue;
    const double closing = dot<D>(dv, o.d);
    if (closing < 0 && o.r2 > 0) {
      const double f = closing * w / o.r2;
      for (std::size_t a = 0; a < D; ++a) out.closing[a] += f * o.d[a];
    }
  }
  return out;
}

#ifdef FSI_HAVE_AVX512

// Eight pairs of a row from k: the lanes that exist (live), their indices, the gathered
// offsets dx, dy, r^2, and the lanes with r < r_e (inside).
struct Lanes {
  __mmask8 live, inside;
  __m256i j;
  __m512d dx, dy, r2;
};

FSI_TARGET_AVX512 inline Lanes lanes(const PairRow& r, std::uint32_t k, const Coords<2>& x) {
  Lanes l;
  const std::uint32_t left = r.count - k;
  l.live = left >= 8 ? __mmask8(0xFF) : __mmask8((1u << left) - 1u);
  l.j = _mm256_maskz_loadu_epi32(l.live, r.j + k);
  const __m512d zero = _mm512_setzero_pd();
  l.dx =
      _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, l.live, l.j, x[0], 8), _mm512_set1_pd(r.xi[0]));
  l.dy =
      _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, l.live, l.j, x[1], 8), _mm512_set1_pd(r.xi[1]));
  l.r2 = _mm512_fmadd_pd(l.dx, l.dx, _mm512_mul_pd(l.dy, l.dy));
  l.inside = _mm512_mask_cmp_pd_mask(l.live, l.r2, _mm512_set1_pd(r.re2), _CMP_LT_OQ);
  return l;
}

// The sum of the eight lanes (GCC 12's _mm512_reduce_add_pd trips -Wuninitialized).
FSI_TARGET_AVX512 inline double lane_sum(__m512d v) {
  alignas(64) double a[8];
  _mm512_store_pd(a, v);
  return ((a[0] + a[1]) + (a[2] + a[3])) + ((a[4] + a[5]) + (a[6] + a[7]));
}

// w = (1 - r/r_e)^2 in the inside lanes.
FSI_TARGET_AVX512 inline __m512d weight(const Lanes& l, const PairRow& r) {
  const __m512d s = _mm512_fnmadd_pd(_mm512_maskz_sqrt_pd(l.inside, l.r2), _mm512_set1_pd(r.inv_re),
                                     _mm512_set1_pd(1.0));
  return _mm512_mul_pd(s, s);
}

// v_j - v_i in the inside lanes (0 - v_i elsewhere).
FSI_TARGET_AVX512 inline __m512d difference(const Lanes& l, const double* v, double v_i) {
  return _mm512_sub_pd(_mm512_mask_i32gather_pd(_mm512_setzero_pd(), l.inside, l.j, v, 8),
                       _mm512_set1_pd(v_i));
}

FSI_TARGET_AVX512 PndSum pnd_avx512(const PairRow& r, const Coords<2>& x) {
  __m512d pnd = _mm512_setzero_pd();
  std::uint32_t within = 0;
  for (std::uint32_t k = 0; k < r.count; k += 8) {
    const Lanes l = lanes(r, k, x);
    pnd = _mm512_mask_add_pd(pnd, l.inside, pnd, weight(l, r));
    within += static_cast<std::uint32_t>(__builtin_popcount(l.inside));
  }
  return {lane_sum(pnd), within};
}

FSI_TARGET_AVX512 VecSum<2> gradient_avx512(const PairRow& r, const Coords<2>& x, const double* p,
                                            double p_i) {
  __m512d gx = _mm512_setzero_pd(), gy = _mm512_setzero_pd();
  const __m512d zero = _mm512_setzero_pd();
  for (std::uint32_t k = 0; k < r.count; k += 8) {
    Lanes l = lanes(r, k, x);
    l.inside = _mm512_mask_cmp_pd_mask(l.inside, l.r2, zero, _CMP_NEQ_OQ);
    const __m512d pj = _mm512_mask_i32gather_pd(zero, l.inside, l.j, p, 8);
    const __m512d f = _mm512_maskz_div_pd(
        l.inside, _mm512_mul_pd(_mm512_add_pd(pj, _mm512_set1_pd(p_i)), weight(l, r)), l.r2);
    gx = _mm512_mask3_fmadd_pd(f, l.dx, gx, l.inside);
    gy = _mm512_mask3_fmadd_pd(f, l.dy, gy, l.inside);
  }
  return {lane_sum(gx), lane_sum(gy)};
}

FSI_TARGET_AVX512 VecSum<2> laplacian_avx512(const PairRow& r, const Coords<2>& x,
                                             const Coords<2>& v, const VecSum<2>& v_i) {
  __m512d sx = _mm512_setzero_pd(), sy = _mm512_setzero_pd();
  for (std::uint32_t k = 0; k < r.count; k += 8) {
    const Lanes l = lanes(r, k, x);
    const __m512d w = weight(l, r);
    const __m512d dvx = difference(l, v[0], v_i[0]), dvy = difference(l, v[1], v_i[1]);
    sx = _mm512_mask3_fmadd_pd(dvx, w, sx, l.inside);
    sy = _mm512_mask3_fmadd_pd(dvy, w, sy, l.inside);
  }
  return {lane_sum(sx), lane_sum(sy)};
}

FSI_TARGET_AVX512 ViscousSum<2> viscous_avx512(const PairRow& r, const Coords<2>& x,
                                               const Coords<2>& v, const VecSum<2>& v_i) {
  __m512d sx = _mm512_setzero_pd(), sy = _mm512_setzero_pd();
  __m512d ax = _mm512_setzero_pd(), ay = _mm512_setzero_pd();
  const __m512d zero = _mm512_setzero_pd();
  for (std::uint32_t k = 0; k < r.count; k += 8) {
    const Lanes l = lanes(r, k, x);
    const __m512d w = weight(l, r);
    const __m512d dvx = difference(l, v[0], v_i[0]), dvy = difference(l, v[1], v_i[1]);
    sx = _mm512_mask3_fmadd_pd(dvx, w, sx, l.inside);
    sy = _mm512_mask3_fmadd_pd(dvy, w, sy, l.inside);
    const __m512d closing = _mm512_fmadd_pd(dvx, l.dx, _mm512_mul_pd(dvy, l.dy));
    const __mmask8 closes = _mm512_mask_cmp_pd_mask(
        _mm512_mask_cmp_pd_mask(l.inside, l.r2, zero, _CMP_NEQ_OQ), closing, zero, _CMP_LT_OQ);
    const __m512d f = _mm512_maskz_div_pd(closes, _mm512_mul_pd(closing, w), l.r2);
    ax = _mm512_mask3_fmadd_pd(f, l.dx, ax, closes);
    ay = _mm512_mask3_fmadd_pd(f, l.dy, ay, closes);
  }
  return {{lane_sum(sx), lane_sum(sy)}, {lane_sum(ax), lane_sum(ay)}};
}
#endif

} // namespace

template <int D> PndSum pnd_sum(const BasicPairRow<D>& row, const Coords<D>& x, bool vector) {
#ifdef FSI_HAVE_AVX512
  if constexpr (D == 2)
    if (vector && particles::avx512_available()) return pnd_avx512(row, x);
#endif
  (void)vector;
  return pnd_scalar<D>(row, x);
}

template <int D>
VecSum<D> gradient_sum(const BasicPairRow<D>& row, const Coords<D>& x, const double* p, double p_i,
                       bool vector) {
#ifdef FSI_HAVE_AVX512
  if constexpr (D == 2)
    if (vector && particles::avx512_available()) return gradient_avx512(row, x, p, p_i);
#endif
  (void)vector;
  return gradient_scalar<D>(row, x, p, p_i);
}

template <int D>
VecSum<D> laplacian_sum(const BasicPairRow<D>& row, const Coords<D>& x, const Coords<D>& v,
                        const VecSum<D>& v_i, bool vector) {
#ifdef FSI_HAVE_AVX512
  if constexpr (D == 2)
    if (vector && particles::avx512_available()) return laplacian_avx512(row, x, v, v_i);
#endif
  (void)vector;
  return viscous_scalar<false, D>(row, x, v, v_i).laplacian;
}

template <int D>
ViscousSum<D> viscous_sum(const BasicPairRow<D>& row, const Coords<D>& x, const Coords<D>& v,
                          const VecSum<D>& v_i, bool vector) {
#ifdef FSI_HAVE_AVX512
  if constexpr (D == 2)
    if (vector && particles::avx512_available()) return viscous_avx512(row, x, v, v_i);
#endif
  (void)vector;
  return viscous_scalar<true, D>(row, x, v, v_i);
}

#define FSI_EMPS_PAIR_SUMS(D)                                                                      \
  template PndSum pnd_sum<D>(const BasicPairRow<D>&, const Coords<D>&, bool);                      \
  template VecSum<D> gradient_sum<D>(const BasicPairRow<D>&, const Coords<D>&, const double*,      \
                                     double, bool);                                                \
  template VecSum<D> laplacian_sum<D>(const BasicPairRow<D>&, const Coords<D>&, const Coords<D>&,  \
                                      const VecSum<D>&, bool);                                     \
  template ViscousSum<D> viscous_sum<D>(const BasicPairRow<D>&, const Coords<D>&,                  \
                                        const Coords<D>&, const VecSum<D>&, bool);
FSI_EMPS_PAIR_SUMS(2)
FSI_EMPS_PAIR_SUMS(3)
#undef FSI_EMPS_PAIR_SUMS

} // namespace fsi::emps
