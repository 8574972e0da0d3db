#include "fsi/core/error.hpp"
#include "fsi_app/coupled_model.hpp"
#include "fsi_app/output/interface_history.hpp"
#include "fsi_app/run.hpp"
#include "fsi_app/solver_plugin.hpp"

namespace fsi::app {

namespace {
bool coupled(const Scene& scene) {
  return scene.fluid && !scene.structures.empty();
}
} // namespace

std::vector<std::unique_ptr<Model>> build_models(const Scene& scene, const Ranks& ranks) {
  std::vector<std::unique_ptr<Model>> models;
  if (coupled(scene)) {
    if (scene.dimension == 3)
      models.push_back(std::make_unique<CoupledModel3>(scene, ranks));
    else
      models.push_back(std::make_unique<CoupledModel>(scene, ranks));
    return models;
  }
  if (scene.fluid)
    models.push_back(find_fluid_plugin(scene.fluid->type)->build(scene, {}, {}, ranks));
  for (std::size_t i = 0; i < scene.structures.size(); ++i)
    models.push_back(find_structure_plugin(scene.structures[i].type)->build(scene, i));
  return models;
}

void check_models(const Scene& scene) {
  std::vector<InterfaceMesh> interfaces;
  std::vector<InterfaceMesh3> interfaces3;
  std::vector<Polygon> solid;
  std::size_t nodes = 0;
  for (std::size_t i = 0; i < scene.structures.size(); ++i) {
    StructureOutline o = find_structure_plugin(scene.structures[i].type)->validate(scene, i);
    nodes += scene.dimension == 3 ? o.interface3.node_count() : o.interface.node_count();
    interfaces.push_back(std::move(o.interface));
    interfaces3.push_back(std::move(o.interface3));
    solid.insert(solid.end(), o.occupied.begin(), o.occupied.end());
  }
  const bool both = coupled(scene);
  const FluidPlugin* fluid = scene.fluid ? find_fluid_plugin(scene.fluid->type) : nullptr;
  if (fluid && both && scene.dimension == 3) {
    if (fluid->validate3) fluid->validate3(scene, interfaces3);
  } else if (fluid) {
    fluid->validate(scene, both ? interfaces : std::vector<InterfaceMesh>{},
                    both ? solid : std::vector<Polygon>{});
  }
  if (both && scene.dimension == 3)
    open_replay<3>(scene, nodes);
  else if (both)
    open_replay<2>(scene, nodes);
}

} // namespace fsi::app
