#pragma once
// The FE structure of one scene entry (structures[].type: fem): the T6 solid under gravity, the
// scene's constant loads and, coupled, the interface loads; also the coupler's S through the
// interface its tagged boundary describes.
#include "coupling/interface.hpp"
#include "fem/fe_adapter.hpp"
#include "fem/fem_part.hpp"
#include "fem/fem_spec.hpp"
#include "fsi_app/solver_plugin.hpp"
#include "fsi_app/wall_motion.hpp"
#include "structure_fem/interface_mesh.hpp"
#include "structure_fem/structure.hpp"

#include <memory>
#include <optional>

namespace fsi::app::fem_plugin {

/// The entry's mesh, read or generated, with its boundary tags and probe nodes checked. Throws
/// InputError (scene file and line) for tags or meshes that do not fit.
fem::Mesh checked_mesh(const Scene& scene, const StructureBlock& block);

/// The mesh's elements as the triangles of their corner nodes (the area kept free of fluid).
std::vector<Polygon> occupied_triangles(const fem::Mesh& mesh);

/// The FEM structure of one scene entry: mesh built, options mapped. Throws InputError (scene
/// file and line) for tags or meshes that do not fit.
std::unique_ptr<fem::Structure> build_structure(const Scene& scene, const StructureBlock& block);

/// The FE node a displacement probe names (by index, or by reference position).
int probe_node(const Scene& scene, const fem::Mesh& mesh, const ProbeSpec& probe);
/// The same on a T10 mesh (the probe's point3).
int probe_node(const Scene& scene, const fem::TetMesh& mesh, const ProbeSpec& probe);

/// Fails (scene file and line) for a clamped, interface or load tag that has_tag(tag) denies,
/// and for a probe of the entry that names no node of `mesh`.
template <class MeshT, class HasTag>
void check_tags_and_probes(const Scene& scene, const StructureBlock& block, const MeshT& mesh,
                           HasTag has_tag) {
  const StructureSpec& spec = block.as<StructureSpec>();
  auto check = [&](const std::string& tag, const char* key) {
    if (!has_tag(tag)) fail_at(scene, block.line, block.key + key, "no boundary '" + tag + "'");
  };
  for (const auto& tag : spec.clamped) check(tag, ".clamped");
  for (const auto& tag : spec.interface) check(tag, ".interface");
  for (const auto& l : spec.loads) check(l.boundary, ".loads");
  for (const auto& p : scene.output.probes)
    if (p.structure == block.name) probe_node(scene, mesh, p);
}

class FemModel final : public BasicFemPart<fem::T6> {
public:
  FemModel(const Scene& scene, const StructureBlock& block);
  ~FemModel() override;
  void declare(FieldsFile& file) const override;
  void write_frame(FieldsFile& file, const std::vector<std::string>& fields) const override;
  std::optional<double> probe(const ProbeSpec& probe) const override;
  /// Once per run: the first factorisation the default solver did by LU.
  std::vector<std::string> take_notes() override;
  const InterfaceMesh& interface_mesh() const override { return interface_.mesh; }
  std::vector<Polygon> occupied_area() const override;
  coupling::StructureSolver& coupling_solver() override;

  /// The interface with its FE nodes (NCR, eq. 50).
  const fem::FeInterface& interface() const { return interface_; }

private:
  fem::FeInterface interface_;
  std::optional<WallFrame> frame_; // the clamped_motion wall's motion (tank-frame probes)
  std::vector<std::pair<std::string, int>> probe_nodes_; // probe name -> node
  std::unique_ptr<PartAdapter<fem::T6>> adapter_;
  bool lu_noted_ = false;
};

} // namespace fsi::app::fem_plugin
