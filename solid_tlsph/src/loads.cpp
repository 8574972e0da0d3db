// External loads (interface nodes' forces, per-particle forces) and set positions and
// velocities: each followed by the stress and acceleration it changes.
#include <algorithm>
#include <string>

#include "fsi/core/error.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

template <int D> void BasicTlsphSolid<D>::update_loaded() {
  loaded_.clear();
  for (std::size_t i = 0; i < size(); ++i)
    if (!clamped_[i] && (at(f_, i).array() != 0.0).any())
      loaded_.push_back(static_cast<std::uint32_t>(i));
}

template <int D> void BasicTlsphSolid<D>::set_interface_loads(const std::vector<Vec>& forces) {
  if (forces.size() != interface_.size())
    throw InputError("tlsph: " + std::to_string(forces.size()) + " interface loads for " +
                     std::to_string(interface_.size()) + " interface nodes");
  for (int k = 0; k < D; ++k) std::fill(f_[k].begin(), f_[k].end(), 0.0);
  for (std::size_t n = 0; n < interface_.size(); ++n) // a particle may carry several nodes
    for (int k = 0; k < D; ++k) f_[k][interface_[n]] += forces[n](k);
  update_loaded();
  compute_acceleration(); // the loads act from now on (a^n of the next half kick)
}

template <int D> void BasicTlsphSolid<D>::set_external_forces(const std::vector<Vec>& forces) {
  if (forces.size() != size())
    throw InputError("tlsph: " + std::to_string(forces.size()) + " external forces for " +
                     std::to_string(size()) + " particles");
  for (std::size_t i = 0; i < size(); ++i)
    for (int k = 0; k < D; ++k) f_[k][i] = forces[i](k);
  update_loaded();
  compute_acceleration();
}

template <int D>
void BasicTlsphSolid<D>::set_free(const std::vector<Vec>& values, Field& field, const char* what) {
  if (values.size() != size())
    throw InputError(std::string("tlsph: ") + what + " needs size() entries");
  for (std::size_t i = 0; i < size(); ++i)
    if (!clamped_[i])
      for (int k = 0; k < D; ++k) field[k][i] = values[i](k);
  if (images_) prescribe(time_); // the odd images follow their partners
}

template <int D> void BasicTlsphSolid<D>::set_positions(const std::vector<Vec>& x) {
  set_free(x, x_, "set_positions");
  compute_stress();
  compute_acceleration();
}

template <int D> void BasicTlsphSolid<D>::set_velocities(const std::vector<Vec>& v) {
  set_free(v, v_, "set_velocities");
  compute_acceleration();
}

template void BasicTlsphSolid<2>::update_loaded();
template void BasicTlsphSolid<3>::update_loaded();
template void BasicTlsphSolid<2>::set_interface_loads(const std::vector<Vec2>&);
template void BasicTlsphSolid<3>::set_interface_loads(const std::vector<Vec3>&);
template void BasicTlsphSolid<2>::set_external_forces(const std::vector<Vec2>&);
template void BasicTlsphSolid<3>::set_external_forces(const std::vector<Vec3>&);
template void BasicTlsphSolid<2>::set_free(const std::vector<Vec2>&, Field&, const char*);
template void BasicTlsphSolid<3>::set_free(const std::vector<Vec3>&, Field&, const char*);
template void BasicTlsphSolid<2>::set_positions(const std::vector<Vec2>&);
template void BasicTlsphSolid<3>::set_positions(const std::vector<Vec3>&);
template void BasicTlsphSolid<2>::set_velocities(const std::vector<Vec2>&);
template void BasicTlsphSolid<3>::set_velocities(const std::vector<Vec3>&);

} // namespace fsi::tlsph
