#pragma once
// Components chosen by name. A Registry maps names to factories; register_builtin_components()
// is the one place that lists the built-in schemes, accelerations, predictors and measures.
// A new component plugs in by one add_*() line there (or on a registry of one's own).
// A registry is of one dimension, BasicRegistry<D> for D = 2 (Registry) and 3 (Registry3): its
// scheme and predictor factories make objects of that dimension (docs/architecture.md).
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "coupling/acceleration.hpp"
#include "coupling/convergence.hpp"
#include "coupling/options.hpp"
#include "coupling/predictor.hpp"
#include "coupling/scheme.hpp"

namespace fsi::coupling {

/// What a scheme couples, declared with it: make_scheme checks the participants against it, and a
/// caller (the scene reader) asks it instead of testing scheme names.
struct SchemeNeeds {
  bool fluid = false, structure = false;
  bool prescribed_motion = false, prescribed_loads = false;
};

template <int D> class BasicRegistry {
public:
  using SchemeFactory = std::function<std::unique_ptr<BasicCouplingScheme<D>>(
      const CouplingOptions&, const BasicParticipants<D>&, const BasicRegistry&)>;
  using AccelerationFactory = std::function<std::unique_ptr<Acceleration>(const CouplingOptions&)>;
  using PredictorFactory =
      std::function<std::unique_ptr<BasicPredictor<D>>(const CouplingOptions&)>;
  using MeasureFactory = std::function<std::unique_ptr<ConvergenceMeasure>(const CouplingOptions&)>;

  /// Register a factory under `name` with a one-line description. Replaces an existing entry.
  void add_scheme(std::string name, std::string doc, SchemeNeeds needs, SchemeFactory factory);
  void add_acceleration(std::string name, std::string doc, AccelerationFactory factory);
  void add_predictor(std::string name, std::string doc, PredictorFactory factory);
  void add_measure(std::string name, std::string doc, MeasureFactory factory);

  /// Build by name; unknown names throw fsi::InputError naming the key and the allowed names.
  /// make_scheme also validates the options and checks the participants the scheme needs.
  std::unique_ptr<BasicCouplingScheme<D>>
  make_scheme(const CouplingOptions& options, const BasicParticipants<D>& participants) const;
  std::unique_ptr<Acceleration> make_acceleration(std::string_view name,
                                                  const CouplingOptions& options) const;
  std::unique_ptr<BasicPredictor<D>> make_predictor(std::string_view name,
                                                    const CouplingOptions& options) const;
  std::unique_ptr<ConvergenceMeasure> make_measure(std::string_view name,
                                                   const CouplingOptions& options) const;

  /// Names in alphabetical order, and their docs (for generated documentation and messages).
  std::vector<std::string> scheme_names() const { return names(schemes_); }
  std::vector<std::string> acceleration_names() const { return names(accelerations_); }
  std::vector<std::string> predictor_names() const { return names(predictors_); }
  std::vector<std::string> measure_names() const { return names(measures_); }
  bool has_scheme(std::string_view n) const { return schemes_.count(std::string(n)) != 0; }
  /// The participants scheme `name` needs; InputError for an unknown name.
  SchemeNeeds scheme_needs(std::string_view name) const;
  bool has_acceleration(std::string_view n) const {
    return accelerations_.count(std::string(n)) != 0;
  }
  bool has_predictor(std::string_view n) const { return predictors_.count(std::string(n)) != 0; }
  bool has_measure(std::string_view n) const { return measures_.count(std::string(n)) != 0; }

  template <class F> struct Entry {
    std::string doc;
    F factory;
    SchemeNeeds needs{}; ///< schemes only
  };

private:
  template <class F>
  static std::vector<std::string> names(const std::map<std::string, Entry<F>>& m) {
    std::vector<std::string> out;
    for (const auto& [name, entry] : m) out.push_back(name);
    return out;
  }
  std::map<std::string, Entry<SchemeFactory>> schemes_;
  std::map<std::string, Entry<AccelerationFactory>> accelerations_;
  std::map<std::string, Entry<PredictorFactory>> predictors_;
  std::map<std::string, Entry<MeasureFactory>> measures_;
};

extern template class BasicRegistry<2>;
extern template class BasicRegistry<3>;
using Registry = BasicRegistry<2>;
using Registry3 = BasicRegistry<3>;

/// Fill `registry` with the built-in components:
///   schemes: css, bgs, one_way_fluid, one_way_structure
///   accelerations: none, constant, aitken, iqn-ils
///   predictors: none, second_order;  measures: relative, absolute.
template <int D> void register_builtin_components(BasicRegistry<D>& registry);

/// The registry of dimension D filled once by register_builtin_components() (one per dimension).
template <int D = 2> const BasicRegistry<D>& builtin_registry();

/// Shorthands on builtin_registry<D>(); D from the participants (make_acceleration: any D).
template <int D>
std::unique_ptr<BasicCouplingScheme<D>> make_scheme(const CouplingOptions& options,
                                                    const BasicParticipants<D>& participants) {
  return builtin_registry<D>().make_scheme(options, participants);
}
template <int D>
std::unique_ptr<BasicCouplingScheme<D>> make_scheme(const CouplingOptions& options,
                                                    BasicFluidSolver<D>& fluid,
                                                    BasicStructureSolver<D>& structure) {
  BasicParticipants<D> p;
  p.fluid = &fluid;
  p.structure = &structure;
  return make_scheme(options, p);
}
std::unique_ptr<Acceleration> make_acceleration(std::string_view name,
                                                const CouplingOptions& options);
template <int D = 2>
std::unique_ptr<BasicPredictor<D>> make_predictor(std::string_view name,
                                                  const CouplingOptions& options) {
  return builtin_registry<D>().make_predictor(name, options);
}

extern template void register_builtin_components(Registry&);
extern template void register_builtin_components(Registry3&);
extern template const Registry& builtin_registry<2>();
extern template const Registry3& builtin_registry<3>();

} // namespace fsi::coupling
