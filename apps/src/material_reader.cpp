#include "fsi_app/material_reader.hpp"

namespace fsi::app {

void read_material(Section& block, materials::MaterialOptions& options) {
  OptionReader reader(block);
  materials::visit_options(options, reader);
  if (!block.context().documenting() && options.model == materials::MaterialModel::neo_hookean &&
      options.plane != materials::PlaneModel::plane_strain)
    block.fail("model", "neo_hookean is implemented in plane strain only (plane: strain)");
  block.finish();
}

} // namespace fsi::app
