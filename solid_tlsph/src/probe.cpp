// Probes of a TL-SPH solid: the displacement at a reference point by the kernel interpolation
// with the linear correction (the moving-least-squares form of Shepard's interpolation).
#include <Eigen/LU>
#include <sstream>

#include "fsi/core/error.hpp"
#include "particles/kernels.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

ProbeStencil TlsphSolid::interpolation_stencil(const Vec2& X) const {
  // Minimise sum_b w_b |u_b - a - G d_b|^2, d_b = (X_b - X) / h, w_b = W(|X_b - X|) V_b: with
  // q_b = (1, d_b) and M = sum_b w_b q_b q_b^T, a = sum_b c_b u_b, c_b = w_b [M^-1 q_b]_0.
  using Vec3 = Eigen::Vector3d;
  const particles::WendlandC2 kernel(h_);
  ProbeStencil stencil;
  std::vector<Vec3> q;
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  for (std::size_t b = 0; b < size(); ++b) {
    const Vec2 d = Vec2(X0_[b] - X.x(), Y0_[b] - X.y());
    if (!(d.norm() < kernel.cutoff())) continue;
    const double w = kernel.W(d.norm()) * V0_[b];
    q.emplace_back(1.0, d.x() / h_, d.y() / h_);
    M += w * q.back() * q.back().transpose();
    stencil.particles.push_back(static_cast<std::uint32_t>(b));
    stencil.weights.push_back(w);
  }
  const Eigen::PartialPivLU<Eigen::Matrix3d> lu(M);
  if (stencil.particles.size() < 3 || !(lu.rcond() > 1e-10)) {
    std::ostringstream s;
    s << "tlsph: probe point (" << X.x() << ", " << X.y() << ") is off the solid: its "
      << stencil.particles.size() << " particles within 2h do not span the plane";
    throw InputError(s.str());
  }
  for (std::size_t k = 0; k < q.size(); ++k) stencil.weights[k] *= lu.solve(q[k])(0);
  return stencil;
}

Vec2 TlsphSolid::displacement_at(const ProbeStencil& stencil) const {
  Vec2 u = Vec2::Zero();
  for (std::size_t k = 0; k < stencil.particles.size(); ++k)
    u += stencil.weights[k] * displacement(stencil.particles[k]);
  return u;
}

} // namespace fsi::tlsph
