#include "fsi/core/error.hpp"
#include "fsi_app/coupled_model.hpp"
#include "fsi_app/run.hpp"
#include "fsi_app/solver_plugin.hpp"

namespace fsi::app {

std::vector<std::unique_ptr<Model>> build_models(const Scene& scene) {
  std::vector<std::unique_ptr<Model>> models;
  if (scene.fluid && !scene.structures.empty()) {
    if (!scene.time.dt)
      fail_at(scene, scene.fluid->line, "time.dt", "a coupled scene needs a fixed time step");
    models.push_back(std::make_unique<CoupledModel>(scene));
    return models;
  }
  if (scene.fluid) models.push_back(find_fluid_plugin(scene.fluid->type)->build(scene, {}, {}));
  for (std::size_t i = 0; i < scene.structures.size(); ++i)
    models.push_back(find_structure_plugin(scene.structures[i].type)->build(scene, i));
  return models;
}

} // namespace fsi::app
