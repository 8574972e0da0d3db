// Probes of a TL-SPH solid: the displacement at a reference point by the kernel interpolation
// with the linear correction (the moving-least-squares form of Shepard's interpolation).
#include <Eigen/LU>
#include <sstream>

#include "fsi/core/error.hpp"
#include "particles/kernels.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

template <int D> ProbeStencil BasicTlsphSolid<D>::interpolation_stencil(const Vec& X) const {
  // Minimise sum_b w_b |u_b - a - G d_b|^2, d_b = (X_b - X) / h, w_b = W(|X_b - X|) V_b: with
  // q_b = (1, d_b) and M = sum_b w_b q_b q_b^T, a = sum_b c_b u_b, c_b = w_b [M^-1 q_b]_0.
  using Q = Eigen::Matrix<double, D + 1, 1>;
  using MatQ = Eigen::Matrix<double, D + 1, D + 1>;
  const particles::BasicWendlandC2<D> kernel(h_);
  ProbeStencil stencil;
  std::vector<Q> q;
  MatQ M = MatQ::Zero();
  for (std::size_t b = 0; b < size(); ++b) {
    const Vec d = at(X0_, b) - X;
    if (!(d.norm() < kernel.cutoff())) continue;
    const double w = kernel.W(d.norm()) * V0_[b];
    Q qb;
    qb << 1.0, d / h_;
    q.push_back(qb);
    M += w * q.back() * q.back().transpose();
    stencil.particles.push_back(static_cast<std::uint32_t>(b));
    stencil.weights.push_back(w);
  }
  const Eigen::PartialPivLU<MatQ> lu(M);
  if (stencil.particles.size() < D + 1 || !(lu.rcond() > 1e-10)) {
    std::ostringstream s;
    s << "tlsph: probe point (";
    for (int k = 0; k < D; ++k) s << (k ? ", " : "") << X(k);
    s << ") is off the solid: its " << stencil.particles.size()
      << " particles within 2h do not span the " << (D == 2 ? "plane" : "space");
    throw InputError(s.str());
  }
  for (std::size_t k = 0; k < q.size(); ++k) stencil.weights[k] *= lu.solve(q[k])(0);
  return stencil;
}

template <int D>
auto BasicTlsphSolid<D>::displacement_at(const ProbeStencil& stencil) const -> Vec {
  Vec u = Vec::Zero();
  for (std::size_t k = 0; k < stencil.particles.size(); ++k)
    u += stencil.weights[k] * displacement(stencil.particles[k]);
  return u;
}

template ProbeStencil BasicTlsphSolid<2>::interpolation_stencil(const Vec2&) const;
template ProbeStencil BasicTlsphSolid<3>::interpolation_stencil(const Vec3&) const;
template auto BasicTlsphSolid<2>::displacement_at(const ProbeStencil&) const -> Vec;
template auto BasicTlsphSolid<3>::displacement_at(const ProbeStencil&) const -> Vec;

} // namespace fsi::tlsph
