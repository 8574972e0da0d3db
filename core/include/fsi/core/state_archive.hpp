#pragma once
// Named arrays of a run's state, for checkpoints. Each library writes and reads its own state
// through this neutral container (keys like "fluid/x", "structure/beam/u"); apps/ stores it as
// HDF5, so no solver library depends on a file format. Values are stored exactly (doubles as
// doubles, integers as int64), so a state read back continues a run bitwise.
#include "fsi/core/error.hpp"
#include "fsi/core/types.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace fsi {

class StateArchive {
public:
  void put(const std::string& key, std::vector<double> values) { reals_[key] = std::move(values); }
  void put(const std::string& key, std::vector<std::int64_t> values) {
    integers_[key] = std::move(values);
  }
  void put_real(const std::string& key, double value) { reals_[key] = {value}; }
  void put_integer(const std::string& key, std::int64_t value) { integers_[key] = {value}; }

  /// Any integer array (indices, flags, counters), stored as int64.
  template <class T> void put_ints(const std::string& key, const std::vector<T>& values) {
    put(key, std::vector<std::int64_t>(values.begin(), values.end()));
  }
  template <class T> std::vector<T> ints(const std::string& key, std::size_t size) const {
    const auto& v = integers(key, size);
    return std::vector<T>(v.begin(), v.end());
  }

  /// Throws InputError naming the key when it is missing (a checkpoint of another scene).
  const std::vector<double>& reals(const std::string& key) const { return find(reals_, key); }
  const std::vector<std::int64_t>& integers(const std::string& key) const {
    return find(integers_, key);
  }
  /// An array that must have `size` entries.
  const std::vector<double>& reals(const std::string& key, std::size_t size) const {
    return sized(reals(key), key, size);
  }
  const std::vector<std::int64_t>& integers(const std::string& key, std::size_t size) const {
    return sized(integers(key), key, size);
  }
  double real(const std::string& key) const { return reals(key, 1).front(); }
  std::int64_t integer(const std::string& key) const { return integers(key, 1).front(); }

  const std::map<std::string, std::vector<double>>& all_reals() const { return reals_; }
  const std::map<std::string, std::vector<std::int64_t>>& all_integers() const { return integers_; }

private:
  template <class T>
  static const std::vector<T>& find(const std::map<std::string, std::vector<T>>& map,
                                    const std::string& key) {
    const auto it = map.find(key);
    if (it == map.end()) throw InputError("checkpoint: no entry '" + key + "'");
    return it->second;
  }
  template <class T>
  static const std::vector<T>& sized(const std::vector<T>& v, const std::string& key,
                                     std::size_t size) {
    if (v.size() != size)
      throw InputError("checkpoint: '" + key + "' has " + std::to_string(v.size()) +
                       " entries, this scene needs " + std::to_string(size));
    return v;
  }

  std::map<std::string, std::vector<double>> reals_;
  std::map<std::string, std::vector<std::int64_t>> integers_;
};

/// VecD<D> arrays as interleaved x, y (, z) doubles and back (D = 2 when not given).
template <int D> std::vector<double> flatten(const std::vector<VecD<D>>& v) {
  std::vector<double> out(D * v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int d = 0; d < D; ++d) out[D * i + static_cast<std::size_t>(d)] = v[i][d];
  return out;
}
template <int D = 2> std::vector<VecD<D>> unflatten(const std::vector<double>& v) {
  std::vector<VecD<D>> out(v.size() / D);
  for (std::size_t i = 0; i < out.size(); ++i)
    for (int d = 0; d < D; ++d) out[i][d] = v[D * i + static_cast<std::size_t>(d)];
  return out;
}

} // namespace fsi
