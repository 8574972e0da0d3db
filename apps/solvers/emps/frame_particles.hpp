#pragma once
// The particles a frame and the probes of an EMPS model read (EmpsModel, EmpsModel3): the
// fluid's own on one process or, decomposed, every rank's owned particles gathered to rank 0 in
// global id order, so a one-process file and an N-process one compare entry by entry.
#include "fluid_emps/particles.hpp"
#include "fsi_app/ranks.hpp"

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

/// Every particle of a fluid on one process, in its own order.
template <int D> FrameParticles<D> frame_of(const emps::BasicParticles<D>& p);

/// The decomposed fluid's particles gathered to rank 0 (one Ranks::gather a frame; no
/// allocation once the largest frame has been gathered).
template <int D> class GatheredParticles {
public:
  /// Collective: the first `owned` particles of `p` on every rank to rank 0, sorted by id.
  void gather(const Ranks& ranks, const emps::BasicParticles<D>& p, std::size_t owned);
  /// The last gather's particles (none on ranks other than 0).
  FrameParticles<D> view() const;

private:
  static constexpr std::size_t k = 2 * D + 4; // values a particle: id, x, v, p, pnd, surface
  std::vector<double> packed_, all_;          // this rank's rows; every rank's (on rank 0)
  std::vector<std::size_t> order_;            // all_'s rows in id order
  std::array<std::vector<double>, D> x_, v_;
  std::vector<double> p_, pnd_;
  std::vector<std::uint8_t> surface_;
};

extern template FrameParticles<2> frame_of<2>(const emps::BasicParticles<2>&);
extern template FrameParticles<3> frame_of<3>(const emps::BasicParticles<3>&);
extern template class GatheredParticles<2>;
extern template class GatheredParticles<3>;

} // namespace fsi::app::emps_plugin
