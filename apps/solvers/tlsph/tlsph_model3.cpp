#include "tlsph/tlsph_model3.hpp"

#include "fem/fem_model_t10.hpp"
#include "fsi/core/error.hpp"
#include "fsi/core/state_archive.hpp"
#include "fsi_app/finite_guard.hpp"

#include <algorithm>
#include <stdexcept>

namespace fsi::app::tlsph_plugin {

namespace {

// A box face by the scene's name (fem_plugin::box_sides(): left, right, bottom, top, back, front)
// as the library's tag (x-, x+, y-, y+, z-, z+; interface_box.cpp).
std::string face_tag(const std::string& side) {
  const auto& sides = fem_plugin::box_sides();
  const auto k = std::find(sides.begin(), sides.end(), side) - sides.begin();
  return {static_cast<char>('x' + k / 2), k % 2 ? '+' : '-'};
}

// The scene's keys (read into the 2-D options, tlsph_scene.cpp) as the 3-D solid's options,
// gravity, fixed clamped boxes (odd images across each box's face, found from the lattice) and
// the wetted faces (none named: every face, as the 2-D outline's edges).
tlsph::TlsphOptions3 options3(const Scene& scene, const TlsphSpec& t) {
  const tlsph::TlsphOptions& o2 = t.options;
  tlsph::TlsphOptions3 o;
  o.material = o2.material;
  o.dp = o2.dp, o.h_factor = o2.h_factor, o.cfl = o2.cfl;
  o.kernel_correction = o2.kernel_correction, o.gradient_correction = o2.gradient_correction;
  o.pair_damping = o2.pair_damping, o.mass_damping = o2.mass_damping;
  o.hourglass = o2.hourglass;
  o.gravity = scene.gravity3;
  for (const auto& side : o2.interface_tags) o.interface_tags.push_back(face_tag(side));
  for (const Box3& box : t.clamped3) {
    tlsph::Clamp3 c;
    c.contains = [box](const Vec3& X) {
      return (X.array() >= box.min.array()).all() && (X.array() <= box.max.array()).all();
    };
    o.clamps.push_back(std::move(c));
  }
  return o;
}

std::unique_ptr<tlsph::TlsphSolid3> build_solid3(const Scene& scene, const StructureBlock& block) {
  const TlsphSpec& t = block.as<TlsphSpec>();
  try {
    return std::make_unique<tlsph::TlsphSolid3>(tlsph::fill_box(t.box.min, t.box.max, t.options.dp),
                                                options3(scene, t));
  } catch (const InputError& e) {
    fail_at(scene, block.line, block.key, e.what());
  }
}

} // namespace

TlsphModel3::TlsphModel3(const Scene& scene, const StructureBlock& block)
    : StructurePart(block.name), solid_(build_solid3(scene, block)),
      interface3_(solid_->interface_mesh()) {
  for (const auto& p : scene.output.probes) {
    if (p.structure != block.name) continue;
    const Vec3 X = *p.point3;
    try { // the kernel interpolation at the point, or its nearest particle with weight 1
      probes_.emplace_back(
          p.name, p.interpolate
                      ? solid_->interpolation_stencil(X)
                      : tlsph::ProbeStencil{
                            {static_cast<std::uint32_t>(solid_->nearest_particle(X))}, {1.0}});
    } catch (const InputError& e) {
      fail_at(scene, p.line, p.key + ".point", e.what());
    }
  }
}

coupling::StructureSolver& TlsphModel3::coupling_solver() {
  throw std::logic_error("a 3-D TL-SPH solid's S is coupling_solver3()");
}

void TlsphModel3::advance(double time, double dt) {
  try { // the run names the structure (issue 41)
    substeps_ += solid_->advance(time, dt);
  } catch (const RunError& e) {
    throw RunError("structure '" + name() + "': " + e.what());
  }
  ++steps_;
}

std::optional<std::string> TlsphModel3::non_finite() const {
  for (std::size_t i = 0; i < solid_->size(); ++i)
    if (auto what = non_finite_point3("structure '" + name() + "' particle " + std::to_string(i),
                                      solid_->position(i), solid_->velocity(i)))
      return what;
  return std::nullopt;
}

void TlsphModel3::write_frame(FieldsFile& file, const std::vector<std::string>& fields) const {
  const std::size_t n = solid_->size();
  xyz_.resize(3 * n), u_.resize(3 * n), v_.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Map<Vec3>(xyz_.data() + 3 * i) = solid_->position(i);
    Eigen::Map<Vec3>(u_.data() + 3 * i) = solid_->displacement(i);
    Eigen::Map<Vec3>(v_.data() + 3 * i) = solid_->velocity(i);
  }
  const std::vector<double> von_mises = solid_->von_mises(), det_F = solid_->det_F();
  file.write_grid(name(), xyz_,
                  select_fields(fields, {{"displacement", 3, u_.data()},
                                         {"velocity", 3, v_.data()},
                                         {"von_mises", 1, von_mises.data()},
                                         {"det_F", 1, det_F.data()}}),
                  3);
}

std::optional<double> TlsphModel3::probe(const ProbeSpec& probe) const {
  for (const auto& [name, stencil] : probes_)
    if (name == probe.name) // displacement_x, _y or _z
      return solid_->displacement_at(stencil)[probe.quantity.back() - 'x'];
  return std::nullopt;
}

void TlsphModel3::report(JsonObject& run) const {
  JsonObject s;
  s.add("particles", static_cast<long long>(solid_->size()))
      .add("interface_nodes", static_cast<long long>(interface3_.node_count()))
      .add("substeps_mean",
           steps_ ? static_cast<double>(substeps_) / static_cast<double>(steps_) : 0.0);
  run.add("structure_" + name(), s);
}

void TlsphModel3::write_state(StateArchive& archive) const {
  const std::string prefix = "structures/" + name() + "/";
  solid_->write_state(archive, prefix);
  archive.put("run/" + prefix + "substeps", std::vector<std::int64_t>{steps_, substeps_});
}

void TlsphModel3::read_state(const StateArchive& archive) {
  const std::string prefix = "structures/" + name() + "/";
  solid_->read_state(archive, prefix);
  const auto& c = archive.integers("run/" + prefix + "substeps", 2);
  steps_ = c[0], substeps_ = c[1];
}

} // namespace fsi::app::tlsph_plugin
