#pragma once
// Partition of particles over the ranks by Zoltan's recursive coordinate bisection (RCB), written
// once for D = 2 and 3. Why RCB: it is geometric (needs only positions, no graph), cheap
// (O(N log P) median searches), its regions are boxes (a halo is "within r of a box", the owner
// of a point is a walk down the cut tree), and with RCB_REUSE a repartition starts from the
// previous cuts, so when the load drifts slowly most particles stay where they are. Each particle
// is one object with a weight, its load (OBJ_WEIGHT_DIM 1; 1 each when none is given): the
// bisection balances the sums of the weights directly, to the tolerance set (a cell of the
// neighbour grid as the object, weighted by its particles' loads, is coarser: the balance is only
// as fine as a cell's; see docs/architecture.md).
#include "parallel/communicator.hpp"
#include "particles/cell_binning.hpp"

#include <cstddef>
#include <span>
#include <vector>

struct Zoltan_Struct;

namespace fsi::parallel {

/// An axis-aligned region; the outer sides of the outer regions are at ±infinity.
template <int D> struct Box {
  VecD<D> lo, hi;
  bool contains(const VecD<D>& p) const {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
  }
  /// Euclidean distance from p to the box (0 inside).
  double distance(const VecD<D>& p) const { return (lo - p).cwiseMax(p - hi).cwiseMax(0.0).norm(); }
};

template <int D> class RcbPartition {
  static_assert(D == 2 || D == 3, "the partition is instantiated for D = 2 and D = 3");

public:
  /// `tolerance`: the largest (max / mean) sum of the weights RCB may leave, > 1.
  explicit RcbPartition(const Communicator& comm, double tolerance = 1.01);
  ~RcbPartition();
  RcbPartition(const RcbPartition&) = delete;
  RcbPartition& operator=(const RcbPartition&) = delete;

  /// Cuts the domain for the n local particles at x with weights `weight` (n values > 0, or
  /// empty: 1 each) so that every rank's sum of the weights is about the mean (collective);
  /// dest[i] is the rank that owns particle i in the new partition. A second call repartitions
  /// from the previous cuts.
  void partition(const particles::Coords<D>& x, std::size_t n, std::span<const float> weight,
                 std::vector<int>& dest);
  /// The owner of each of the n particles at x under the last partition's cuts (no
  /// communication): the destinations of a migration after the particles moved.
  void owners(const particles::Coords<D>& x, std::size_t n, std::vector<int>& dest) const;
  /// Every rank's region under the last partition (the same on every rank).
  const std::vector<Box<D>>& boxes() const { return boxes_; }
  /// How many partitions have been made (the first and the repartitions).
  int partitions() const { return partitions_; }

private:
  Communicator comm_;
  Zoltan_Struct* zz_ = nullptr;
  std::vector<Box<D>> boxes_;
  int partitions_ = 0;
};

/// The load imbalance max_r L_r / mean_r L_r of the local loads L (particle counts, or sums of
/// their weights) (collective); 1 if all are 0.
double imbalance(const Communicator& comm, double load);

extern template class RcbPartition<2>;
extern template class RcbPartition<3>;

} // namespace fsi::parallel
