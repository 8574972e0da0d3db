#include "fsi/core/error.hpp"
#include "fsi_app/coupled_model.hpp"
#include "fsi_app/fluid_model.hpp"
#include "fsi_app/run.hpp"
#include "fsi_app/structure_model.hpp"

namespace fsi::app {

std::vector<std::unique_ptr<Model>> build_models(const Scene& scene) {
  std::vector<std::unique_ptr<Model>> models;
  if (scene.fluid && !scene.structures.empty()) {
    if (!scene.time.dt)
      fail_at(scene, scene.fluid->line, "time.dt", "a coupled scene needs a fixed time step");
    models.push_back(std::make_unique<CoupledModel>(scene));
    return models;
  }
  if (scene.fluid) models.push_back(std::make_unique<FluidModel>(scene));
  for (const auto& spec : scene.structures)
    models.push_back(std::make_unique<StructureModel>(scene, spec));
  return models;
}

} // namespace fsi::app
