#pragma once
// The particle set of the MPI tests: N particles with global ids 0..N-1, each a pure function
// of its id (position in the unit box [0, 1]^D, a mass, a flag), so every rank can compute the
// serial reference of any particle without communication. Rank r starts with the ids g with
// g % P == r: scattered over the whole box, so the first partition moves almost everything.
#include "parallel/communicator.hpp"
#include "particles/field_set.hpp"
#include "particles/vector_field.hpp"

#include <cstdint>
#include <vector>

namespace fsi::parallel::test {

/// A uniform double in [0, 1) from (id, salt): splitmix64.
inline double hash01(std::uint64_t id, std::uint64_t salt) {
  std::uint64_t z =
      id * 0x9E3779B97F4A7C15ull + salt * 0xD1B54A32D1B54A33ull + 0x632BE59BD9B4E019ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

/// The reference values of particle `id`. The cloud is denser towards x = 0 (x = u^2 along the
/// first axis), so equal counts need unequal boxes.
template <int D> double position(std::uint32_t id, int axis) {
  const double u = hash01(id, static_cast<std::uint64_t>(axis));
  return axis == 0 ? u * u : u;
}
inline double mass(std::uint32_t id) {
  return 1.0 + hash01(id, 7);
}
inline std::uint8_t tag(std::uint32_t id) {
  return static_cast<std::uint8_t>(id % 7);
}
/// A displacement of up to ±0.05 per axis for step `step`.
inline double displacement(std::uint32_t id, int axis, int step) {
  return 0.1 * (hash01(id, 100 + static_cast<std::uint64_t>(10 * step + axis)) - 0.5);
}

/// A FieldSet with x (D reals), m, id, tag and a scratch real; holds references into itself.
template <int D> struct Cloud {
  particles::FieldSet fields;
  particles::VectorField<D> x = particles::add_vector<D>(fields, "");
  std::vector<double>& m = fields.add_real("m");
  std::vector<std::uint32_t>& id = fields.add_index("id");
  std::vector<std::uint8_t>& flag = fields.add_flag("tag");
  std::vector<double>& scratch = fields.add_real("scratch", false);

  /// Rank `rank` of `ranks`: the ids g < n with g % ranks == rank.
  Cloud(std::uint32_t n, int rank, int ranks) {
    std::size_t local = 0;
    for (std::uint32_t g = 0; g < n; ++g) local += static_cast<int>(g % ranks) == rank ? 1 : 0;
    fields.resize(local);
    std::size_t i = 0;
    for (std::uint32_t g = 0; g < n; ++g)
      if (static_cast<int>(g % ranks) == rank) {
        for (int a = 0; a < D; ++a) x[a][i] = position<D>(g, a);
        m[i] = mass(g), id[i] = g, flag[i] = tag(g), scratch[i] = -1.0;
        ++i;
      }
  }
  std::size_t size() const { return fields.size(); }
  VecD<D> at(std::size_t i) const {
    VecD<D> p;
    for (int a = 0; a < D; ++a) p[a] = x[a][i];
    return p;
  }
};

/// owner[g] = the rank holding id g among the first n entries of each rank's ids, or -1 if no
/// rank or several hold it (collective).
inline std::vector<int> owners_of(const Communicator& comm, const std::vector<std::uint32_t>& ids,
                                  std::size_t n, std::uint32_t total) {
  std::vector<int> count(total, 0), rank_sum(total, 0);
  for (std::size_t i = 0; i < n; ++i) count[ids[i]] += 1, rank_sum[ids[i]] += comm.rank();
  MPI_Allreduce(MPI_IN_PLACE, count.data(), static_cast<int>(total), MPI_INT, MPI_SUM, comm.comm());
  MPI_Allreduce(MPI_IN_PLACE, rank_sum.data(), static_cast<int>(total), MPI_INT, MPI_SUM,
                comm.comm());
  for (std::uint32_t g = 0; g < total; ++g)
    if (count[g] != 1) rank_sum[g] = -1;
  return rank_sum;
}

} // namespace fsi::parallel::test
