#pragma once
// The coupler's S in a decomposed run (issue 47): the scene's structures are solved on rank 0
// and their interface motion broadcast from it after each solve, so every rank's fluid sees the
// same walls and every rank's coupling scheme computes on the same motion. Rank 0 because it
// writes the frames, the probes, run.json and the checkpoints, which read the structures' state:
// solved there, the state needs no transfer. Not decomposed (one process), every call is the
// wrapped solver's.
#include "coupling/interface.hpp"
#include "fsi_app/ranks.hpp"

#include <string>
#include <vector>

namespace fsi::app {

template <int D> class RootStructures final : public coupling::BasicStructureSolver<D> {
public:
  explicit RootStructures(coupling::BasicStructureSolver<D>& structures) : solver_(structures) {}
  /// From now on solved on rank 0 of `ranks` (which outlive this); collective. Every rank holds
  /// the same state on entry (each built the scene and read the checkpoint).
  void decompose(const Ranks& ranks);
  void initialize() override { solver_.initialize(); }
  void set_interface_loads(const coupling::BasicInterfaceLoads<D>& loads) override {
    if (solves()) solver_.set_interface_loads(loads);
  }
  /// Rank 0 solves; then its motion reaches every rank (collective when decomposed). A
  /// RunError of rank 0's solve is thrown on every rank (rank 0's message there).
  void advance(double t, double dt) override;
  coupling::BasicInterfaceMotion<D> interface_motion() const override {
    return ranks_ ? motion_ : solver_.interface_motion();
  }
  void save_state() override;
  void restore_state() override;
  /// Rank 0's is the state written (the other ranks' structures are not advanced).
  void write_state(StateArchive& archive) const override { solver_.write_state(archive); }
  void read_state(const StateArchive& archive) override { solver_.read_state(archive); }
  void finalize() override { solver_.finalize(); }

private:
  bool solves() const { return !ranks_ || ranks_->rank() == 0; }
  /// Rank 0's motion (and whether its solve failed, with `failure`) to every rank.
  void share(const std::string& failure);

  coupling::BasicStructureSolver<D>& solver_;
  const Ranks* ranks_ = nullptr;
  coupling::BasicInterfaceMotion<D> motion_, saved_; ///< rank 0's motion, on every rank
  std::vector<double> packed_;
};

extern template class RootStructures<2>;
extern template class RootStructures<3>;

} // namespace fsi::app
