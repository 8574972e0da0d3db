#include "particles/vector_field.hpp"

namespace fsi::particles {

template <int D>
VectorField<D> add_vector(FieldSet& fields, const std::string& prefix, bool state,
                          const std::string& suffix) {
  static constexpr std::array<const char*, 3> axes{"x", "y", "z"};
  VectorField<D> v;
  for (std::size_t a = 0; a < D; ++a)
    v.component[a] = &fields.add_real(prefix + axes[a] + suffix, state);
  return v;
}

template VectorField<2> add_vector<2>(FieldSet&, const std::string&, bool, const std::string&);
template VectorField<3> add_vector<3>(FieldSet&, const std::string&, bool, const std::string&);

} // namespace fsi::particles
