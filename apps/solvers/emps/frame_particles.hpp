#pragma once
// The particles a frame and the probes of an EMPS model read (EmpsModel, EmpsModel3): the
// fluid's own on one process or, decomposed, every rank's owned particles gathered to rank 0 in
// global id order, so a one-process file and an N-process one compare entry by entry.
#include "decomposed_particles.hpp"
#include "fluid_emps/particles.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fsi::app::emps_plugin {

/// Read-only arrays of n particles (positions and velocities by axis).
template <int D> struct FrameParticles {
  std::size_t n = 0;
  std::array<const double*, D> x{}, v{};
  const double *p = nullptr, *pnd = nullptr;
  const std::uint8_t* surface = nullptr;
};

/// The decomposed fluid's particles gathered to rank 0 through the shared glue (one
/// Ranks::gather a frame; no allocation once the largest frame has been gathered).
template <int D> class GatheredParticles {
public:
  /// Collective: the first `owned` particles of `p` on every rank to rank 0, sorted by id.
  void gather(DecomposedParticles<D>& ranks, const emps::BasicParticles<D>& p, std::size_t owned);
  /// The particles a frame and the probes read: decomposed, the last gather's (none on ranks
  /// other than 0); otherwise the first `owned` particles of `own` (not the periodic images
  /// after them), in their own order.
  FrameParticles<D> view(const DecomposedParticles<D>& ranks, const emps::BasicParticles<D>& own,
                         std::size_t owned) const;

private:
  static constexpr std::size_t k = 2 * D + 4; // values a particle: id, x, v, p, pnd, surface
  std::vector<std::uint8_t> surface_;
};

extern template class GatheredParticles<2>;
extern template class GatheredParticles<3>;

} // namespace fsi::app::emps_plugin
