#pragma once
// Fluid particles as struct-of-arrays in a field registry: every array is resized, permuted by
// cell, compacted on removal, saved, restored and checkpointed together (particles/field_set.hpp).
// Positions and velocities are D-component fields (x, y (, z); vx, vy (, vz)), the names the
// 2-D fluid always gave them, so 2-D checkpoints are unchanged.
#include "particles/field_set.hpp"
#include "particles/vector_field.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace fsi::emps {

template <int D> struct BasicParticles {
  particles::FieldSet fields;
  particles::VectorField<D> position = particles::add_vector<D>(fields, "");  ///< m
  particles::VectorField<D> velocity = particles::add_vector<D>(fields, "v"); ///< m/s
  /// The first two components by their 2-D names (the wall terms and the 2-D drivers use them).
  std::vector<double>& x = position[0];
  std::vector<double>& y = position[1];
  std::vector<double>& vx = velocity[0];
  std::vector<double>& vy = velocity[1];
  std::vector<double>& p = fields.add_real("p");     ///< pressure, Pa (eq. 15)
  std::vector<double>& pnd = fields.add_real("pnd"); ///< n* incl. the wall term (eq. 20)
  std::vector<std::uint8_t>& surface = fields.add_flag("surface"); ///< free surface (eq. 17)
  std::vector<std::uint32_t>& id = fields.add_index("id"); ///< stable identity, for messages
  /// Work beyond a bulk particle's, in bulk-particle units: its walls' (wall_work.hpp), the load
  /// the partition over processes balances (particles::Decomposition::migrate). Scratch.
  std::vector<double>& work = fields.add_real("work", false);

  std::size_t size() const { return fields.size(); }
  void resize(std::size_t n) { fields.resize(n); }
  /// Applies new_index -> old_index to every array; `scratch` avoids allocation.
  void permute(const std::vector<std::uint32_t>& order, std::vector<double>& scratch) {
    fields.permute(order, scratch);
  }
  /// Keeps only particles with keep[i] != 0, in order. Returns how many were removed.
  std::size_t compact(const std::vector<std::uint8_t>& keep) { return fields.compact(keep); }
};
using Particles = BasicParticles<2>;
using Particles3 = BasicParticles<3>;

/// The component arrays of a vector field, read once before a loop.
template <int D> std::array<double*, D> components(const particles::VectorField<D>& f) {
  std::array<double*, D> out;
  for (int a = 0; a < D; ++a) out[static_cast<std::size_t>(a)] = f[a].data();
  return out;
}
using Particles3 = BasicParticles<3>;

} // namespace fsi::emps
