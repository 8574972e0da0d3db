#include "particles/field_set.hpp"

#include "fsi/core/parallel.hpp"
#include "fsi/core/state_archive.hpp"

#include <algorithm>
#include <cassert>

namespace fsi::particles {

namespace {
template <class T, class S>
void permute_one(std::vector<T>& a, const std::vector<std::uint32_t>& order, std::vector<S>& tmp) {
  tmp.resize(a.size());
  parallel_for(a.size(), [&](std::size_t i) { tmp[i] = static_cast<S>(a[order[i]]); });
  parallel_for(a.size(), [&](std::size_t i) { a[i] = static_cast<T>(tmp[i]); });
}

template <class T>
void compact_one(std::vector<T>& a, const std::vector<std::uint8_t>& keep, std::size_t kept) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (keep[i]) a[n++] = a[i];
  a.resize(kept);
}

template <class T> void save_all(const T& fields, auto& into, std::size_t n) {
  into.resize(fields.size());
  std::size_t k = 0;
  for (const auto& f : fields)
    if (f.state)
      into[k++].assign(f.values.begin(), f.values.begin() + static_cast<std::ptrdiff_t>(n));
}

template <class T> void restore_all(T& fields, const auto& from) {
  std::size_t k = 0;
  for (auto& f : fields)
    if (f.state) f.values.assign(from[k].begin(), from[k].end()), ++k;
}
} // namespace

std::vector<double>& FieldSet::add_real(const std::string& name, bool state) {
  assert(!has(name) && "FieldSet: a field of this name is registered already");
  return reals_.push_back({name, state, std::vector<double>(size_, 0.0)}), reals_.back().values;
}
std::vector<std::uint8_t>& FieldSet::add_flag(const std::string& name, bool state) {
  assert(!has(name) && "FieldSet: a field of this name is registered already");
  return flags_.push_back({name, state, std::vector<std::uint8_t>(size_, 0)}), flags_.back().values;
}
std::vector<std::uint32_t>& FieldSet::add_index(const std::string& name, bool state) {
  assert(!has(name) && "FieldSet: a field of this name is registered already");
  return indices_.push_back({name, state, std::vector<std::uint32_t>(size_, 0)}),
         indices_.back().values;
}

void FieldSet::resize(std::size_t n) {
  for (auto& f : reals_) f.values.resize(n, 0.0);
  for (auto& f : flags_) f.values.resize(n, 0);
  for (auto& f : indices_) f.values.resize(n, 0);
  size_ = n;
}

void FieldSet::permute(const std::vector<std::uint32_t>& order, std::vector<double>& scratch) {
  for (auto& f : reals_) permute_one(f.values, order, scratch);
  for (auto& f : flags_) permute_one(f.values, order, scratch);   // small integers: exact in double
  for (auto& f : indices_) permute_one(f.values, order, scratch); // < 2^32: exact in double
}

std::size_t FieldSet::compact(const std::vector<std::uint8_t>& keep) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < size_; ++i) kept += keep[i] ? 1 : 0;
  for (auto& f : reals_) compact_one(f.values, keep, kept);
  for (auto& f : flags_) compact_one(f.values, keep, kept);
  for (auto& f : indices_) compact_one(f.values, keep, kept);
  const std::size_t removed = size_ - kept;
  size_ = kept;
  return removed;
}

void FieldSet::save(Snapshot& into, std::size_t count) const {
  into.size = std::min(count, size_);
  save_all(reals_, into.reals, into.size);
  save_all(flags_, into.flags, into.size);
  save_all(indices_, into.indices, into.size);
}

void FieldSet::restore(const Snapshot& from) {
  resize(from.size);
  restore_all(reals_, from.reals);
  restore_all(flags_, from.flags);
  restore_all(indices_, from.indices);
}

void FieldSet::write_state(StateArchive& a, const std::string& prefix, std::size_t count) const {
  const auto n = static_cast<std::ptrdiff_t>(std::min(count, size_));
  for (const auto& f : reals_)
    if (f.state)
      a.put(prefix + f.name, std::vector<double>(f.values.begin(), f.values.begin() + n));
  for (const auto& f : flags_)
    if (f.state)
      a.put(prefix + f.name, std::vector<std::int64_t>(f.values.begin(), f.values.begin() + n));
  for (const auto& f : indices_)
    if (f.state)
      a.put(prefix + f.name, std::vector<std::int64_t>(f.values.begin(), f.values.begin() + n));
}

void FieldSet::read_state(const StateArchive& a, const std::string& prefix) {
  // The first state array fixes the size; every other one must match it (StateArchive checks).
  std::size_t n = size_;
  if (!reals_.empty()) n = a.reals(prefix + reals_.front().name).size();
  resize(n);
  for (auto& f : reals_)
    if (f.state) f.values = a.reals(prefix + f.name, n);
  for (auto& f : flags_)
    if (f.state) f.values = a.ints<std::uint8_t>(prefix + f.name, n);
  for (auto& f : indices_)
    if (f.state) f.values = a.ints<std::uint32_t>(prefix + f.name, n);
}

std::size_t FieldSet::bytes_per_particle(const FieldList& only) const {
  std::size_t bytes = 0;
  for_each_array(only, [&](const auto& values) { bytes += sizeof(values[0]); });
  return bytes;
}

bool FieldSet::has(const std::string& name) const {
  const auto all = names();
  return std::find(all.begin(), all.end(), name) != all.end();
}

std::vector<std::string> FieldSet::names() const {
  std::vector<std::string> out;
  for (const auto& f : reals_) out.push_back(f.name);
  for (const auto& f : flags_) out.push_back(f.name);
  for (const auto& f : indices_) out.push_back(f.name);
  return out;
}

} // namespace fsi::particles
