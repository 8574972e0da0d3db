// The TL-SPH solid's set-up (options checked, particles, reference data, first stress and
// acceleration), its reference-point lookup, and its state (save, restore, checkpoint).
#include "solid_tlsph/solid.hpp"

#include <cmath>
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

} // namespace

void validate(const TlsphOptions& o) {
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

TlsphSolid::TlsphSolid(SolidGeometry geometry, TlsphOptions options)
    : options_(std::move(options)), x_(fields_.add_real("x")), y_(fields_.add_real("y")),
      vx_(fields_.add_real("vx")), vy_(fields_.add_real("vy")), ax_(fields_.add_real("ax")),
      ay_(fields_.add_real("ay")), fx_(fields_.add_real("fx")), fy_(fields_.add_real("fy")),
      X0_(fields_.add_real("X0", false)), Y0_(fields_.add_real("Y0", false)),
      V0_(fields_.add_real("V0", false)), B00_(fields_.add_real("B00", false)),
      B01_(fields_.add_real("B01", false)), B10_(fields_.add_real("B10", false)),
      B11_(fields_.add_real("B11", false)), clamped_(fields_.add_flag("clamp", false)),
      surface_(fields_.add_flag("surface", false)), F00_(fields_.add_real("F00", false)),
      F01_(fields_.add_real("F01", false)), F10_(fields_.add_real("F10", false)),
      F11_(fields_.add_real("F11", false)), PB00_(fields_.add_real("PB00", false)),
      PB01_(fields_.add_real("PB01", false)), PB10_(fields_.add_real("PB10", false)),
      PB11_(fields_.add_real("PB11", false)) {
  validate(options_);
  const std::size_t n = geometry.X0.size();
  if (n == 0) throw InputError("tlsph: the geometry holds no particles");
  if (geometry.V0.size() != n)
    throw InputError("tlsph: " + std::to_string(geometry.V0.size()) + " volumes for " +
                     std::to_string(n) + " particles");
  if (geometry.outline_tags.size() != geometry.outline.size())
    throw InputError("tlsph: outline has " + std::to_string(geometry.outline.size()) +
                     " edges but " + std::to_string(geometry.outline_tags.size()) + " tags");
  material_ = materials::make_material(options_.material);
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
    X0_[i] = x_[i] = geometry.X0[i].x();
    Y0_[i] = y_[i] = geometry.X0[i].y();
    V0_[i] = geometry.V0[i];
    for (std::size_t k = 0; k < options_.clamps.size(); ++k)
      if (options_.clamps[k].contains(geometry.X0[i])) {
        clamped_[i] = static_cast<std::uint8_t>(k + 1);
        break;
      }
  }
  build_reference();
  build_interface(geometry);
  build_images();
  if (quadratic_ && options_.hourglass > 0.0) { // k_ab = hourglass E V_a w_ab; not on images
    const std::size_t pairs = pair_b_.size();
    pair_k_.assign(pairs, 0.0), pair_rx_.assign(pairs, 0.0), pair_ry_.assign(pairs, 0.0);
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

TlsphSolid::~TlsphSolid() = default;

std::size_t TlsphSolid::nearest_particle(const Vec2& X) const {
  std::size_t best = 0;
  double d2 = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < size(); ++i) {
    const double d = (Vec2(X0_[i], Y0_[i]) - X).squaredNorm();
    if (d < d2) d2 = d, best = i;
  }
  return best;
}

TlsphState TlsphSolid::save() const {
  TlsphState s;
  fields_.save(s.fields);
  s.time = time_, s.step = step_, s.external_work = external_work_;
  return s;
}

void TlsphSolid::restore(const TlsphState& s) {
  fields_.restore(s.fields);
  time_ = s.time, step_ = s.step, external_work_ = s.external_work;
  update_loaded();
  compute_stress(); // F and P B0 are scratch: a later set_interface_loads() needs them current
}

void TlsphSolid::write_state(StateArchive& archive, const std::string& prefix) const {
  fields_.write_state(archive, prefix + "particles/");
  archive.put_real(prefix + "time", time_);
  archive.put_integer(prefix + "step", step_);
  archive.put_real(prefix + "external_work", external_work_);
}

void TlsphSolid::read_state(const StateArchive& archive, const std::string& prefix) {
  // Checked before reading: FieldSet::read_state resizes every array, the reference ones too.
  archive.reals(prefix + "particles/x", size());
  fields_.read_state(archive, prefix + "particles/");
  time_ = archive.real(prefix + "time");
  step_ = static_cast<long>(archive.integer(prefix + "step"));
  external_work_ = archive.real(prefix + "external_work");
  update_loaded();
  compute_stress();
}

} // namespace fsi::tlsph
