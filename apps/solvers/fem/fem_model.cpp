#include "fem/fem_model.hpp"

#include "fem/fe_adapter.hpp"
#include "fsi/core/error.hpp"
#include "fsi_app/wall_motion.hpp"
#include "structure_fem/gmsh_reader.hpp"
#include "structure_fem/loads.hpp"
#include "structure_fem/rectangle_mesher.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>

namespace fsi::app::fem_plugin {

namespace {

fem::Mesh build_mesh(const Scene& scene, const StructureBlock& block) {
  const StructureSpec& spec = block.as<StructureSpec>();
  if (spec.mesh.kind == "rectangle") {
    fem::RectangleMeshOptions r;
    r.origin = spec.mesh.origin;
    r.width = spec.mesh.width;
    r.height = spec.mesh.height;
    r.elements_x = spec.mesh.elements_x;
    r.elements_y = spec.mesh.elements_y;
    r.diagonals =
        spec.mesh.diagonals == "mirrored" ? fem::Diagonals::mirrored : fem::Diagonals::rising;
    try {
      return fem::make_rectangle_mesh(r);
    } catch (const InputError& e) {
      fail_at(scene, block.line, block.key + ".mesh", e.what());
    }
  }
  std::vector<std::string> groups = spec.clamped;
  groups.insert(groups.end(), spec.interface.begin(), spec.interface.end());
  for (const auto& l : spec.loads) groups.push_back(l.boundary);
  try {
    return fem::read_gmsh(spec.mesh.file.string(), groups);
  } catch (const InputError& e) {
    fail_at(scene, block.line, block.key + ".mesh", e.what());
  }
}

double edge_length(const fem::Mesh& mesh, const std::string& tag) {
  double length = 0.0;
  for (const auto& e : mesh.edges_with_tag(tag))
    length += (mesh.X[static_cast<std::size_t>(e.nodes[2])] -
               mesh.X[static_cast<std::size_t>(e.nodes[0])])
                  .norm();
  return length;
}

} // namespace

namespace {
// The node a probe names, by index or at its reference point (probe.point, in 3-D point3).
template <class MeshT>
int probe_node_of(const Scene& scene, const MeshT& mesh, const ProbeSpec& probe) {
  const int count = static_cast<int>(mesh.num_nodes());
  if (probe.node) {
    if (*probe.node >= count)
      fail_at(scene, probe.line, probe.key + ".node",
              "node " + std::to_string(*probe.node) + " does not exist (the mesh has " +
                  std::to_string(count) + " nodes)");
    return *probe.node;
  }
  using Point = std::decay_t<decltype(mesh.X.front())>;
  const Point point = [&] {
    if constexpr (Point::RowsAtCompileTime == 3)
      return *probe.point3;
    else
      return *probe.point;
  }();
  Point lo = mesh.X.front(), hi = mesh.X.front();
  for (const auto& x : mesh.X) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const double tolerance = 1e-6 * (hi - lo).norm();
  int best = 0;
  for (int k = 1; k < count; ++k)
    if ((mesh.X[static_cast<std::size_t>(k)] - point).norm() <
        (mesh.X[static_cast<std::size_t>(best)] - point).norm())
      best = k;
  if ((mesh.X[static_cast<std::size_t>(best)] - point).norm() > tolerance) {
    std::ostringstream msg;
    msg << "no node of structure '" << probe.structure << "' at (";
    for (int i = 0; i < point.size(); ++i) msg << (i ? ", " : "") << point[i];
    msg << ")";
    fail_at(scene, probe.line, probe.key + ".point", msg.str());
  }
  return best;
}
} // namespace

int probe_node(const Scene& scene, const fem::Mesh& mesh, const ProbeSpec& probe) {
  return probe_node_of(scene, mesh, probe);
}

int probe_node(const Scene& scene, const fem::TetMesh& mesh, const ProbeSpec& probe) {
  return probe_node_of(scene, mesh, probe);
}

namespace {
std::optional<WallFrame> tank_frame(const Scene& scene, const StructureBlock& block) {
  return wall_frame(scene, block.as<StructureSpec>().clamped_motion, block.line,
                    block.key + ".clamped_motion");
}
} // namespace

fem::Mesh checked_mesh(const Scene& scene, const StructureBlock& block) {
  fem::Mesh mesh = build_mesh(scene, block);
  check_tags_and_probes(scene, block, mesh, [&](const std::string& t) { return mesh.has_tag(t); });
  return mesh;
}

std::vector<Polygon> occupied_triangles(const fem::Mesh& mesh) {
  std::vector<Polygon> triangles;
  for (const auto& e : mesh.elements)
    triangles.push_back({mesh.X[static_cast<std::size_t>(e[0])],
                         mesh.X[static_cast<std::size_t>(e[1])],
                         mesh.X[static_cast<std::size_t>(e[2])]});
  return triangles;
}

std::unique_ptr<fem::Structure> build_structure(const Scene& scene, const StructureBlock& block) {
  const StructureSpec& spec = block.as<StructureSpec>();
  fem::Mesh mesh = checked_mesh(scene, block);
  const std::string& key = block.key;
  fem::StructureOptions o = spec.options;
  o.gravity = scene.gravity;
  fem::PrescribedMotion clamped_motion; // empty: fixed
  if (const auto frame = tank_frame(scene, block)) {
    clamped_motion = [frame](const Vec2& X, double t) { // the tank's rigid motion at X
      const erp::NodeState n = erp::rigid_node_state(frame->motion->at(t), frame->pivot, X);
      return fem::PrescribedKinematics{n.x - X, n.v, n.a};
    };
  }
  for (const auto& tag : spec.clamped) o.clamped.push_back({tag, true, true, {}, clamped_motion});
  fem::Vector loads = fem::Vector::Zero(2 * static_cast<Eigen::Index>(mesh.num_nodes()));
  for (const auto& l : spec.loads)
    loads += fem::edge_traction_forces(mesh, l.boundary, l.force / edge_length(mesh, l.boundary));
  auto structure = std::make_unique<fem::Structure>(std::move(mesh), o);
  if (!spec.loads.empty()) {
    structure->set_external_forces(loads);
    structure->update_acceleration();
  }
  if (clamped_motion) { // start at rest, in equilibrium with the clamped nodes where the wall is
    try {
      structure->solve_static({.load_steps = 1, .time = 0.0});
      structure->update_acceleration();
    } catch (const RunError& e) {
      fail_at(scene, block.line, key + ".clamped_motion", e.what());
    }
  }
  return structure;
}

FemModel::FemModel(const Scene& scene, const StructureBlock& block)
    : BasicFemPart(block.name, build_structure(scene, block)),
      interface_(fem::interface_of(structure_->mesh(), block.as<StructureSpec>().interface)),
      frame_(tank_frame(scene, block)),
      adapter_(std::make_unique<PartAdapter<fem::T6>>(*this, interface_)) {
  for (const auto& p : scene.output.probes)
    if (p.structure == block.name)
      probe_nodes_.emplace_back(p.name, probe_node(scene, structure_->mesh(), p));
}

FemModel::~FemModel() = default;

coupling::StructureSolver& FemModel::coupling_solver() {
  return *adapter_;
}

std::vector<Polygon> FemModel::occupied_area() const {
  return occupied_triangles(structure_->mesh());
}

std::vector<std::string> FemModel::take_notes() {
  if (lu_noted_ || counters_.lu_fallbacks == 0) return {};
  lu_noted_ = true;
  std::ostringstream s;
  s << "structure '" << name() << "': the stiffness matrix is not positive definite at structure "
    << "step " << structure_->step() << ", t = " << structure_->time()
    << " s; LDLT gave way to UMFPACK LU there (linear_solver: auto; counted in run.json as "
    << "structure_" << name() << ".linear_solver_lu_fallbacks)";
  return {s.str()};
}

void FemModel::declare(FieldsFile& file) const {
  std::vector<std::int64_t> t6;
  for (const auto& e : structure_->mesh().elements) t6.insert(t6.end(), e.begin(), e.end());
  file.add_mesh(name(), t6);
}

void FemModel::write_frame(FieldsFile& file, const std::vector<std::string>& fields) const {
  const auto x = structure_->positions();
  std::vector<double> xy;
  xy.reserve(2 * x.size());
  for (const auto& p : x) xy.push_back(p.x()), xy.push_back(p.y());
  const fem::Vector von_mises = structure_->von_mises();
  file.write_grid(name(), xy,
                  select_fields(fields, {{"displacement", 2, structure_->displacement().data()},
                                         {"velocity", 2, structure_->velocity().data()},
                                         {"von_mises", 1, von_mises.data()}}));
}

std::optional<double> FemModel::probe(const ProbeSpec& probe) const {
  for (const auto& [name, node] : probe_nodes_) {
    if (name != probe.name) continue;
    const int c = probe.quantity.starts_with("displacement_y") ? 1 : 0;
    if (!probe.quantity.ends_with("_tank")) return structure_->displacement()[2 * node + c];
    const auto i = static_cast<std::size_t>(node);
    return frame_->displacement(structure_->mesh().X[i], structure_->positions()[i],
                                structure_->time())[c];
  }
  return std::nullopt;
}

} // namespace fsi::app::fem_plugin
