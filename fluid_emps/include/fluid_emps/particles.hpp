#pragma once
// Fluid particles as struct-of-arrays. Every per-particle array has the same length and is
// permuted together (reordering by cell) and compacted together (removal).
#include <cstdint>
#include <vector>

namespace fsi::emps {

struct Particles {
  std::vector<double> x, y;          ///< position, m
  std::vector<double> vx, vy;        ///< velocity, m/s
  std::vector<double> p;             ///< pressure, Pa (eq. 15)
  std::vector<double> pnd;           ///< particle number density n* incl. the wall term (eq. 20)
  std::vector<std::uint8_t> surface; ///< free-surface flag (eq. 17)
  std::vector<std::uint32_t> id;     ///< stable identity, for messages and output

  std::size_t size() const { return x.size(); }
  void resize(std::size_t n);
  /// Applies new_index -> old_index to every array; `scratch` avoids allocation.
  void permute(const std::vector<std::uint32_t>& order, std::vector<double>& scratch);
  /// Keeps only particles with keep[i] != 0, in order. Returns how many were removed.
  std::size_t compact(const std::vector<std::uint8_t>& keep);
};

} // namespace fsi::emps
