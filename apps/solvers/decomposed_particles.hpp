#pragma once
// What a particle fluid's model needs to run decomposed over ranks (issue 47), once for every
// particle fluid (EMPS and SPH, 2-D and 3-D): the exchange hook it hands its fluid, the ranks,
// global counts, and a frame's rows in global id order, so a one-process file and an N-process
// one compare entry by entry: gathered to rank 0, or, when fields.h5 is written collectively
// (writes_collectively), every rank a block of the file's rows, sent there by place with one
// all-to-all (FileRows). Not decomposed (a plain run), it holds nothing and every count is the
// local one.
#include "fsi_app/output/fields_file.hpp"
#include "fsi_app/output/json.hpp"
#include "fsi_app/ranks.hpp"
#include "fsi_app/scene.hpp"
#include "particles/setup_block.hpp"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fsi::app {

/// The positions of a fill one process builds its fluid with, and `block` saying which.
template <int D> struct FillBlock {
  std::vector<VecD<D>> positions;
  particles::SetupBlock block;
};

template <int D> class DecomposedParticles {
public:
  /// The part of the fill `filled` this process builds its fluid with: all on one process;
  /// under mpirun (ranks.decomposed()) this rank's block, at most ceil(n / P) positions
  /// (particles/setup_block.hpp), the fluid's start deferred to decompose(). Keeps the fill's
  /// count (filled()).
  FillBlock<D> setup(const Ranks& ranks, std::vector<VecD<D>> filled);
  /// setup() for a fill each process built its part of already: `part` the positions of ids
  /// [first, first + part.size()) of a fill of `filled` (on one process the whole, first 0).
  FillBlock<D> setup(const Ranks& ranks, std::vector<VecD<D>> part, std::size_t first,
                     std::size_t filled);
  /// The count of the fill of the last setup(): every rank's, also after a restart.
  std::size_t filled() const { return filled_; }
  /// The model read a checkpoint of `particles` particles, whole on every rank.
  void restored(std::size_t particles) { particles_ = particles; }
  /// A new hook over `ranks` for the fluid of the last setup() or restored(); the caller hands
  /// it to the fluid. InputError if some rank would get none, or the message of refuse().
  particles::Decomposition<D>& decompose(const Ranks& ranks);
  /// decompose() throws InputError(message) (`FILE:LINE: key: what`): a fluid that cannot run
  /// decomposed; an empty message: none.
  void refuse(std::string message) { refusal_ = std::move(message); }
  bool decomposed() const { return ranks_ != nullptr; }
  /// A count over every rank when decomposed (exact: a sum of integers below 2^53).
  std::size_t global(std::size_t local) const;
  /// A sum over every rank when decomposed.
  double sum(double local) const { return hook_ ? hook_->sum(local) : local; }
  /// The least and the largest of `local` over every rank when decomposed (collective).
  double min(double local) const { return hook_ ? hook_->min(local) : local; }
  double max(double local) const { return hook_ ? hook_->max(local) : local; }
  /// Bytes every rank has sent for ghosts so far (halo builds and updates), summed (collective).
  double halo_bytes() const { return hook_ ? hook_->sum(hook_->halo_bytes()) : 0.0; }
  /// Collective, decomposed: the spread over the ranks of their owned particles and of the wall
  /// seconds each waited in collectives (the waiting of the slowest rank's peers: the imbalance),
  /// the partitions made and the loads' imbalance the last migration judged.
  JsonObject balance(std::size_t owned) const;
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
  /// particles, filled by pack(i, row), sorted by id: to rank 0 or, written collectively, every
  /// rank the block of file rows rows() names; no allocation once the largest frame was held.
  template <class Pack> void gather(std::size_t owned, std::size_t k, Pack pack) {
    k_ = k;
    packed_.resize(k * owned);
    for (std::size_t i = 0; i < owned; ++i) pack(i, &packed_[k * i]);
    gather_packed();
  }
  /// The block of fields.h5's rows the last gather left here when each rank writes its own,
  /// else null.
  const FileRows* rows() const { return own_rows_ ? &rows_ : nullptr; }
  /// Over the frame's rows on every rank: collective when each rank holds its own (rows()),
  /// else (every row here, or one process) the value itself.
  double frame_sum(double v) const { return own_rows_ ? hook_->sum(v) : v; }
  double frame_max(double v) const { return own_rows_ ? hook_->max(v) : v; }
  double frame_min(double v) const { return own_rows_ ? hook_->min(v) : v; }
  /// The last gather's particle count (rank 0's: every rank's, 0 on the others; rows(): its
  /// block's) and value c of the j-th in id order (column-major: column(c)[j]).
  std::size_t gathered() const { return k_ ? sorted_.size() / k_ : 0; }
  const double* column(std::size_t c) const { return sorted_.data() + c * gathered(); }

private:
  void gather_packed();
  /// The places of this rank's rows (sorted_, in id order) in a one-process file (places_).
  void place_rows();
  /// Sends every row to the rank writing its place (rows_: a block each, by place) and leaves
  /// that rank's block in sorted_, in place order.
  void to_blocks();

  std::unique_ptr<particles::Decomposition<D>> hook_;
  const Ranks* ranks_ = nullptr;
  bool own_rows_ = false; // writes_collectively: each rank keeps its rows
  FileRows rows_;
  std::vector<double> present_;     // place_rows: 1 per id held by some rank
  std::vector<std::size_t> places_; // place_rows: sorted_'s rows' places
  std::vector<double> send_;        // to_blocks: rows with their places, by destination
  std::vector<int> counts_;         // to_blocks: values sent to each rank
  std::string refusal_;
  std::size_t particles_ = 0; // the fill's count, or the checkpoint's (decompose)
  std::size_t filled_ = 0;    // the fill's count
  std::size_t k_ = 0;
  std::vector<double> packed_, all_, sorted_; // this rank's rows; every rank's; columns (rank 0)
  std::vector<std::size_t> order_;            // all_'s rows in id order
  std::vector<std::pair<std::string, std::optional<double>>> values_; // by probe key
};

extern template class DecomposedParticles<2>;
extern template class DecomposedParticles<3>;

} // namespace fsi::app
