#pragma once
// A registry of per-particle struct-of-arrays fields. A solver registers each array once, by name;
// resizing, reordering by cell, removal, save/restore for iterative coupling, checkpoints and the
// memory estimate then iterate over the registry, so no field list is written by hand twice.
// Arrays live in a deque: the references add_*() returns stay valid for the set's lifetime.
#include <algorithm>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace fsi {
class StateArchive;
}

namespace fsi::particles {

/// Some arrays of a FieldSet, named by the references its add_*() returned (or a VectorField's
/// components): what changed since the last halo update, so only they are resent. Default: every
/// array.
class FieldList {
public:
  FieldList() = default;
  template <class... Array>
  explicit FieldList(const Array&... arrays) : arrays_{static_cast<const void*>(&arrays)...} {}
  /// Also `array` (a std::vector the set registered).
  template <class Array> FieldList& add(const Array& array) {
    arrays_.push_back(&array);
    return *this;
  }
  bool has(const void* array) const {
    return arrays_.empty() || std::find(arrays_.begin(), arrays_.end(), array) != arrays_.end();
  }

private:
  std::vector<const void*> arrays_;
};

class FieldSet {
public:
  FieldSet() = default;
  FieldSet(const FieldSet&) = delete; // members hold references into the arrays
  FieldSet& operator=(const FieldSet&) = delete;

  /// Registers an array of n = size() zeros. `state`: part of the solver's state (saved,
  /// restored, checkpointed); otherwise scratch that each step recomputes (only resized and
  /// reordered). Names are unique (asserted).
  std::vector<double>& add_real(const std::string& name, bool state = true);
  std::vector<std::uint8_t>& add_flag(const std::string& name, bool state = true);
  std::vector<std::uint32_t>& add_index(const std::string& name, bool state = true);

  std::size_t size() const { return size_; }
  void resize(std::size_t n);
  /// Applies new_index -> old_index to every array; `scratch` avoids allocation.
  void permute(const std::vector<std::uint32_t>& order, std::vector<double>& scratch);
  /// Keeps only entries with keep[i] != 0, in order. Returns how many were removed.
  std::size_t compact(const std::vector<std::uint8_t>& keep);

  /// The state arrays' values; restore() returns them exactly (also the size).
  struct Snapshot {
    std::size_t size = 0;
    std::vector<std::vector<double>> reals;
    std::vector<std::vector<std::uint8_t>> flags;
    std::vector<std::vector<std::uint32_t>> indices;
  };
  /// The first `count` entries (all: size(); a decomposed set's owned ones). Reuses the
  /// snapshot's buffers: no allocation once they are large enough.
  void save(Snapshot& into, std::size_t count = std::size_t(-1)) const;
  void restore(const Snapshot& from);

  /// Every state array under prefix + name (doubles exact, integers as int64), of the first
  /// `count` particles (all: size(); a decomposed set's owned ones).
  void write_state(StateArchive& archive, const std::string& prefix,
                   std::size_t count = std::size_t(-1)) const;
  void read_state(const StateArchive& archive, const std::string& prefix);

  /// Bytes per entry over the registered arrays `only` names (default: every array).
  std::size_t bytes_per_particle(const FieldList& only = {}) const;
  /// Names of the registered arrays (reals, then flags, then indices, each in registration order).
  std::vector<std::string> names() const;
  bool has(const std::string& name) const;

  /// Calls f(values) on every registered array, state and scratch alike, in the order of
  /// names(); values is a std::vector of double, std::uint8_t or std::uint32_t. For code that
  /// moves whole particles between sets (parallel/: migration, halos) without a field list.
  template <class F> void for_each_array(F&& f) {
    for (auto& a : reals_) f(a.values);
    for (auto& a : flags_) f(a.values);
    for (auto& a : indices_) f(a.values);
  }
  template <class F> void for_each_array(F&& f) const {
    for (const auto& a : reals_) f(a.values);
    for (const auto& a : flags_) f(a.values);
    for (const auto& a : indices_) f(a.values);
  }
  /// The same over the arrays `only` names, in the order of names().
  template <class F> void for_each_array(const FieldList& only, F&& f) {
    for_each_array([&](auto& values) {
      if (only.has(&values)) f(values);
    });
  }
  template <class F> void for_each_array(const FieldList& only, F&& f) const {
    for_each_array([&](const auto& values) {
      if (only.has(&values)) f(values);
    });
  }

private:
  template <class T> struct Field {
    std::string name;
    bool state;
    std::vector<T> values;
  };
  std::size_t size_ = 0;
  std::deque<Field<double>> reals_;
  std::deque<Field<std::uint8_t>> flags_;
  std::deque<Field<std::uint32_t>> indices_;
};

} // namespace fsi::particles
