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
  // Raw arrays and u_a loaded once: the stores to r alias none of them for the compiler.
  const auto x = x_.coords(), X0 = X0_.coords();
  const std::uint32_t* pb = pair_b_.data();
  const double* fit = pair_fit_.data();
  const double h = h_;
  Vec X0_a, u_a;
  for (int k = 0; k < D; ++k) X0_a(k) = X0[k][a], u_a(k) = x[k][a] - X0[k][a];
  auto du_ab = [&](std::uint32_t b) {
    Vec du;
    for (int k = 0; k < D; ++k) du(k) = x[k][b] - X0[k][b] - u_a(k);
    return du;
  };
  double c[M][D] = {}; // C_a by monomial: the D components side by side
  for (std::uint32_t q = start; q < end; ++q) {
    const Vec du = du_ab(pb[q]);
    for (int m = 0; m < M; ++m)
      for (int k = 0; k < D; ++k) c[m][k] += du(k) * fit[M * q + m];
  }
  for (std::uint32_t q = start; q < end; ++q) {
    const std::uint32_t b = pb[q];
    Vec d;
    for (int k = 0; k < D; ++k) d(k) = (X0[k][b] - X0_a(k)) / h;
    const Monomials<D> p = monomials<D>(d);
    const Vec du = du_ab(b);
    for (int k = 0; k < D; ++k) {
      double fit = 0.0;
      for (int m = 0; m < M; ++m) fit += c[m][k] * p(m);
      r[k][q - start] = du(k) - fit;
    }
  }
}

template void BasicTlsphSolid<2>::hourglass_residuals(std::size_t,
                                                      const std::array<double*, 2>&) const;
template void BasicTlsphSolid<3>::hourglass_residuals(std::size_t,
                                                      const std::array<double*, 3>&) const;

} // namespace fsi::tlsph
