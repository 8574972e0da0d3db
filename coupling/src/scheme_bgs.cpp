#include "coupling/scheme_bgs.hpp"

namespace fsi::coupling {

BgsScheme::BgsScheme(const CouplingOptions& options, FluidSolver& fluid, StructureSolver& structure,
                     SchemeComponents components)
    : CouplingScheme("bgs", options, std::move(components)), fluid_(fluid), structure_(structure) {}

InterfaceMotion BgsScheme::initialize_participants(double /*t0*/) {
  time_fluid([&] { fluid_.initialize(); });
  time_structure([&] { structure_.initialize(); });
  return structure_.interface_motion();
}

void BgsScheme::finalize_participants() {
  fluid_.finalize();
  structure_.finalize();
}

void BgsScheme::save_checkpoint() {
  time_fluid([&] { fluid_.save_state(); });
  time_structure([&] { structure_.save_state(); });
}

void BgsScheme::restore_checkpoint() {
  time_fluid([&] { fluid_.restore_state(); });
  time_structure([&] { structure_.restore_state(); });
}

} // namespace fsi::coupling
