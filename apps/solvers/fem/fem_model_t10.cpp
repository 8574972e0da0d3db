#include "fem/fem_model_t10.hpp"

#include "fem/fem_model.hpp"
#include "fsi/core/error.hpp"
#include "fsi_app/wall_motion.hpp"
#include "structure_fem/box_mesher.hpp"
#include "structure_fem/gmsh_reader.hpp"
#include "structure_fem/loads.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>

namespace fsi::app::fem_plugin {

const std::vector<std::string>& box_sides() {
  static const std::vector<std::string> sides{"left", "right", "bottom", "top", "back", "front"};
  return sides;
}

namespace {

fem::TetMesh build_tet_mesh(const Scene& scene, const StructureBlock& block) {
  const StructureSpec& spec = block.as<StructureSpec>();
  try {
    if (spec.mesh.kind == "box") {
      fem::BoxMeshOptions b;
      b.origin = spec.mesh.origin3;
      b.size = Vec3(spec.mesh.width, spec.mesh.height, spec.mesh.depth);
      b.cells = {spec.mesh.elements_x, spec.mesh.elements_y, spec.mesh.elements_z};
      fem::TetMesh mesh = fem::make_box_mesh(b);
      const std::vector<std::string> axis_sides{"x_min", "x_max", "y_min",
                                                "y_max", "z_min", "z_max"};
      for (auto& f : mesh.faces) // side d of the mesher is box_sides()[d]
        f.tag = box_sides()[static_cast<std::size_t>(
            std::find(axis_sides.begin(), axis_sides.end(), f.tag) - axis_sides.begin())];
      return mesh;
    }
    std::vector<std::string> groups = spec.clamped;
    groups.insert(groups.end(), spec.sliding.begin(), spec.sliding.end());
    groups.insert(groups.end(), spec.interface.begin(), spec.interface.end());
    for (const auto& l : spec.loads) groups.push_back(l.boundary);
    return fem::read_gmsh_t10(spec.mesh.file.string(), groups);
  } catch (const InputError& e) {
    fail_at(scene, block.line, block.key + ".mesh", e.what());
  }
}

// Reference area of the tagged faces: the x-forces of a unit x-traction sum to it (each face's
// shape functions sum to 1).
double face_area(const fem::TetMesh& mesh, const std::string& tag) {
  const fem::Vector f =
      fem::face_traction_forces(mesh, tag, [](const Vec3&) { return Vec3(1.0, 0.0, 0.0); });
  return Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic>>(f.data(), 3, f.size() / 3)
      .row(0)
      .sum();
}

// The axis a sliding face's nodes share one coordinate of (to 1e-9 of the mesh's size); the
// face slides in that plane, its displacement along the axis held.
int plane_axis(const Scene& scene, const StructureBlock& block, const fem::TetMesh& mesh,
               const std::string& tag) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec3& x : mesh.X) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const double tolerance = 1e-9 * (hi - lo).norm();
  lo.setConstant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const int k : mesh.node_set(tag))
    lo = lo.cwiseMin(mesh.X[static_cast<std::size_t>(k)]),
    hi = hi.cwiseMax(mesh.X[static_cast<std::size_t>(k)]);
  const Vec3 spread = hi - lo;
  int axis = -1;
  for (int c = 0; c < 3; ++c)
    if (spread[c] <= tolerance) axis = axis < 0 ? c : 3;
  if (axis < 0 || axis == 3)
    fail_at(scene, block.line, block.key + ".sliding",
            "face '" + tag + "' does not lie in one plane x, y or z = const (a sliding face " +
                "holds the displacement along that axis)");
  return axis;
}

// The clamped faces' rigid motion (clamped_rigid_motion; erp::RigidMotion3, exact v and a).
fem::PrescribedMotion3 clamp_motion(const MotionSpec& m) {
  return [motion = make_motion3(m)](const Vec3& X, double t) {
    const erp::NodeState3 n = motion.at(t, X);
    return fem::PrescribedKinematics3{n.x - X, n.v, n.a};
  };
}

