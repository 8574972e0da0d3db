#pragma once
// Fluid particles as struct-of-arrays in a field registry: every array is resized, permuted by
// cell, compacted on removal, saved, restored and checkpointed together (particles/field_set.hpp).
#include "particles/field_set.hpp"

#include <cstdint>
#include <vector>

namespace fsi::emps {

struct Particles {
  particles::FieldSet fields;
  std::vector<double>& x = fields.add_real("x"); ///< position, m
  std::vector<double>& y = fields.add_real("y");
  std::vector<double>& vx = fields.add_real("vx"); ///< velocity, m/s
  std::vector<double>& vy = fields.add_real("vy");
  std::vector<double>& p = fields.add_real("p");     ///< pressure, Pa (eq. 15)
  std::vector<double>& pnd = fields.add_real("pnd"); ///< n* incl. the wall term (eq. 20)
  std::vector<std::uint8_t>& surface = fields.add_flag("surface"); ///< free surface (eq. 17)
  std::vector<std::uint32_t>& id = fields.add_index("id"); ///< stable identity, for messages

  std::size_t size() const { return fields.size(); }
  void resize(std::size_t n) { fields.resize(n); }
  /// Applies new_index -> old_index to every array; `scratch` avoids allocation.
  void permute(const std::vector<std::uint32_t>& order, std::vector<double>& scratch) {
    fields.permute(order, scratch);
  }
  /// Keeps only particles with keep[i] != 0, in order. Returns how many were removed.
  std::size_t compact(const std::vector<std::uint8_t>& keep) { return fields.compact(keep); }
};

} // namespace fsi::emps
