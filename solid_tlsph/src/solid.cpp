// The TL-SPH solid's set-up (options checked, particles, reference data, first stress and
// acceleration), its reference-point lookup, and its state (save, restore, checkpoint).
#include "solid_tlsph/solid.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <sstream>

#include "fsi/core/error.hpp"
#include "fsi/core/state_archive.hpp"

namespace fsi::tlsph {

namespace {

template <class T> void require(bool ok, const std::string& key, T value, const char* range) {
  if (ok) return;
  std::ostringstream s;
  s << "tlsph: " << key << " = " << value << " must be " << range;
  throw InputError(s.str());
}

/// The reals NAME0 per axis ("X0", "Y0" (, "Z0")): reference positions, not state.
template <int D> particles::VectorField<D> reference_vector(particles::FieldSet& fields) {
  static constexpr std::array<const char*, 3> axes{"X0", "Y0", "Z0"};
  particles::VectorField<D> v;
  for (std::size_t k = 0; k < D; ++k) v.component[k] = &fields.add_real(axes[k], false);
  return v;
}

/// The reals name + "ij" of a D x D matrix, row-major (B00, B01, B10, B11), not state.
template <int D>
std::array<std::vector<double>*, D * D> tensor(particles::FieldSet& fields,
                                               const std::string& name) {
  std::array<std::vector<double>*, D * D> t;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j)
      t[static_cast<std::size_t>(D * i + j)] =
          &fields.add_real(name + std::to_string(i) + std::to_string(j), false);
  return t;
}

template <int D> auto make_law(const materials::MaterialOptions& o) {
  if constexpr (D == 2)
    return materials::make_material(o);
  else
    return materials::make_material_3d(o);
}

} // namespace

template <int D> void validate(const BasicTlsphOptions<D>& o) {
  materials::validate(o.material);
  require(o.dp > 0.0, "dp", o.dp, "> 0");
  require(o.h_factor >= 1.0 && o.h_factor <= 2.0, "h_factor", o.h_factor, "in [1, 2]");
  require(o.cfl > 0.0 && o.cfl <= 1.0, "cfl", o.cfl, "in (0, 1]");
  require(o.pair_damping >= 0.0, "pair_damping", o.pair_damping, ">= 0");
  require(o.mass_damping >= 0.0, "mass_damping", o.mass_damping, ">= 0");
  require(o.max_neighbors >= 8, "max_neighbors", o.max_neighbors, ">= 8");
  require(o.hourglass >= 0.0, "hourglass", o.hourglass, ">= 0");
  if (o.gradient_correction == GradientCorrection::quadratic && !o.kernel_correction)
    throw InputError("tlsph: gradient_correction = quadratic needs kernel_correction = true");
  require(o.gravity.allFinite(), "gravity", o.gravity.transpose(), "finite");
  for (std::size_t k = 0; k < o.clamps.size(); ++k) {
    const auto& c = o.clamps[k];
    if (!c.contains)
      throw InputError("tlsph: clamps[" + std::to_string(k) + "].contains is not set");
    if (!c.face_normal.allFinite() || !c.face_point.allFinite())
      throw InputError("tlsph: clamps[" + std::to_string(k) + "]: face is not finite");
    if (static_cast<bool>(c.position) != static_cast<bool>(c.velocity))
      throw InputError("tlsph: clamps[" + std::to_string(k) +
                       "]: set both position and velocity of a moving clamp, or neither");
  }
}

