#include "coupling/scheme_serial.hpp"

namespace fsi::coupling {

SerialScheme::SerialScheme(std::string name, const CouplingOptions& options, FluidSolver& fluid,
                           StructureSolver& structure, SchemeComponents components)
    : CouplingScheme(std::move(name), options, std::move(components)), fluid_(fluid),
      structure_(structure) {}

InterfaceMotion SerialScheme::initialize_participants(double /*t0*/) {
  time_fluid([&] { fluid_.initialize(); });
  time_structure([&] { structure_.initialize(); });
  return structure_.interface_motion();
}

void SerialScheme::finalize_participants() {
  fluid_.finalize();
  structure_.finalize();
}

void SerialScheme::write_participants(StateArchive& archive) const {
  fluid_.write_state(archive);
  structure_.write_state(archive);
}

void SerialScheme::read_participants(const StateArchive& archive) {
  fluid_.read_state(archive);
  structure_.read_state(archive);
}

void SerialScheme::save_checkpoint() {
  time_fluid([&] { fluid_.save_state(); });
  time_structure([&] { structure_.save_state(); });
}

void SerialScheme::restore_checkpoint() {
  time_fluid([&] { fluid_.restore_state(); });
  time_structure([&] { structure_.restore_state(); });
}

} // namespace fsi::coupling
