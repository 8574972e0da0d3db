#include "tlsph/tlsph_model.hpp"

#include "fsi/core/error.hpp"
#include "fsi/core/state_archive.hpp"
#include "fsi_app/finite_guard.hpp"
#include "fsi_app/wall_motion.hpp"
#include "geometry_erp/motion.hpp"

#include <algorithm>

namespace fsi::app::tlsph_plugin {

namespace {

bool inside(const Box& b, const Vec2& X) {
  return X.x() >= b.min.x() && X.x() <= b.max.x() && X.y() >= b.min.y() && X.y() <= b.max.y();
}

std::optional<WallFrame> tank_frame(const Scene& scene, const StructureBlock& block) {
  return wall_frame(scene, block.as<TlsphSpec>().clamped_motion, block.line,
                    block.key + ".clamped_motion");
}

// The lattice starts at the lower-left corner of the region's box (a rectangle's min).
Vec2 lattice_origin(const std::vector<Vec2>& outline) {
  Vec2 lo = outline.front();
  for (const Vec2& p : outline) lo = lo.cwiseMin(p);
  return lo;
}

std::unique_ptr<tlsph::TlsphSolid> build_solid(const Scene& scene, const StructureBlock& block) {
  const TlsphSpec& t = block.as<TlsphSpec>();
  tlsph::TlsphOptions o = t.options;
  o.gravity = scene.gravity;
  // The library's defaults (quadratic correction, hourglass control, each clamp at its face
  // with the free particles: docs/solid_tlsph.md, "Coupled").
  const std::optional<WallFrame> frame = tank_frame(scene, block);
  for (const Box& box : t.clamped) {
    tlsph::Clamp c;
    c.contains = [box](const Vec2& X) { return inside(box, X); };
    if (frame) { // the wall's rigid motion at X0
      c.position = [frame](const Vec2& X, double time) {
        return erp::rigid_node_state(frame->motion->at(time), frame->pivot, X).x;
      };
      c.velocity = [frame](const Vec2& X, double time) {
        return erp::rigid_node_state(frame->motion->at(time), frame->pivot, X).v;
      };
    }
    o.clamps.push_back(std::move(c));
  }
  try {
    return std::make_unique<tlsph::TlsphSolid>(
        tlsph::fill_polygon(t.outline, t.tags, o.dp, lattice_origin(t.outline)), std::move(o));
  } catch (const InputError& e) {
    fail_at(scene, block.line, block.key, e.what());
  }
}

} // namespace

TlsphModel::TlsphModel(const Scene& scene, const StructureBlock& block)
    : StructurePart(block.name), outline_(block.as<TlsphSpec>().outline),
      solid_(build_solid(scene, block)), interface_(solid_->interface_mesh()),
      frame_(tank_frame(scene, block)) {
  for (const auto& p : scene.output.probes) {
    if (p.structure != block.name) continue;
    const auto nearest = static_cast<std::uint32_t>(solid_->nearest_particle(*p.point));
    try { // the kernel interpolation at the point, or its nearest particle with weight 1
      if (p.interpolate)
        probes_.push_back({p.name, solid_->interpolation_stencil(*p.point), *p.point});
      else
        probes_.push_back({p.name, {{nearest}, {1.0}}, solid_->reference_position(nearest)});
    } catch (const InputError& e) {
      fail_at(scene, p.line, p.key + ".point", e.what());
    }
  }
}

std::vector<Polygon> TlsphModel::occupied_area() const {
  return {outline_};
}

void TlsphModel::advance(double time, double dt) {
  try { // the run names the structure (issue 41)
    substeps_ += solid_->advance(time, dt);
  } catch (const RunError& e) {
    throw RunError("structure '" + name() + "': " + e.what());
  }
  ++steps_;
}

std::optional<std::string> TlsphModel::non_finite() const {
  for (std::size_t i = 0; i < solid_->size(); ++i)
    if (auto what = non_finite_point("structure '" + name() + "' particle " + std::to_string(i),
                                     solid_->position(i), solid_->velocity(i)))
      return what;
  return std::nullopt;
}

void TlsphModel::write_frame(FieldsFile& file, const std::vector<std::string>& fields) const {
  const std::size_t n = solid_->size();
  xy_.resize(2 * n), u_.resize(2 * n), v_.resize(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 x = solid_->position(i), u = solid_->displacement(i), v = solid_->velocity(i);
    xy_[2 * i] = x.x(), xy_[2 * i + 1] = x.y();
    u_[2 * i] = u.x(), u_[2 * i + 1] = u.y();
    v_[2 * i] = v.x(), v_[2 * i + 1] = v.y();
  }
  const std::vector<double> von_mises = solid_->von_mises(), det_F = solid_->det_F();
  file.write_grid(name(), xy_,
                  select_fields(fields, {{"displacement", 2, u_.data()},
                                         {"velocity", 2, v_.data()},
                                         {"von_mises", 1, von_mises.data()},
                                         {"det_F", 1, det_F.data()}}));
}

std::optional<double> TlsphModel::probe(const ProbeSpec& probe) const {
  for (const auto& [name, stencil, X] : probes_) {
    if (name != probe.name) continue;
    const int c = probe.quantity.starts_with("displacement_y") ? 1 : 0;
    const Vec2 u = solid_->displacement_at(stencil);
    return probe.quantity.ends_with("_tank") ? frame_->displacement(X, X + u, solid_->time())[c]
                                             : u[c];
  }
  return std::nullopt;
}

void TlsphModel::report(JsonObject& run) const {
  JsonObject s;
  s.add("particles", static_cast<long long>(solid_->size()))
      .add("interface_nodes", static_cast<long long>(interface_.node_count()))
      .add("substeps_mean",
           steps_ ? static_cast<double>(substeps_) / static_cast<double>(steps_) : 0.0);
  run.add("structure_" + name(), s);
}

void TlsphModel::write_state(StateArchive& archive) const {
  const std::string prefix = "structures/" + name() + "/";
  solid_->write_state(archive, prefix);
  archive.put("run/" + prefix + "substeps", std::vector<std::int64_t>{steps_, substeps_});
}

void TlsphModel::read_state(const StateArchive& archive) {
  const std::string prefix = "structures/" + name() + "/";
  solid_->read_state(archive, prefix);
  const auto& c = archive.integers("run/" + prefix + "substeps", 2);
  steps_ = c[0], substeps_ = c[1];
}

} // namespace fsi::app::tlsph_plugin
