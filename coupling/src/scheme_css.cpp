#include "coupling/scheme_css.hpp"

namespace fsi::coupling {

CssScheme::CssScheme(const CouplingOptions& options, FluidSolver& fluid, StructureSolver& structure,
                     SchemeComponents components)
    : CouplingScheme("css", options, std::move(components)), fluid_(fluid), structure_(structure) {}

InterfaceMotion CssScheme::initialize_participants(double /*t0*/) {
  time_fluid([&] { fluid_.initialize(); });
  time_structure([&] { structure_.initialize(); });
  return structure_.interface_motion();
}

void CssScheme::finalize_participants() {
  fluid_.finalize();
  structure_.finalize();
}

} // namespace fsi::coupling