// The fields are registered in the order of the 2-D solid before it was written for D (x, y,
// vx, vy, ..., F11, PB00 .. PB11): the same names, checkpoints and output.
template <int D>
BasicTlsphSolid<D>::BasicTlsphSolid(Geometry geometry, Options options)
    : options_(std::move(options)), x_(particles::add_vector<D>(fields_, "")),
      v_(particles::add_vector<D>(fields_, "v")), a_(particles::add_vector<D>(fields_, "a")),
      f_(particles::add_vector<D>(fields_, "f")), X0_(reference_vector<D>(fields_)),
      V0_(fields_.add_real("V0", false)), B_(tensor<D>(fields_, "B")),
      clamped_(fields_.add_flag("clamp", false)), surface_(fields_.add_flag("surface", false)),
      F_(tensor<D>(fields_, "F")), PB_(tensor<D>(fields_, "PB")) {
  validate(options_);
  const std::size_t n = geometry.X0.size();
  if (n == 0) throw InputError("tlsph: the geometry holds no particles");
  if (geometry.V0.size() != n)
    throw InputError("tlsph: " + std::to_string(geometry.V0.size()) + " volumes for " +
                     std::to_string(n) + " particles");
  if (geometry.outline_tags.size() != geometry.outline.size())
    throw InputError("tlsph: outline has " + std::to_string(geometry.outline.size()) +
                     " edges but " + std::to_string(geometry.outline_tags.size()) + " tags");
  if constexpr (D == 3)
    if (!geometry.outline.empty())
      throw InputError("tlsph: a 3-D solid takes its interface from a box, not an outline");
  material_ = make_law<D>(options_.material);
  rho0_ = options_.material.density;
  h_ = options_.h_factor * options_.dp;
  {
    const double E = options_.material.youngs_modulus, nu = options_.material.poisson_ratio;
    const double K = E / (3.0 * (1.0 - 2.0 * nu)); // eq. 11
    c_s_ = std::sqrt(K / rho0_);
  }
  fields_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!(geometry.V0[i] > 0.0))
      throw InputError("tlsph: particle " + std::to_string(i) + " has volume <= 0");
    for (int k = 0; k < D; ++k) X0_[k][i] = x_[k][i] = geometry.X0[i](k);
    V0_[i] = geometry.V0[i];
    for (std::size_t k = 0; k < options_.clamps.size(); ++k)
      if (options_.clamps[k].contains(geometry.X0[i])) {
        clamped_[i] = static_cast<std::uint8_t>(k + 1);
        break;
      }
  }
  build_reference();
  if constexpr (D == 2)
    build_outline_interface(geometry);
  else
    build_box_interface(geometry);
  build_images();
  if (quadratic_ && options_.hourglass > 0.0) { // k_ab = hourglass E V_a w_ab; not on images
    const std::size_t pairs = pair_b_.size();
    pair_k_.assign(pairs, 0.0);
    for (auto& r : pair_r_) r.assign(pairs, 0.0);
    const double k = options_.hourglass * options_.material.youngs_modulus;
    for (std::size_t a = 0; a < n; ++a)
      if (!imaged(a))
        for (std::uint32_t q = pair_start_[a]; q < pair_start_[a + 1]; ++q)
          pair_k_[q] = k * V0_[a] * pair_dwr_[q];
  }
  prescribe(0.0);
  compute_stress();
  compute_acceleration();
}

template <int D> BasicTlsphSolid<D>::~BasicTlsphSolid() = default;

template <int D> std::size_t BasicTlsphSolid<D>::nearest_particle(const Vec& X) const {
  std::size_t best = 0;
  double d2 = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < size(); ++i) {
    const double d = (at(X0_, i) - X).squaredNorm();
    if (d < d2) d2 = d, best = i;
  }
  return best;
}

template <int D> TlsphState BasicTlsphSolid<D>::save() const {
  TlsphState s;
  fields_.save(s.fields);
  s.time = time_, s.step = step_, s.external_work = external_work_;
  return s;
}

template <int D> void BasicTlsphSolid<D>::restore(const TlsphState& s) {
  fields_.restore(s.fields);
  time_ = s.time, step_ = s.step, external_work_ = s.external_work;
  update_loaded();
  compute_stress(); // F and P B0 are scratch: a later set_interface_loads() needs them current
}

template <int D>
void BasicTlsphSolid<D>::write_state(StateArchive& archive, const std::string& prefix) const {
  fields_.write_state(archive, prefix + "particles/");
  archive.put_real(prefix + "time", time_);
  archive.put_integer(prefix + "step", step_);
  archive.put_real(prefix + "external_work", external_work_);
}

template <int D>
void BasicTlsphSolid<D>::read_state(const StateArchive& archive, const std::string& prefix) {
  // Checked before reading: FieldSet::read_state resizes every array, the reference ones too.
  archive.reals(prefix + "particles/x", size());
  fields_.read_state(archive, prefix + "particles/");
  time_ = archive.real(prefix + "time");
  step_ = static_cast<long>(archive.integer(prefix + "step"));
  external_work_ = archive.real(prefix + "external_work");
  update_loaded();
  compute_stress();
}

template void validate<2>(const BasicTlsphOptions<2>&);
template void validate<3>(const BasicTlsphOptions<3>&);
template class BasicTlsphSolid<2>;
template class BasicTlsphSolid<3>;

} // namespace fsi::tlsph
