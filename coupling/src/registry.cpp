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

void check_participants(const std::string& scheme, const SchemeNeeds& n, const Participants& p) {
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

void Registry::add_scheme(std::string name, std::string doc, SchemeNeeds needs,
                          SchemeFactory factory) {
  schemes_[std::move(name)] = {std::move(doc), std::move(factory), needs};
}

SchemeNeeds Registry::scheme_needs(std::string_view name) const {
  return find(schemes_, name, "scheme", scheme_names()).needs;
}
void Registry::add_acceleration(std::string name, std::string doc, AccelerationFactory factory) {
  accelerations_[std::move(name)] = {std::move(doc), std::move(factory)};
}
void Registry::add_predictor(std::string name, std::string doc, PredictorFactory factory) {
  predictors_[std::move(name)] = {std::move(doc), std::move(factory)};
}
void Registry::add_measure(std::string name, std::string doc, MeasureFactory factory) {
  measures_[std::move(name)] = {std::move(doc), std::move(factory)};
}

std::unique_ptr<CouplingScheme> Registry::make_scheme(const CouplingOptions& options,
                                                      const Participants& participants) const {
  validate_options(options, *this);
  const auto& entry = find(schemes_, options.scheme, "scheme", scheme_names());
  check_participants(options.scheme, entry.needs, participants);
  return entry.factory(options, participants, *this);
}

std::unique_ptr<Acceleration> Registry::make_acceleration(std::string_view name,
                                                          const CouplingOptions& options) const {
  return find(accelerations_, name, "acceleration", acceleration_names()).factory(options);
}

std::unique_ptr<Predictor> Registry::make_predictor(std::string_view name,
                                                    const CouplingOptions& options) const {
  return find(predictors_, name, "predictor", predictor_names()).factory(options);
}

std::unique_ptr<ConvergenceMeasure> Registry::make_measure(std::string_view name,
                                                           const CouplingOptions& options) const {
  return find(measures_, name, "convergence", measure_names()).factory(options);
}

void register_builtin_components(Registry& r) {
  // Schemes. css and bgs are one serial scheme; an acceleration makes it implicit.
  const SchemeNeeds serial{true, true, false, false};
  r.add_scheme("css", "conventional serial staggered: predict, F, loads, S; one evaluation", serial,
               [](const CouplingOptions& o, const Participants& p, const Registry& reg) {
                 SchemeComponents c;
                 c.predictor = reg.make_predictor(o.predictor, o);
                 return std::make_unique<SerialScheme>("css", o, *p.fluid, *p.structure,
                                                       std::move(c));
               });
  r.add_scheme("bgs", "block Gauss-Seidel iterations within the step (eqs. 68-69), accelerated",
               serial, [](const CouplingOptions& o, const Participants& p, const Registry& reg) {
                 SchemeComponents c;
                 c.predictor = reg.make_predictor(o.predictor, o);
                 c.acceleration = reg.make_acceleration(o.acceleration, o);
                 c.measures.push_back(reg.make_measure(o.convergence, o));
                 if (o.converge_velocities)
                   c.measures.push_back(reg.make_measure(o.convergence, o));
                 return std::make_unique<SerialScheme>("bgs", o, *p.fluid, *p.structure,
                                                       std::move(c));
               });
  r.add_scheme(
      "one_way_fluid", "fluid against a prescribed interface motion", {true, false, true, false},
      [](const CouplingOptions& o, const Participants& p, const Registry& reg) {
        SchemeComponents c;
        c.predictor = reg.make_predictor("none", o);
        return std::make_unique<OneWayFluidScheme>(o, *p.fluid, p.prescribed_motion, std::move(c));
      });
  r.add_scheme("one_way_structure", "structure under prescribed (recorded) interface loads",
               {false, true, false, true},
               [](const CouplingOptions& o, const Participants& p, const Registry& reg) {
                 SchemeComponents c;
                 c.predictor = reg.make_predictor("none", o);
                 return std::make_unique<OneWayStructureScheme>(o, *p.structure, p.prescribed_loads,
                                                                std::move(c));
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
                  [](const CouplingOptions&) { return std::make_unique<NoPredictor>(); });
  r.add_predictor("second_order", "Newmark-consistent extrapolation with a^ = a^n (eqs. 63-65)",
                  [](const CouplingOptions&) { return std::make_unique<SecondOrderPredictor>(); });

  // Convergence measures.
  r.add_measure("relative", "||r^i|| / ||r^0|| < tolerance (eq. 69)", [](const CouplingOptions& o) {
    return std::make_unique<RelativeConvergence>(o.tolerance);
  });
  r.add_measure("absolute", "||r^i|| < tolerance", [](const CouplingOptions& o) {
    return std::make_unique<AbsoluteConvergence>(o.tolerance);
  });
}

const Registry& builtin_registry() {
  static const Registry registry = [] {
    Registry r;
    register_builtin_components(r);
    return r;
  }();
  return registry;
}

std::unique_ptr<CouplingScheme> make_scheme(const CouplingOptions& options,
                                            const Participants& participants) {
  return builtin_registry().make_scheme(options, participants);
}

std::unique_ptr<CouplingScheme> make_scheme(const CouplingOptions& options, FluidSolver& fluid,
                                            StructureSolver& structure) {
  Participants p;
  p.fluid = &fluid;
  p.structure = &structure;
  return make_scheme(options, p);
}

std::unique_ptr<Acceleration> make_acceleration(std::string_view name,
                                                const CouplingOptions& options) {
  return builtin_registry().make_acceleration(name, options);
}

std::unique_ptr<Predictor> make_predictor(std::string_view name, const CouplingOptions& options) {
  return builtin_registry().make_predictor(name, options);
}

} // namespace fsi::coupling