std::unique_ptr<fem::StructureT10> build_structure_t10(const Scene& scene,
                                                       const StructureBlock& block) {
  const StructureSpec& spec = block.as<StructureSpec>();
  fem::TetMesh mesh = checked_tet_mesh(scene, block);
  fem::StructureT10Options o;
  o.material = spec.options.material;
  o.newmark = spec.options.newmark;
  o.newton = spec.options.newton;
  o.linear_solver = spec.options.linear_solver;
  o.gravity = scene.gravity3;
  const fem::PrescribedMotion3 motion =
      spec.clamped_rigid_motion ? clamp_motion(*spec.clamped_rigid_motion) : nullptr; // null: fixed
  for (const auto& tag : spec.clamped) o.clamped.push_back({tag, {true, true, true}, {}, motion});
  for (const auto& tag : spec.sliding) {
    std::array<bool, 3> fix{false, false, false};
    fix[static_cast<std::size_t>(plane_axis(scene, block, mesh, tag))] = true;
    o.clamped.push_back({tag, fix, {}, {}});
  }
  fem::Vector loads = fem::Vector::Zero(3 * static_cast<Eigen::Index>(mesh.num_nodes()));
  for (const auto& l : spec.loads) {
    const Vec3 t = l.force3 / face_area(mesh, l.boundary);
    loads += fem::face_traction_forces(mesh, l.boundary, [t](const Vec3&) { return t; });
    const double p = l.pressure;
    loads += fem::face_pressure_forces(mesh, l.boundary, [p](const Vec3&) { return p; });
  }
  std::unique_ptr<fem::StructureT10> structure;
  try {
    structure = std::make_unique<fem::StructureT10>(std::move(mesh), o);
  } catch (const InputError& e) {
    fail_at(scene, block.line, block.key, e.what());
  }
  if (!spec.loads.empty()) {
    structure->set_external_forces(loads);
    structure->update_acceleration();
  }
  if (motion) { // start at rest, in equilibrium with the clamp where it is at t = 0
    try {
      structure->solve_static({.load_steps = 1, .time = 0.0});
      structure->update_acceleration();
    } catch (const RunError& e) {
      fail_at(scene, block.line, block.key + ".clamped_rigid_motion", e.what());
    }
  }
  return structure;
}

} // namespace

fem::TetMesh checked_tet_mesh(const Scene& scene, const StructureBlock& block) {
  fem::TetMesh mesh = build_tet_mesh(scene, block);
  check_tags_and_probes(scene, block, mesh, [&](const std::string& tag) {
    return std::any_of(mesh.faces.begin(), mesh.faces.end(),
                       [&](const fem::BoundaryFace& f) { return f.tag == tag; });
  });
  return mesh;
}

FemModelT10::FemModelT10(const Scene& scene, const StructureBlock& block)
    : BasicFemPart(block.name, build_structure_t10(scene, block)),
      interface_(fem::interface_of(structure_->mesh(), block.as<StructureSpec>().interface)) {
  for (const auto& p : scene.output.probes)
    if (p.structure == block.name)
      probe_nodes_.emplace_back(p.name, probe_node(scene, structure_->mesh(), p));
}

coupling::StructureSolver& FemModelT10::coupling_solver() {
  throw std::logic_error("a 3-D FE structure couples through coupling_solver3(), not the 2-D S");
}

void FemModelT10::declare(FieldsFile& file) const {
  std::vector<std::int64_t> t10;
  for (const auto& e : structure_->mesh().elements) t10.insert(t10.end(), e.begin(), e.end());
  file.add_mesh_t10(name(), t10);
}

void FemModelT10::write_frame(FieldsFile& file, const std::vector<std::string>& fields) const {
  std::vector<double> xyz;
  for (const auto& p : structure_->positions()) xyz.insert(xyz.end(), p.data(), p.data() + 3);
  const fem::Vector von_mises = structure_->von_mises();
  file.write_grid(name(), xyz,
                  select_fields(fields, {{"displacement", 3, structure_->displacement().data()},
                                         {"velocity", 3, structure_->velocity().data()},
                                         {"von_mises", 1, von_mises.data()}}),
                  3);
}

std::optional<double> FemModelT10::probe(const ProbeSpec& probe) const {
  for (const auto& [name, node] : probe_nodes_)
    if (name == probe.name) // displacement_x, _y or _z
      return structure_->displacement()[3 * node + (probe.quantity.back() - 'x')];
  return std::nullopt;
}

} // namespace fsi::app::fem_plugin
