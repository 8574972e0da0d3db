#pragma once
// The exchange hook of a particle solver (particles::Decomposition) over MPI: Zoltan RCB regions,
// migration to the owner of each region and halos of every registered array (Halo, Migration,
// RcbPartition). The solver calls it; this class only moves particles and reduces numbers.
//
// Start: at the first migrate() each rank holds distinct particles (its block of the fill,
// particles/setup_block.hpp: a solver built whole on every rank keeps its block first), and the
// first RCB partition sends them to their regions. Later migrate() calls send particles to the
// owner of their position under the current cuts, or repartition (from the previous cuts) first
// when the imbalance max L / mean L exceeds `rebalance`.
//
// Load: a rank's L is the sum of its particles' loads 1 + work (particles::Decomposition::
// migrate; the solver says what a particle costs beyond a bulk one, e.g. the EMPS fluid its wall
// terms), the RCB weights; without `work`, L is the particle count.
//
// Halo reach: build_ghosts(reach) sends every particle within reach + d_out of another rank's
// box, d_out the largest distance (over all ranks) of an owned particle outside its own box
// (0 right after a migration; > 0 when a solver rebuilds its halo between migrations). So each
// owned particle sees every particle that comes within `reach` of where it was at the build.
//
// Failure: every reduction carries the fail() flag in its own MPI_Allreduce (two values where
// one was, no extra message); when it is set, the failing rank's message is broadcast and every
// rank throws RunError.
#include "parallel/halo.hpp"
#include "parallel/migration.hpp"
#include "parallel/rcb_partition.hpp"
#include "particles/decomposition.hpp"

#include <string>
#include <vector>

namespace fsi::parallel {

template <int D> class ParticleDecomposition final : public particles::Decomposition<D> {
public:
  /// `rebalance` > 1: the imbalance of the loads at which a migration repartitions first.
  explicit ParticleDecomposition(const Communicator& comm, double rebalance = 1.2);

  bool migrate(particles::FieldSet& fields, const particles::VectorField<D>& x,
               const std::vector<double>* work) override;
  void build_ghosts(particles::FieldSet& fields, const particles::VectorField<D>& x,
                    double reach) override;
  void update_ghosts(particles::FieldSet& fields, const particles::FieldList& changed) override;
  void drop_ghosts(particles::FieldSet& fields) override;
  std::size_t ghosts() const override { return active_ ? halo_.ghosts() : 0; }
  double halo_bytes() const override { return halo_.bytes_sent(); }
  double waited_seconds() const override { return collective_seconds(); }
  int partitions() const override { return rcb_.partitions(); }
  double load_imbalance() const override { return imbalance_; }

  double sum(double v) const override { return agreed(comm_.sum(v, failing())); }
  void sum(std::vector<double>& values) const override {
    agreed({0.0, comm_.sum(values, failing())});
  }
  double max(double v) const override { return agreed(comm_.max(v, failing())); }
  double min(double v) const override { return agreed(comm_.min(v, failing())); }
  bool all(bool v) const override { return agreed(comm_.min(v ? 1.0 : 0.0, failing())) != 0.0; }
  void fail(const std::string& what) override;
  void agree() override { agreed(comm_.max(0.0, failing())); }
  int rank() const override { return comm_.rank(); }
  int processes() const override { return comm_.size(); }
  void gather(const std::vector<double>& local, std::vector<double>& all) const override {
    comm_.gather(local, all);
  }

  /// Migrations and halo builds so far, and the particles that left this rank by migration.
  long migrations() const { return migrations_; }
  long halo_builds() const { return halo_builds_; }
  long emigrants() const { return emigrants_; }
  const std::vector<Box<D>>& boxes() const { return rcb_.boxes(); }

private:
  bool failing() const { return !failure_.empty(); }
  /// The reduced value, or RunError on every rank when some rank failed (this one's message
  /// cleared, so the hook serves the failed run's last gathers and reports).
  double agreed(Communicator::Flagged reduced) const;

  Communicator comm_;
  mutable std::string failure_; // the first fail() since the last reduction
  double rebalance_;
  RcbPartition<D> rcb_;
  Migration migration_;
  Halo<D> halo_;
  std::vector<int> dest_;
  std::vector<float> load_; // each owned particle's, 1 + work (the RCB weights)
  double imbalance_ = 1.0;  // the last migration's, before it moved anything
  bool active_ = false; // ghosts appended (the same on every rank: builds and drops are collective)
  long migrations_ = 0, halo_builds_ = 0, emigrants_ = 0;
};

extern template class ParticleDecomposition<2>;
extern template class ParticleDecomposition<3>;

} // namespace fsi::parallel
