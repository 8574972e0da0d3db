#pragma once
// The FE structure of one entry of a 3-D scene (dimension: 3, structures[].type: fem): the T10
// solid (a box mesh or a Gmsh file) under gravity and the scene's constant face loads; its
// interface, the 6-node faces of the tagged surfaces (fem::interface_of, NCR eq. 50), and the
// coupler's S on it (PartAdapter<T10>: interface loads in as nodal forces, node motion out). The
// part shows no 2-D interface or area; a 3-D fluid couples through interface_mesh3() and
// coupling_solver3().
#include "fem/fe_adapter.hpp"
#include "fem/fem_part.hpp"
#include "fem/fem_spec.hpp"
#include "fsi_app/solver_plugin.hpp"
#include "structure_fem/mesh_t10.hpp"
#include "structure_fem/structure.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fsi::app::fem_plugin {

/// The box's sides by name: left/right along x, bottom/top along y, back/front along z
/// (x_min, x_max, y_min, y_max, z_min, z_max of fem::make_box_mesh).
const std::vector<std::string>& box_sides();

/// The entry's T10 mesh, generated (box, faces tagged by box_sides) or read (Gmsh physical
/// surfaces), with its tags and probe nodes checked. Throws InputError (scene file and line).
fem::TetMesh checked_tet_mesh(const Scene& scene, const StructureBlock& block);

class FemModelT10 final : public BasicFemPart<fem::T10> {
public:
  FemModelT10(const Scene& scene, const StructureBlock& block);
  void declare(FieldsFile& file) const override;
  void write_frame(FieldsFile& file, const std::vector<std::string>& fields) const override;
  std::optional<double> probe(const ProbeSpec& probe) const override;
  const InterfaceMesh& interface_mesh() const override { return no_interface_; }
  std::vector<Polygon> occupied_area() const override { return {}; }
  /// The 2-D S: throws std::logic_error (a 3-D structure's S is coupling_solver3()).
  coupling::StructureSolver& coupling_solver() override;

  /// The tagged interface surfaces' 6-node faces with their FE nodes (NCR, eq. 50).
  const fem::FeInterface3& interface() const { return interface_; }
  /// The coupler's S (eq. 67) on the T10 structure through interface().
  coupling::StructureSolver3& coupling_solver3() override { return adapter_; }
  /// interface()'s mesh: what the fluid of a 3-D coupled scene is built on.
  const InterfaceMesh3& interface_mesh3() const override { return interface_.mesh; }

private:
  InterfaceMesh no_interface_;
  fem::FeInterface3 interface_;
  PartAdapter<fem::T10> adapter_{*this, interface_};
  std::vector<std::pair<std::string, int>> probe_nodes_; // probe name -> node
};

} // namespace fsi::app::fem_plugin
