#pragma once
// Scheme "one_way_structure": the structure under prescribed (e.g. recorded) loads, evaluated at
// the end of each step, prescribed(t + dt), as a Newmark structure expects. No fluid is run.
// BasicOneWayStructureScheme<D> for D = 2 and 3.
#include "coupling/scheme.hpp"

namespace fsi::coupling {

template <int D> class BasicOneWayStructureScheme final : public BasicCouplingScheme<D> {
public:
  using typename BasicCouplingScheme<D>::Structure;

  BasicOneWayStructureScheme(const CouplingOptions& options, Structure& structure,
                             BasicLoadFunction<D> prescribed, BasicSchemeComponents<D> components);

protected:
  BasicInterfaceMotion<D> initialize_participants(double t0) override;
  void finalize_participants() override;
  void write_participants(StateArchive& archive) const override { structure_.write_state(archive); }
  void read_participants(const StateArchive& archive) override { structure_.read_state(archive); }
  BasicInterfaceMotion<D> evaluate(double t, double dt,
                                   const BasicInterfaceMotion<D>& input) override;

private:
  Structure& structure_;
  BasicLoadFunction<D> prescribed_;
};

extern template class BasicOneWayStructureScheme<2>;
extern template class BasicOneWayStructureScheme<3>;
using OneWayStructureScheme = BasicOneWayStructureScheme<2>;
using OneWayStructureScheme3 = BasicOneWayStructureScheme<3>;

} // namespace fsi::coupling
