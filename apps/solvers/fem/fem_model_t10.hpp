#pragma once
// The FE structure of one entry of a 3-D scene (dimension: 3, structures[].type: fem): the T10
// solid (a box mesh or a Gmsh file) under gravity and the scene's constant face loads. 3-D
// scenes take no fluid yet (read_scene refuses one), so the part is never coupled: it shows no
// 2-D interface and occupies no 2-D area.
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
  /// Never called: a 3-D scene has no fluid to couple to (throws std::logic_error).
  coupling::StructureSolver& coupling_solver() override;

private:
  InterfaceMesh no_interface_;
  std::vector<std::pair<std::string, int>> probe_nodes_; // probe name -> node
};

} // namespace fsi::app::fem_plugin
