#pragma once
// What a particle fluid's model needs to run decomposed over ranks (issue 47), once for every
// particle fluid (EMPS and SPH, 2-D and 3-D): the exchange hook it hands its fluid, the ranks,
// global counts, and a frame's rows gathered to rank 0 in global id order, so a one-process
// file and an N-process one compare entry by entry. Not decomposed (a plain run), it holds
// nothing and every count is the local one.
#include "fsi_app/ranks.hpp"
#include "fsi_app/scene.hpp"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fsi::app {

template <int D> class DecomposedParticles {
public:
  /// A new hook over `ranks` for a fluid of `particles` particles (every rank built the whole
  /// fluid); the caller hands it to the fluid. InputError if some rank would get none, or the
  /// message of refuse().
  particles::Decomposition<D>& decompose(const Ranks& ranks, std::size_t particles);
  /// decompose() throws InputError(message) (`FILE:LINE: key: what`): a fluid that cannot run
  /// decomposed; an empty message: none.
  void refuse(std::string message) { refusal_ = std::move(message); }
  bool decomposed() const { return ranks_ != nullptr; }
  /// A count over every rank when decomposed (exact: a sum of integers below 2^53).
  std::size_t global(std::size_t local) const;
  /// A sum over every rank when decomposed.
  double sum(double local) const { return hook_ ? hook_->sum(local) : local; }
  /// Bytes every rank has sent for ghosts so far (halo builds and updates), summed (collective).
  double halo_bytes() const { return hook_ ? hook_->sum(hook_->halo_bytes()) : 0.0; }
  /// Every rank's `values` summed entry by entry, the same bits on every rank (Ranks::sum).
  void sum(std::vector<double>& values) const {
    if (ranks_) ranks_->sum(values);
  }

  /// Collective: every probe's value by `evaluate` (itself collective, the same calls in the
  /// same order on every rank), kept for probe_value on rank 0, which alone asks.
  template <class Evaluate>
  void evaluate_probes(const std::vector<ProbeSpec>& probes, Evaluate evaluate) {
    values_.clear();
    for (const ProbeSpec& p : probes) values_.emplace_back(p.key, evaluate(p));
  }
  /// The last evaluate_probes value of the probe `p` names (by its key).
  std::optional<double> probe_value(const ProbeSpec& p) const {
    for (const auto& [key, value] : values_)
      if (key == p.key) return value;
    return std::nullopt;
  }

  /// Collective: rows of k values (row[0] the particle's id) of this rank's first `owned`
  /// particles, filled by pack(i, row), to rank 0 sorted by id; no allocation once the largest
  /// frame has been gathered.
  template <class Pack> void gather(std::size_t owned, std::size_t k, Pack pack) {
    k_ = k;
    packed_.resize(k * owned);
    for (std::size_t i = 0; i < owned; ++i) pack(i, &packed_[k * i]);
    gather_packed();
  }
  /// The last gather's particle count (0 on ranks other than 0) and value c of the j-th in id
  /// order (column-major: column(c)[j]).
  std::size_t gathered() const { return k_ ? sorted_.size() / k_ : 0; }
  const double* column(std::size_t c) const { return sorted_.data() + c * gathered(); }

private:
  void gather_packed();

  std::unique_ptr<particles::Decomposition<D>> hook_;
  const Ranks* ranks_ = nullptr;
  std::string refusal_;
  std::size_t k_ = 0;
  std::vector<double> packed_, all_, sorted_; // this rank's rows; every rank's; columns (rank 0)
  std::vector<std::size_t> order_;            // all_'s rows in id order
  std::vector<std::pair<std::string, std::optional<double>>> values_; // by probe key
};

extern template class DecomposedParticles<2>;
extern template class DecomposedParticles<3>;

} // namespace fsi::app
