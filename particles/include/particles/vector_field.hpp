#pragma once
// A D-component vector field in a FieldSet: D reals named prefix + x, y (, z) + suffix, the names
// the 2-D solvers give their x/y arrays ("x", "y"; "vx", "vy"; "x0", "y0"), so a solver moved to
// add_vector keeps its field names and checkpoints. The components are ordinary reals: resizing,
// permuting by cell, compaction, save/restore and checkpoints go through the registry.
#include "particles/cell_binning.hpp"
#include "particles/field_set.hpp"

#include <array>
#include <string>
#include <vector>

namespace fsi::particles {

/// The D component arrays of a vector field registered in a FieldSet.
template <int D> struct VectorField {
  std::array<std::vector<double>*, D> component;
  std::vector<double>& operator[](int axis) const {
    return *component[static_cast<std::size_t>(axis)];
  }
  /// The arrays' data as the grids bin them; valid until the set is resized or compacted.
  Coords<D> coords() const {
    Coords<D> c;
    for (std::size_t a = 0; a < D; ++a) c[a] = component[a]->data();
    return c;
  }
};

/// Registers the reals prefix + "x", "y" (, "z") + suffix in `fields`: ("") gives x, y; ("v")
/// vx, vy; ("", true, "0") x0, y0. `state` as for FieldSet::add_real.
template <int D>
VectorField<D> add_vector(FieldSet& fields, const std::string& prefix, bool state = true,
                          const std::string& suffix = "");

extern template VectorField<2> add_vector<2>(FieldSet&, const std::string&, bool,
                                             const std::string&);
extern template VectorField<3> add_vector<3>(FieldSet&, const std::string&, bool,
                                             const std::string&);

} // namespace fsi::particles
