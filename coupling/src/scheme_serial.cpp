#include "coupling/scheme_serial.hpp"

namespace fsi::coupling {

template <int D>
BasicSerialScheme<D>::BasicSerialScheme(std::string name, const CouplingOptions& options,
                                        Fluid& fluid, Structure& structure,
                                        BasicSchemeComponents<D> components)
    : BasicCouplingScheme<D>(std::move(name), options, std::move(components)), fluid_(fluid),
      structure_(structure) {}

template <int D>
BasicInterfaceMotion<D> BasicSerialScheme<D>::initialize_participants(double /*t0*/) {
  this->time_fluid([&] { fluid_.initialize(); });
  this->time_structure([&] { structure_.initialize(); });
  return structure_.interface_motion();
}

template <int D> void BasicSerialScheme<D>::finalize_participants() {
  fluid_.finalize();
  structure_.finalize();
}

template <int D> void BasicSerialScheme<D>::write_participants(StateArchive& archive) const {
  fluid_.write_state(archive);
  structure_.write_state(archive);
}

template <int D> void BasicSerialScheme<D>::read_participants(const StateArchive& archive) {
  fluid_.read_state(archive);
  structure_.read_state(archive);
}

template <int D> void BasicSerialScheme<D>::save_checkpoint() {
  this->time_fluid([&] { fluid_.save_state(); });
  this->time_structure([&] { structure_.save_state(); });
}

template <int D> void BasicSerialScheme<D>::restore_checkpoint() {
  this->time_fluid([&] { fluid_.restore_state(); });
  this->time_structure([&] { structure_.restore_state(); });
}

template class BasicSerialScheme<2>;
template class BasicSerialScheme<3>;

} // namespace fsi::coupling
