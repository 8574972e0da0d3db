#include "coupling/scheme_one_way_structure.hpp"

#include <sstream>

#include "fsi/core/error.hpp"

namespace fsi::coupling {

template <int D>
BasicOneWayStructureScheme<D>::BasicOneWayStructureScheme(const CouplingOptions& options,
                                                          Structure& structure,
                                                          BasicLoadFunction<D> prescribed,
                                                          BasicSchemeComponents<D> components)
    : BasicCouplingScheme<D>("one_way_structure", options, std::move(components)),
      structure_(structure), prescribed_(std::move(prescribed)) {}

template <int D>
BasicInterfaceMotion<D> BasicOneWayStructureScheme<D>::initialize_participants(double /*t0*/) {
  this->time_structure([&] { structure_.initialize(); });
  return structure_.interface_motion();
}

template <int D> void BasicOneWayStructureScheme<D>::finalize_participants() {
  structure_.finalize();
}

template <int D>
BasicInterfaceMotion<D>
BasicOneWayStructureScheme<D>::evaluate(double t, double dt,
                                        const BasicInterfaceMotion<D>& /*input*/) {
  this->loads_ = prescribed_(t + dt);
  if (this->loads_.size() != this->n_nodes_) {
    std::ostringstream e;
    e << "coupling (one_way_structure): prescribed loads at t = " << t + dt << " s have "
      << this->loads_.size() << " entries, expected " << this->n_nodes_ << " interface nodes";
    throw RunError(e.str());
  }
  return this->run_structure(structure_, this->loads_, t, dt);
}

template class BasicOneWayStructureScheme<2>;
template class BasicOneWayStructureScheme<3>;

} // namespace fsi::coupling
