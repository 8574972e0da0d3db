#include "fsi_app/material_reader.hpp"

namespace fsi::app {

void read_material(Section& block, materials::MaterialOptions& options) {
  const bool three_d = !block.context().documenting() && block.context().dimension == 3;
  if (three_d && block.has("plane"))
    block.fail("plane", "a 3-D solid has the full 3-D law; plane is 2-D only");
  OptionReader reader(block);
  materials::visit_options(options, reader);
  if (!block.context().documenting() && !three_d &&
      options.model == materials::MaterialModel::neo_hookean &&
      options.plane != materials::PlaneModel::plane_strain)
    block.fail("model", "neo_hookean is implemented in plane strain only (plane: strain)");
  block.finish();
}

} // namespace fsi::app
