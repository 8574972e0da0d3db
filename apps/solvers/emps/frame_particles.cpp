#include "emps/frame_particles.hpp"

#include <algorithm>

namespace fsi::app::emps_plugin {

template <int D> FrameParticles<D> frame_of(const emps::BasicParticles<D>& p) {
  FrameParticles<D> f;
  f.n = p.size();
  for (int a = 0; a < D; ++a) {
    f.x[static_cast<std::size_t>(a)] = p.position[a].data();
    f.v[static_cast<std::size_t>(a)] = p.velocity[a].data();
  }
  f.p = p.p.data(), f.pnd = p.pnd.data(), f.surface = p.surface.data();
  return f;
}

template <int D>
void GatheredParticles<D>::gather(const Ranks& ranks, const emps::BasicParticles<D>& p,
                                  std::size_t owned) {
  packed_.resize(k * owned);
  for (std::size_t i = 0; i < owned; ++i) {
    double* row = &packed_[k * i];
    row[0] = p.id[i];
    for (int a = 0; a < D; ++a) row[1 + a] = p.position[a][i], row[1 + D + a] = p.velocity[a][i];
    row[1 + 2 * D] = p.p[i], row[2 + 2 * D] = p.pnd[i], row[3 + 2 * D] = p.surface[i];
  }
  ranks.gather(packed_, all_);
  const std::vector<double>& all = all_;
  const std::size_t n = all.size() / k;
  order_.resize(n);
  for (std::size_t j = 0; j < n; ++j) order_[j] = j;
  std::sort(order_.begin(), order_.end(),
            [&](std::size_t a, std::size_t b) { return all[k * a] < all[k * b]; });
  for (std::size_t a = 0; a < D; ++a) x_[a].resize(n), v_[a].resize(n);
  p_.resize(n), pnd_.resize(n), surface_.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const double* row = &all[k * order_[j]];
    for (std::size_t a = 0; a < D; ++a) x_[a][j] = row[1 + a], v_[a][j] = row[1 + D + a];
    p_[j] = row[1 + 2 * D], pnd_[j] = row[2 + 2 * D];
    surface_[j] = static_cast<std::uint8_t>(row[3 + 2 * D]);
  }
}

template <int D> FrameParticles<D> GatheredParticles<D>::view() const {
  FrameParticles<D> f;
  f.n = p_.size();
  for (std::size_t a = 0; a < D; ++a) f.x[a] = x_[a].data(), f.v[a] = v_[a].data();
  f.p = p_.data(), f.pnd = pnd_.data(), f.surface = surface_.data();
  return f;
}

template FrameParticles<2> frame_of<2>(const emps::BasicParticles<2>&);
template FrameParticles<3> frame_of<3>(const emps::BasicParticles<3>&);
template class GatheredParticles<2>;
template class GatheredParticles<3>;

} // namespace fsi::app::emps_plugin
