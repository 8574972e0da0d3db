// External loads (interface nodes' forces, per-particle forces) and set positions and
// velocities: each followed by the stress and acceleration it changes.
#include <algorithm>
#include <string>

#include "fsi/core/error.hpp"
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

void TlsphSolid::update_loaded() {
  loaded_.clear();
  for (std::size_t i = 0; i < size(); ++i)
    if (!clamped_[i] && (fx_[i] != 0.0 || fy_[i] != 0.0))
      loaded_.push_back(static_cast<std::uint32_t>(i));
}

void TlsphSolid::set_interface_loads(const std::vector<Vec2>& forces) {
  if (forces.size() != interface_.size())
    throw InputError("tlsph: " + std::to_string(forces.size()) + " interface loads for " +
                     std::to_string(interface_.size()) + " interface nodes");
  std::fill(fx_.begin(), fx_.end(), 0.0);
  std::fill(fy_.begin(), fy_.end(), 0.0);
  for (std::size_t k = 0; k < interface_.size(); ++k) // a particle may carry several nodes
    fx_[interface_[k]] += forces[k].x(), fy_[interface_[k]] += forces[k].y();
  update_loaded();
  compute_acceleration(); // the loads act from now on (a^n of the next half kick)
}

void TlsphSolid::set_external_forces(const std::vector<Vec2>& forces) {
  if (forces.size() != size())
    throw InputError("tlsph: " + std::to_string(forces.size()) + " external forces for " +
                     std::to_string(size()) + " particles");
  for (std::size_t i = 0; i < size(); ++i) fx_[i] = forces[i].x(), fy_[i] = forces[i].y();
  update_loaded();
  compute_acceleration();
}

void TlsphSolid::set_free(const std::vector<Vec2>& values, std::vector<double>& ex,
                          std::vector<double>& ey, const char* what) {
  if (values.size() != size())
    throw InputError(std::string("tlsph: ") + what + " needs size() entries");
  for (std::size_t i = 0; i < size(); ++i)
    if (!clamped_[i]) ex[i] = values[i].x(), ey[i] = values[i].y();
  if (images_) prescribe(time_); // the odd images follow their partners
}

void TlsphSolid::set_positions(const std::vector<Vec2>& x) {
  set_free(x, x_, y_, "set_positions");
  compute_stress();
  compute_acceleration();
}

void TlsphSolid::set_velocities(const std::vector<Vec2>& v) {
  set_free(v, vx_, vy_, "set_velocities");
  compute_acceleration();
}

} // namespace fsi::tlsph
