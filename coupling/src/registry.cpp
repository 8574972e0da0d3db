#include "coupling/registry.hpp"

#include <sstream>

#include "coupling/acceleration_aitken.hpp"
#include "coupling/acceleration_constant.hpp"
#include "coupling/acceleration_iqn_ils.hpp"
#include "coupling/acceleration_none.hpp"
#include "coupling/convergence_absolute.hpp"
#include "coupling/convergence_relative.hpp"
#include "coupling/predictor_none.hpp"
#include "coupling/predictor_second_order.hpp"
#include "coupling/scheme_one_way_fluid.hpp"
#include "coupling/scheme_one_way_structure.hpp"
#include "coupling/scheme_serial.hpp"
#include "fsi/core/error.hpp"

namespace fsi::coupling {

namespace {

template <class Map>
const typename Map::mapped_type& find(const Map& map, std::string_view name, const char* key,
                                      const std::vector<std::string>& allowed) {
  const auto it = map.find(std::string(name));
  if (it != map.end()) return it->second;
  std::ostringstream s;
  s << "coupling." << key << ": unknown name '" << name << "' (allowed:";
  for (const auto& a : allowed) s << " " << a;
  s << ")";
  throw InputError(s.str());
}

template <int D>
void check_participants(const std::string& scheme, const SchemeNeeds& n,
                        const BasicParticipants<D>& p) {
  const auto missing = [&](bool needed, bool given, const char* what) {
    if (needed && !given) throw InputError("coupling.scheme: '" + scheme + "' needs " + what);
  };
  missing(n.fluid, p.fluid != nullptr, "a fluid solver");
  missing(n.structure, p.structure != nullptr, "a structure solver");
  missing(n.prescribed_motion, static_cast<bool>(p.prescribed_motion),
          "a prescribed motion (coupling.motion)");
  missing(n.prescribed_loads, static_cast<bool>(p.prescribed_loads),
          "prescribed loads (coupling.loads)");
}

} // namespace

template <int D>
void BasicRegistry<D>::add_scheme(std::string name, std::string doc, SchemeNeeds needs,
                                  SchemeFactory factory) {
  schemes_[std::move(name)] = {std::move(doc), std::move(factory), needs};
}

template <int D> SchemeNeeds BasicRegistry<D>::scheme_needs(std::string_view name) const {
  return find(schemes_, name, "scheme", scheme_names()).needs;
}
template <int D>
void BasicRegistry<D>::add_acceleration(std::string name, std::string doc,
                                        AccelerationFactory factory) {
  accelerations_[std::move(name)] = {std::move(doc), std::move(factory)};
}
template <int D>
void BasicRegistry<D>::add_predictor(std::string name, std::string doc, PredictorFactory factory) {
  predictors_[std::move(name)] = {std::move(doc), std::move(factory)};
}
template <int D>
void BasicRegistry<D>::add_measure(std::string name, std::string doc, MeasureFactory factory) {
  measures_[std::move(name)] = {std::move(doc), std::move(factory)};
}

template <int D>
std::unique_ptr<BasicCouplingScheme<D>>
BasicRegistry<D>::make_scheme(const CouplingOptions& options,
                              const BasicParticipants<D>& participants) const {
  validate_options(options, *this);
  const auto& entry = find(schemes_, options.scheme, "scheme", scheme_names());
  check_participants(options.scheme, entry.needs, participants);
  return entry.factory(options, participants, *this);
}

template <int D>
std::unique_ptr<Acceleration>
BasicRegistry<D>::make_acceleration(std::string_view name, const CouplingOptions& options) const {
  return find(accelerations_, name, "acceleration", acceleration_names()).factory(options);
}

template <int D>
std::unique_ptr<BasicPredictor<D>>
BasicRegistry<D>::make_predictor(std::string_view name, const CouplingOptions& options) const {
  return find(predictors_, name, "predictor", predictor_names()).factory(options);
}

template <int D>
std::unique_ptr<ConvergenceMeasure>
BasicRegistry<D>::make_measure(std::string_view name, const CouplingOptions& options) const {
  return find(measures_, name, "convergence", measure_names()).factory(options);
}

template class BasicRegistry<2>;
template class BasicRegistry<3>;

template <int D> void register_builtin_components(BasicRegistry<D>& r) {
  using Options = CouplingOptions;
  using Given = BasicParticipants<D>;
  using Reg = BasicRegistry<D>;
  // Schemes. css and bgs are one serial scheme; an acceleration makes it implicit.
  const SchemeNeeds serial{true, true, false, false};
  r.add_scheme("css", "conventional serial staggered: predict, F, loads, S; one evaluation", serial,
               [](const Options& o, const Given& p, const Reg& reg) {
                 BasicSchemeComponents<D> c;
                 c.predictor = reg.make_predictor(o.predictor, o);
                 return std::make_unique<BasicSerialScheme<D>>("css", o, *p.fluid, *p.structure,
                                                               std::move(c));
               });
  r.add_scheme("bgs", "block Gauss-Seidel iterations within the step (eqs. 68-69), accelerated",
               serial, [](const Options& o, const Given& p, const Reg& reg) {
                 BasicSchemeComponents<D> c;
                 c.predictor = reg.make_predictor(o.predictor, o);
                 c.acceleration = reg.make_acceleration(o.acceleration, o);
                 c.measures.push_back(reg.make_measure(o.convergence, o));
                 if (o.converge_velocities)
                   c.measures.push_back(reg.make_measure(o.convergence, o));
                 return std::make_unique<BasicSerialScheme<D>>("bgs", o, *p.fluid, *p.structure,
                                                               std::move(c));
               });
  r.add_scheme("one_way_fluid", "fluid against a prescribed interface motion",
               {true, false, true, false}, [](const Options& o, const Given& p, const Reg& reg) {
                 BasicSchemeComponents<D> c;
                 c.predictor = reg.make_predictor("none", o);
                 return std::make_unique<BasicOneWayFluidScheme<D>>(
                     o, *p.fluid, p.prescribed_motion, std::move(c));
               });
  r.add_scheme("one_way_structure", "structure under prescribed (recorded) interface loads",
               {false, true, false, true}, [](const Options& o, const Given& p, const Reg& reg) {
                 BasicSchemeComponents<D> c;
                 c.predictor = reg.make_predictor("none", o);
                 return std::make_unique<BasicOneWayStructureScheme<D>>(
                     o, *p.structure, p.prescribed_loads, std::move(c));
               });

  // Accelerations.
  r.add_acceleration("none", "plain BGS: x^{i+1} = x~^i",
                     [](const CouplingOptions&) { return std::make_unique<NoAcceleration>(); });
  r.add_acceleration(
      "constant", "constant relaxation with factor omega",
      [](const CouplingOptions& o) { return std::make_unique<ConstantRelaxation>(o.omega); });
  r.add_acceleration("aitken", "Aitken dynamic relaxation (Kuettler & Wall 2008)",
                     [](const CouplingOptions& o) {
                       return std::make_unique<AitkenRelaxation>(o.omega, o.aitken_omega_max);
                     });
  r.add_acceleration("iqn-ils", "interface quasi-Newton, inverse least squares (Degroote 2009)",
                     [](const CouplingOptions& o) {
                       return std::make_unique<IqnIlsAcceleration>(o.omega, o.reuse, o.iqn_filter);
                     });

  // Predictors.
  r.add_predictor("none", "keep x^n, v^n, a^n",
                  [](const CouplingOptions&) { return std::make_unique<BasicNoPredictor<D>>(); });
  r.add_predictor(
      "second_order", "Newmark-consistent extrapolation with a^ = a^n (eqs. 63-65)",
      [](const CouplingOptions&) { return std::make_unique<BasicSecondOrderPredictor<D>>(); });

  // Convergence measures.
  r.add_measure("relative", "||r^i|| / ||r^0|| < tolerance (eq. 69)", [](const CouplingOptions& o) {
    return std::make_unique<RelativeConvergence>(o.tolerance);
  });
  r.add_measure("absolute", "||r^i|| < tolerance", [](const CouplingOptions& o) {
    return std::make_unique<AbsoluteConvergence>(o.tolerance);
  });
}

template <int D> const BasicRegistry<D>& builtin_registry() {
  static const BasicRegistry<D> registry = [] {
    BasicRegistry<D> r;
    register_builtin_components(r);
    return r;
  }();
  return registry;
}

template void register_builtin_components(Registry&);
template void register_builtin_components(Registry3&);
template const Registry& builtin_registry<2>();
template const Registry3& builtin_registry<3>();

std::unique_ptr<Acceleration> make_acceleration(std::string_view name,
                                                const CouplingOptions& options) {
  return builtin_registry().make_acceleration(name, options);
}

} // namespace fsi::coupling
