#pragma once
// The processes a run is spread over (issue 47): one (every plain `fsi run`), or the MPI ranks of
// `mpirun -np N fsi run` (MpiRanks, apps/src/mpi_ranks.cpp, built only with FSI_HAVE_MPI). The
// driver writes its files on rank 0; a model decomposed over the ranks gathers each frame there.
// Every call but rank(), size() and decomposed() is collective.
#include "fsi/core/error.hpp"
#include "particles/decomposition.hpp"

#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace fsi::app {

class Ranks {
public:
  virtual ~Ranks() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// Whether the run is decomposed over MPI ranks (started by an MPI launcher, np = 1 included).
  virtual bool decomposed() const = 0;
  /// True on every rank iff `v` is true on every rank.
  virtual bool all(bool v) const = 0;
  /// The step's collective point (one reduction): the largest signal any rank received and, if
  /// some rank failed outside the models' step (`failure` not empty: writing a frame), the lowest
  /// failing rank's message, naming it, on every rank (empty if none failed).
  struct Agreed {
    int signal;
    std::string failure;
  };
  virtual Agreed agree(int signal, const std::string& failure) const = 0;
  /// The lowest rank's non-empty `failure`, as given, on every rank; empty if every rank passed
  /// an empty one (a check each rank makes on its block of the input, reported as one process).
  virtual std::string first(const std::string& failure) const = 0;
  /// A new exchange hook over these ranks for a particle fluid of dimension D (2 or 3) holding
  /// `particles`; InputError if some rank would get none (RCB gives every rank a particle).
  template <int D>
  std::unique_ptr<particles::Decomposition<D>> particle_decomposition(std::size_t particles) const {
    const auto n = particles;
    if (n < static_cast<std::size_t>(size()))
      throw InputError("fluid: " + std::to_string(n) + " particle" + (n == 1 ? "" : "s") + " for " +
                       std::to_string(size()) +
                       " processes; each needs at least one (run on at most " + std::to_string(n) +
                       ")");
    return new_decomposition(std::integral_constant<int, D>());
  }
  /// Every rank's `local`, concatenated in rank order, into `all` on rank 0 (emptied on the
  /// others); no allocation once `all` has held the largest frame.
  virtual void gather(const std::vector<double>& local, std::vector<double>& all) const = 0;
  /// All to all: `send`'s consecutive parts of counts[r] values go to rank r; `received` holds
  /// what every rank sent here, in rank order (a frame's rows to the ranks writing their places).
  virtual void exchange(const std::vector<double>& send, const std::vector<int>& counts,
                        std::vector<double>& received) const = 0;
  /// Every rank's `values` summed entry by entry, the same bits on every rank (sizes agree): a
  /// structure's interface loads from every rank's particles.
  virtual void sum(std::vector<double>& values) const = 0;
  /// Rank 0's `values` on every rank (sizes agree): a structure's motion from the rank solving it.
  virtual void broadcast(std::vector<double>& values) const = 0;

private:
  // particle_decomposition<D>'s hooks, one per dimension.
  virtual std::unique_ptr<particles::Decomposition<2>>
      new_decomposition(std::integral_constant<int, 2>) const = 0;
  virtual std::unique_ptr<particles::Decomposition<3>>
      new_decomposition(std::integral_constant<int, 3>) const = 0;
};

/// A failure already agreed over the ranks: every rank throws it, with the lowest failing rank's
/// message, so the driver stops without agreeing again (Ranks::agree).
struct AgreedError : RunError {
  using RunError::RunError;
};

/// Runs `body` on every rank (one collective phase: the same collective calls on every rank
/// whether or not it fails) and agrees on its success (one reduction): a RunError on some ranks
/// throws AgreedError on every rank. One process: `body` itself.
template <class F> void agreed(const Ranks& ranks, F&& body) {
  if (!ranks.decomposed()) return body();
  std::string failure;
  try {
    body();
  } catch (const AgreedError&) {
    throw; // an inner phase's: on every rank already
  } catch (const RunError& e) {
    failure = e.what();
  }
  const std::string first = ranks.agree(0, failure).failure;
  if (!first.empty()) throw AgreedError(first);
}

/// One process, not decomposed: the serial run.
class OneProcess final : public Ranks {
public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  bool decomposed() const override { return false; }
  bool all(bool v) const override { return v; }
  Agreed agree(int signal, const std::string& failure) const override { return {signal, failure}; }
  std::string first(const std::string& failure) const override { return failure; }
  void gather(const std::vector<double>& local, std::vector<double>& all) const override {
    all.assign(local.begin(), local.end());
  }
  void exchange(const std::vector<double>& send, const std::vector<int>&,
                std::vector<double>& received) const override {
    received.assign(send.begin(), send.end());
  }
  void sum(std::vector<double>&) const override {}
  void broadcast(std::vector<double>&) const override {}

private:
  std::unique_ptr<particles::Decomposition<2>>
  new_decomposition(std::integral_constant<int, 2>) const override {
    return std::make_unique<particles::LocalParticles<2>>();
  }
  std::unique_ptr<particles::Decomposition<3>>
  new_decomposition(std::integral_constant<int, 3>) const override {
    return std::make_unique<particles::LocalParticles<3>>();
  }
};

} // namespace fsi::app
