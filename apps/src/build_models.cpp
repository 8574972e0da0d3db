#include "fsi/core/error.hpp"
#include "fsi_app/run.hpp"

namespace fsi::app {

std::vector<std::unique_ptr<Model>> build_models(const Scene& scene) {
  std::vector<std::unique_ptr<Model>> models;
  if (scene.fluid)
    throw InputError(scene.path.string() +
                     ": fluid: the EMPS fluid solver is not part of this build yet");
  if (!scene.structures.empty())
    throw InputError(scene.path.string() +
                     ": structures: the FEM solver is not part of this build yet");
  return models;
}

} // namespace fsi::app
