#pragma once
// Scheme "one_way_fluid": the fluid against a prescribed interface motion. Sub-step k of the
// step [t, t + dt] gets prescribed(t + k dt / m) (exact, not interpolated). The loads (averaged
// over the sub-steps) are available from interface_loads() for output; no structure is run.
// BasicOneWayFluidScheme<D> for D = 2 and 3.
#include "coupling/scheme.hpp"

namespace fsi::coupling {

template <int D> class BasicOneWayFluidScheme final : public BasicCouplingScheme<D> {
public:
  using typename BasicCouplingScheme<D>::Fluid;

  BasicOneWayFluidScheme(const CouplingOptions& options, Fluid& fluid,
                         BasicMotionFunction<D> prescribed, BasicSchemeComponents<D> components);

protected:
  BasicInterfaceMotion<D> initialize_participants(double t0) override;
  void finalize_participants() override;
  void write_participants(StateArchive& archive) const override { fluid_.write_state(archive); }
  void read_participants(const StateArchive& archive) override { fluid_.read_state(archive); }
  BasicInterfaceMotion<D> first_input(double t, double dt) override { return prescribed_(t + dt); }
  BasicInterfaceMotion<D> evaluate(double t, double dt,
                                   const BasicInterfaceMotion<D>& input) override;

private:
  Fluid& fluid_;
  BasicMotionFunction<D> prescribed_;
};

extern template class BasicOneWayFluidScheme<2>;
extern template class BasicOneWayFluidScheme<3>;
using OneWayFluidScheme = BasicOneWayFluidScheme<2>;
using OneWayFluidScheme3 = BasicOneWayFluidScheme<3>;

} // namespace fsi::coupling
