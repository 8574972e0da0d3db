#include "fsi_app/root_structures.hpp"

#include "fsi/core/error.hpp"

#include <cstddef>
#include <string>

namespace fsi::app {

namespace {
// `motion`'s x, v and a node by node into `packed` (3 D n doubles), and back.
template <int D>
void pack_motion(const coupling::BasicInterfaceMotion<D>& motion, std::vector<double>& packed) {
  packed.clear();
  for (const auto* nodes : {&motion.x, &motion.v, &motion.a})
    for (const VecD<D>& p : *nodes)
      for (int k = 0; k < D; ++k) packed.push_back(p[k]);
}

template <int D>
void unpack_motion(const std::vector<double>& packed, coupling::BasicInterfaceMotion<D>& motion) {
  std::size_t i = 0;
  for (auto* nodes : {&motion.x, &motion.v, &motion.a})
    for (VecD<D>& p : *nodes)
      for (int k = 0; k < D; ++k) p[k] = packed[i++];
}

} // namespace

template <int D> void RootStructures<D>::decompose(const Ranks& ranks) {
  ranks_ = &ranks;
  motion_ = solver_.interface_motion(); // the same on every rank: each built the scene
  share("");
}

template <int D> void RootStructures<D>::advance(double t, double dt) {
  std::string failure;
  try {
    if (solves()) solver_.advance(t, dt);
  } catch (const RunError& e) { // rank 0 alone: every rank must stop at the same point
    if (!ranks_) throw;
    failure = e.what();
  }
  if (ranks_) share(failure);
}

template <int D> void RootStructures<D>::share(const std::string& failure) {
  if (solves()) {
    pack_motion(solver_.interface_motion(), packed_);
    packed_.push_back(failure.empty() ? 0.0 : 1.0);
  } else {
    packed_.resize(3 * D * motion_.size() + 1);
  }
  ranks_->broadcast(packed_);
  if (packed_.back() != 0.0)
    throw RunError(solves() ? failure : "a structure failed on rank 0, which solves it");
  unpack_motion(packed_, motion_);
}

template <int D> void RootStructures<D>::save_state() {
  if (solves()) solver_.save_state();
  saved_ = motion_;
}

template <int D> void RootStructures<D>::restore_state() {
  if (solves()) solver_.restore_state();
  motion_ = saved_; // rank 0's motion when saved: what its restored solver gives
}

template class RootStructures<2>;
template class RootStructures<3>;

} // namespace fsi::app
