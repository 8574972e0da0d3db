#pragma once
// The exchange hook of a particle solver decomposed over processes (issue 47): the solver calls
// it at the points of its step where particles change owner or where a field its pair sums read
// has changed; the serial hook (LocalParticles) does nothing there and reduces nothing.
// parallel/ implements it over MPI (parallel::ParticleDecomposition, Zoltan RCB, migration and
// halos). Layout contract: the first size() - ghosts() entries of the FieldSet are the particles
// this process owns; ghosts (copies of other processes' particles) follow them, so a neighbour
// search over the whole set sees them. Pair loops read ghosts and write owned particles only.
// Every call but ghosts() and fail() is collective: each process makes the same calls in the
// same order.
//
// Failure on some processes only (an unstable step, a NaN): the solver calls fail(what) where it
// finds it and goes on to its next reduction, which throws RunError on every process with the
// message of the lowest failing one, so no process is left waiting in a collective. The serial
// hook throws at fail() itself.
#include "fsi/core/error.hpp"
#include "particles/field_set.hpp"
#include "particles/vector_field.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace fsi::particles {

template <int D> class Decomposition {
public:
  virtual ~Decomposition() = default;

  /// Removes the ghosts and moves every owned particle to the process whose region holds it
  /// now (repartitioning when the load has drifted; the first call partitions: each process
  /// holds distinct particles then, e.g. its block of the fill, particles/setup_block.hpp); `x` is
  /// the set's position field. `work`, an array of the set or null (none): each particle's work
  /// beyond a bulk particle's, in units of a bulk particle's (>= 0), so that a particle's load is 1
  /// + work: the partition balances the processes' sums of the loads, and the drift is judged on
  /// them. Returns whether the owned particles' order changed.
  virtual bool migrate(FieldSet& fields, const VectorField<D>& x,
                       const std::vector<double>* work) = 0;
  /// Appends, after the owned particles, copies of every other process's particles that may
  /// come within `reach` of an owned particle (the set holds no ghosts on entry).
  virtual void build_ghosts(FieldSet& fields, const VectorField<D>& x, double reach) = 0;
  /// Copies the owners' current values of the arrays `changed` names onto the ghosts, same
  /// order: the caller names the arrays that changed since the ghosts were last sent and that
  /// a pair sum reads (an empty list: every array).
  virtual void update_ghosts(FieldSet& fields, const FieldList& changed) = 0;
  /// Removes the ghosts (before owned particles are removed or reordered).
  virtual void drop_ghosts(FieldSet& fields) = 0;
  /// How many of the set's last entries are ghosts.
  virtual std::size_t ghosts() const = 0;
  /// Bytes this process has sent to others for ghosts (builds and updates) so far.
  virtual double halo_bytes() const = 0;
  /// Wall seconds this process has waited in collectives (exchanges and reductions) so far.
  virtual double waited_seconds() const = 0;
  /// Partitions made so far (the first and the repartitions; 0 on one process).
  virtual int partitions() const = 0;
  /// The load imbalance max / mean over the processes of their loads' sums (see migrate) as the
  /// last migration found it, before it moved anything (1 on one process).
  virtual double load_imbalance() const = 0;

  /// Global reductions over every process (the same value on each).
  virtual double sum(double v) const = 0;
  /// Every process's `values` summed entry by entry, in one message (sizes agree).
  virtual void sum(std::vector<double>& values) const = 0;
  virtual double max(double v) const = 0;
  virtual double min(double v) const = 0;
  /// True on every process iff `v` is true on every process.
  virtual bool all(bool v) const = 0;

  /// This process cannot go on (not collective): the next reduction (sum, max, min, all or
  /// agree) throws RunError(what, naming this process) on every process; with several failing,
  /// the lowest one's. The solver must reach that reduction without further harm (its
  /// neighbour rows truncated, positions not finite) and without throwing.
  virtual void fail(const std::string& what) = 0;
  /// A reduction that only agrees on fail(): throws on every process if any failed.
  virtual void agree() = 0;

  /// This process's number, 0 .. processes() - 1, and the count (not collective).
  virtual int rank() const = 0;
  virtual int processes() const = 0;
  /// Every process's `local`, concatenated in process order, into `all` on process 0 (emptied
  /// on the others): a decomposed checkpoint, written by process 0.
  virtual void gather(const std::vector<double>& local, std::vector<double>& all) const = 0;
};

/// One process owns every particle: no ghosts, nothing moves, a reduction is its argument
/// (PeriodicImages adds ghosts to it).
template <int D> class LocalParticles : public Decomposition<D> {
public:
  bool migrate(FieldSet&, const VectorField<D>&, const std::vector<double>*) override {
    return false;
  }
  void build_ghosts(FieldSet&, const VectorField<D>&, double) override {}
  void update_ghosts(FieldSet&, const FieldList&) override {}
  void drop_ghosts(FieldSet&) override {}
  std::size_t ghosts() const override { return 0; }
  double halo_bytes() const override { return 0.0; }
  double waited_seconds() const override { return 0.0; }
  int partitions() const override { return 0; }
  double load_imbalance() const override { return 1.0; }
  double sum(double v) const override { return v; }
  void sum(std::vector<double>&) const override {}
  double max(double v) const override { return v; }
  double min(double v) const override { return v; }
  bool all(bool v) const override { return v; }
  void fail(const std::string& what) override { throw RunError(what); }
  void agree() override {}
  int rank() const override { return 0; }
  int processes() const override { return 1; }
  void gather(const std::vector<double>& local, std::vector<double>& all) const override {
    all = local;
  }
};

} // namespace fsi::particles
