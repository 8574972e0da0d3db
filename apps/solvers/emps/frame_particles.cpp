#include "emps/frame_particles.hpp"

namespace fsi::app::emps_plugin {

namespace {

template <int D> FrameParticles<D> frame_of(const emps::BasicParticles<D>& p, std::size_t owned) {
  FrameParticles<D> f;
  f.n = owned;
  for (int a = 0; a < D; ++a) {
    f.x[static_cast<std::size_t>(a)] = p.position[a].data();
    f.v[static_cast<std::size_t>(a)] = p.velocity[a].data();
  }
  f.p = p.p.data(), f.pnd = p.pnd.data(), f.surface = p.surface.data();
  return f;
}

} // namespace

template <int D>
void GatheredParticles<D>::gather(DecomposedParticles<D>& ranks, const emps::BasicParticles<D>& p,
                                  std::size_t owned) {
  ranks.gather(owned, k, [&](std::size_t i, double* row) {
    row[0] = p.id[i];
    for (int a = 0; a < D; ++a) row[1 + a] = p.position[a][i], row[1 + D + a] = p.velocity[a][i];
    row[1 + 2 * D] = p.p[i], row[2 + 2 * D] = p.pnd[i], row[3 + 2 * D] = p.surface[i];
  });
  const double* surface = ranks.column(3 + 2 * D);
  surface_.resize(ranks.gathered());
  for (std::size_t j = 0; j < surface_.size(); ++j)
    surface_[j] = static_cast<std::uint8_t>(surface[j]);
}

template <int D>
FrameParticles<D> GatheredParticles<D>::view(const DecomposedParticles<D>& ranks,
                                             const emps::BasicParticles<D>& own,
                                             std::size_t owned) const {
  if (!ranks.decomposed()) return frame_of(own, owned);
  FrameParticles<D> f;
  f.n = ranks.gathered();
  for (std::size_t a = 0; a < D; ++a)
    f.x[a] = ranks.column(1 + a), f.v[a] = ranks.column(1 + D + a);
  f.p = ranks.column(1 + 2 * D), f.pnd = ranks.column(2 + 2 * D), f.surface = surface_.data();
  return f;
}

template class GatheredParticles<2>;
template class GatheredParticles<3>;

} // namespace fsi::app::emps_plugin
