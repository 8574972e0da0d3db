#include "coupling/scheme_one_way_structure.hpp"

#include <sstream>

#include "fsi/core/error.hpp"

namespace fsi::coupling {

OneWayStructureScheme::OneWayStructureScheme(const CouplingOptions& options,
                                             StructureSolver& structure, LoadFunction prescribed,
                                             SchemeComponents components)
    : CouplingScheme("one_way_structure", options, std::move(components)), structure_(structure),
      prescribed_(std::move(prescribed)) {}

InterfaceMotion OneWayStructureScheme::initialize_participants(double /*t0*/) {
  time_structure([&] { structure_.initialize(); });
  return structure_.interface_motion();
}

void OneWayStructureScheme::finalize_participants() {
  structure_.finalize();
}

InterfaceMotion OneWayStructureScheme::evaluate(double t, double dt,
                                                const InterfaceMotion& /*input*/) {
  loads_ = prescribed_(t + dt);
  if (loads_.size() != n_nodes_) {
    std::ostringstream e;
    e << "coupling (one_way_structure): prescribed loads at t = " << t + dt << " s have "
      << loads_.size() << " entries, expected " << n_nodes_ << " interface nodes";
    throw RunError(e.str());
  }
  return run_structure(structure_, loads_, t, dt);
}

} // namespace fsi::coupling
