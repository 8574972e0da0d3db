// Hourglass control of the quadratic correction: the residuals r_ab of a particle's quadratic
// fit, the penalty's strain (TlsphOptions::hourglass, docs/solid_tlsph.md).
#include "shared.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

template <int D>
void BasicTlsphSolid<D>::hourglass_residuals(std::size_t a, const std::array<double*, D>& r) const {
  // r_ab = (u_b - u_a) - C_a p_ab with the fit C_a = sum_c (u_c - u_a) s_ac^T
  constexpr int M = monomial_count<D>;
  const std::uint32_t start = pair_start_[a], end = pair_start_[a + 1];
  const auto x = x_.coords(), X0 = X0_.coords(); // raw arrays: no reloads in the pair loops
  auto du_ab = [&](std::uint32_t b) {
    Vec du;
    for (int k = 0; k < D; ++k) du(k) = x[k][b] - X0[k][b] - (x[k][a] - X0[k][a]);
    return du;
  };
  double c[D][M] = {};
  for (std::uint32_t q = start; q < end; ++q) {
    const Vec du = du_ab(pair_b_[q]);
    for (int m = 0; m < M; ++m)
      for (int k = 0; k < D; ++k) c[k][m] += du(k) * pair_fit_[M * q + m];
  }
  for (std::uint32_t q = start; q < end; ++q) {
    const std::uint32_t b = pair_b_[q];
    Vec d;
    for (int k = 0; k < D; ++k) d(k) = (X0[k][b] - X0[k][a]) / h_;
    const Monomials<D> p = monomials<D>(d);
    const Vec du = du_ab(b);
    for (int k = 0; k < D; ++k) {
      double fit = 0.0;
      for (int m = 0; m < M; ++m) fit += c[k][m] * p(m);
      r[k][q - start] = du(k) - fit;
    }
  }
}

template void BasicTlsphSolid<2>::hourglass_residuals(std::size_t,
                                                      const std::array<double*, 2>&) const;
template void BasicTlsphSolid<3>::hourglass_residuals(std::size_t,
                                                      const std::array<double*, 3>&) const;

} // namespace fsi::tlsph
