#pragma once
// Shared by the fluid's sources (private to fluid_sph): the no-particle index, the number format
// of messages and the D-component arithmetic of the pair loops, each written so that D = 2 is the
// 2-D code's expression term by term (first term first: the 2-D results bitwise unchanged).
#include "fsi/core/format.hpp"
#include "fsi/core/unroll.hpp"

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

namespace fsi::sph {

/// No particle (an unset index; the neutral element of a first-bad-particle reduction).
inline constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

/// A number as a message shows it: 6 significant digits.
inline std::string fmt(double v) {
  return significant(v, 6);
}

/// Index of entry (r, c) of a symmetric D x D matrix stored as its upper triangle row by row.
template <int D> constexpr int sym(int r, int c) {
  return r <= c ? r * D - r * (r - 1) / 2 + c - r : sym<D>(c, r);
}

/// a . b of D components: a_0 b_0 + a_1 b_1 (+ a_2 b_2).
template <int D, class A, class B> inline double dot(const A& a, const B& b) {
  double s = a[0] * b[0];
  FSI_UNROLL for (int c = 1; c < D; ++c) s += a[c] * b[c];
  return s;
}

/// Row r of the symmetric matrix b (upper triangle, sym) times g: sum_c b_rc g_c.
template <int D, class G> inline double sym_row(const double* b, int r, const G& g) {
  double s = b[sym<D>(r, 0)] * g[0];
  FSI_UNROLL for (int c = 1; c < D; ++c) s += b[sym<D>(r, c)] * g[c];
  return s;
}

/// |v| by std::hypot (the 2-D code's two-argument form).
template <int D, class V> inline double length(const V& v) {
  if constexpr (D == 2)
    return std::hypot(v[0], v[1]);
  else
    return std::hypot(v[0], v[1], v[2]);
}

} // namespace fsi::sph
