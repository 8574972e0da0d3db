#include "fsi/core/error.hpp"
#include "fsi_app/run.hpp"
#include "fsi_app/structure_model.hpp"

namespace fsi::app {

std::vector<std::unique_ptr<Model>> build_models(const Scene& scene) {
  if (scene.fluid)
    throw InputError(scene.path.string() + ": fluid: the EMPS fluid is not part of this build yet");
  std::vector<std::unique_ptr<Model>> models;
  for (const auto& spec : scene.structures)
    models.push_back(std::make_unique<StructureModel>(scene, spec));
  return models;
}

} // namespace fsi::app
