#include "fluid_emps/pair_sums.hpp"

#include "particles/simd.hpp"

#include <cmath>

#ifdef FSI_HAVE_AVX512
#include <immintrin.h>
#endif

namespace fsi::emps {
namespace {

PndSum pnd_scalar(const PairRow& r, const double* x, const double* y) {
  PndSum out;
  for (std::uint32_t k = 0; k < r.count; ++k) {
    const std::uint32_t j = r.j[k];
    const double dx = x[j] - r.xi, dy = y[j] - r.yi, r2 = dx * dx + dy * dy;
    if (r2 >= r.re2) continue;
    const double s = 1.0 - std::sqrt(r2) * r.inv_re;
    out.pnd += s * s;
    ++out.within;
  }
  return out;
}

VecSum gradient_scalar(const PairRow& r, const double* x, const double* y, const double* p,
                       double p_i) {
  VecSum out;
  for (std::uint32_t k = 0; k < r.count; ++k) {
    const std::uint32_t j = r.j[k];
    const double dx = x[j] - r.xi, dy = y[j] - r.yi, r2 = dx * dx + dy * dy;
    if (r2 >= r.re2 || r2 == 0.0) continue;
    const double s = 1.0 - std::sqrt(r2) * r.inv_re;
    const double f = (p[j] + p_i) * s * s / r2;
    out.x += f * dx;
    out.y += f * dy;
  }
  return out;
}

VecSum laplacian_scalar(const PairRow& r, const double* x, const double* y, const double* vx,
                        const double* vy, double vxi, double vyi) {
  VecSum out;
  for (std::uint32_t k = 0; k < r.count; ++k) {
    const std::uint32_t j = r.j[k];
    const double dx = x[j] - r.xi, dy = y[j] - r.yi, r2 = dx * dx + dy * dy;
    if (r2 >= r.re2) continue;
    const double s = 1.0 - std::sqrt(r2) * r.inv_re, w = s * s;
    out.x += (vx[j] - vxi) * w;
    out.y += (vy[j] - vyi) * w;
  }
  return out;
}

ViscousSum viscous_scalar(const PairRow& r, const double* x, const double* y, const double* vx,
                          const double* vy, double vxi, double vyi) {
  ViscousSum out;
  for (std::uint32_t k = 0; k < r.count; ++k) {
    const std::uint32_t j = r.j[k];
    const double dx = x[j] - r.xi, dy = y[j] - r.yi, r2 = dx * dx + dy * dy;
    if (r2 >= r.re2) continue;
    const double s = 1.0 - std::sqrt(r2) * r.inv_re, w = s * s;
    const double dvx = vx[j] - vxi, dvy = vy[j] - vyi;
    out.laplacian.x += dvx * w;
    out.laplacian.y += dvy * w;
    const double closing = dvx * dx + dvy * dy;
    if (closing < 0 && r2 > 0) {
      const double f = closing * w / r2;
      out.closing.x += f * dx;
      out.closing.y += f * dy;
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

FSI_TARGET_AVX512 inline Lanes lanes(const PairRow& r, std::uint32_t k, const double* x,
                                     const double* y) {
  Lanes l;
  const std::uint32_t left = r.count - k;
  l.live = left >= 8 ? __mmask8(0xFF) : __mmask8((1u << left) - 1u);
  l.j = _mm256_maskz_loadu_epi32(l.live, r.j + k);
  const __m512d zero = _mm512_setzero_pd();
  l.dx = _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, l.live, l.j, x, 8), _mm512_set1_pd(r.xi));
  l.dy = _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, l.live, l.j, y, 8), _mm512_set1_pd(r.yi));
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

FSI_TARGET_AVX512 PndSum pnd_avx512(const PairRow& r, const double* x, const double* y) {
  __m512d pnd = _mm512_setzero_pd();
  std::uint32_t within = 0;
  for (std::uint32_t k = 0; k < r.count; k += 8) {
    const Lanes l = lanes(r, k, x, y);
    pnd = _mm512_mask_add_pd(pnd, l.inside, pnd, weight(l, r));
    within += static_cast<std::uint32_t>(__builtin_popcount(l.inside));
  }
  return {lane_sum(pnd), within};
}

FSI_TARGET_AVX512 VecSum gradient_avx512(const PairRow& r, const double* x, const double* y,
                                         const double* p, double p_i) {
  __m512d gx = _mm512_setzero_pd(), gy = _mm512_setzero_pd();
  const __m512d zero = _mm512_setzero_pd();
  for (std::uint32_t k = 0; k < r.count; k += 8) {
    Lanes l = lanes(r, k, x, y);
    l.inside = _mm512_mask_cmp_pd_mask(l.inside, l.r2, zero, _CMP_NEQ_OQ);
    const __m512d pj = _mm512_mask_i32gather_pd(zero, l.inside, l.j, p, 8);
    const __m512d f = _mm512_maskz_div_pd(
        l.inside, _mm512_mul_pd(_mm512_add_pd(pj, _mm512_set1_pd(p_i)), weight(l, r)), l.r2);
    gx = _mm512_mask3_fmadd_pd(f, l.dx, gx, l.inside);
    gy = _mm512_mask3_fmadd_pd(f, l.dy, gy, l.inside);
  }
  return {lane_sum(gx), lane_sum(gy)};
}

FSI_TARGET_AVX512 VecSum laplacian_avx512(const PairRow& r, const double* x, const double* y,
                                          const double* vx, const double* vy, double vxi,
                                          double vyi) {
  __m512d sx = _mm512_setzero_pd(), sy = _mm512_setzero_pd();
  for (std::uint32_t k = 0; k < r.count; k += 8) {
    const Lanes l = lanes(r, k, x, y);
    const __m512d w = weight(l, r);
    const __m512d dvx = difference(l, vx, vxi), dvy = difference(l, vy, vyi);
    sx = _mm512_mask3_fmadd_pd(dvx, w, sx, l.inside);
    sy = _mm512_mask3_fmadd_pd(dvy, w, sy, l.inside);
  }
  return {lane_sum(sx), lane_sum(sy)};
}

FSI_TARGET_AVX512 ViscousSum viscous_avx512(const PairRow& r, const double* x, const double* y,
                                            const double* vx, const double* vy, double vxi,
                                            double vyi) {
  __m512d sx = _mm512_setzero_pd(), sy = _mm512_setzero_pd();
  __m512d ax = _mm512_setzero_pd(), ay = _mm512_setzero_pd();
  const __m512d zero = _mm512_setzero_pd();
  for (std::uint32_t k = 0; k < r.count; k += 8) {
    const Lanes l = lanes(r, k, x, y);
    const __m512d w = weight(l, r);
    const __m512d dvx = difference(l, vx, vxi), dvy = difference(l, vy, vyi);
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

PndSum pnd_sum(const PairRow& row, const double* x, const double* y, bool vector) {
#ifdef FSI_HAVE_AVX512
  if (vector && particles::avx512_available()) return pnd_avx512(row, x, y);
#endif
  (void)vector;
  return pnd_scalar(row, x, y);
}

VecSum gradient_sum(const PairRow& row, const double* x, const double* y, const double* p,
                    double p_i, bool vector) {
#ifdef FSI_HAVE_AVX512
  if (vector && particles::avx512_available()) return gradient_avx512(row, x, y, p, p_i);
#endif
  (void)vector;
  return gradient_scalar(row, x, y, p, p_i);
}

VecSum laplacian_sum(const PairRow& row, const double* x, const double* y, const double* vx,
                     const double* vy, double vxi, double vyi, bool vector) {
#ifdef FSI_HAVE_AVX512
  if (vector && particles::avx512_available()) return laplacian_avx512(row, x, y, vx, vy, vxi, vyi);
#endif
  (void)vector;
  return laplacian_scalar(row, x, y, vx, vy, vxi, vyi);
}

ViscousSum viscous_sum(const PairRow& row, const double* x, const double* y, const double* vx,
                       const double* vy, double vxi, double vyi, bool vector) {
#ifdef FSI_HAVE_AVX512
  if (vector && particles::avx512_available()) return viscous_avx512(row, x, y, vx, vy, vxi, vyi);
#endif
  (void)vector;
  return viscous_scalar(row, x, y, vx, vy, vxi, vyi);
}

} // namespace fsi::emps
