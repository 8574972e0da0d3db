#include "coupling/options.hpp"

#include "coupling/registry.hpp"
#include "fsi/core/error.hpp"
#include "fsi/core/option_ranges.hpp"

#include <sstream>

namespace fsi::coupling {

template <int D>
void visit_options(CouplingOptions& o, const BasicRegistry<D>& r, OptionVisitor& v) {
  v.name("scheme", o.scheme, r.scheme_names(), "coupling scheme");
  v.name("predictor", o.predictor, r.predictor_names(),
         "first guess of the interface at t^{n+1} (eqs. 63-65)");
  v.name("acceleration", o.acceleration, r.acceleration_names(),
         "acceleration of the iterations of an implicit scheme (bgs); explicit schemes (css) "
         "have none");
  v.name("convergence", o.convergence, r.measure_names(),
         "convergence measure of the iterations (relative: eq. 69)");
  v.real("tolerance", o.tolerance, Range::positive(),
         "relative: norm(r^i) / norm(r^0) < tolerance (below 1, eq. 69); absolute: norm(r^i) < "
         "tolerance, m");
  v.integer("max_iterations", o.max_iterations, Range::closed(1, 100000),
            "evaluations per step before the step is accepted unconverged (counted)");
  v.real("omega", o.omega, Range::left_open(0.0, 2.0),
         "constant relaxation factor; initial factor of aitken and iqn-ils");
  v.integer("reuse", o.reuse, Range::closed(0, 1000),
            "iqn-ils: past time steps whose columns are reused");
  v.real("iqn_filter", o.iqn_filter, Range::right_open(0.0, 1.0),
         "iqn-ils QR2 filter: delete columns with orthogonal part < iqn_filter x norm");
  v.real("aitken_omega_max", o.aitken_omega_max, Range::closed(0.01, 100.0),
         "aitken clamp: abs(omega) <= aitken_omega_max");
  v.flag("converge_velocities", o.converge_velocities,
         "the iterations also measure the velocity residual");
  v.flag("stop_on_unconverged", o.stop_on_unconverged,
         "stop the run (RunError) at the first unconverged step");
  v.integer("substeps", o.substeps, Range::closed(1, 100000),
            "fluid sub-steps per coupling (structure) step");
}

namespace {

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : " ") + n;
  return out;
}

std::string text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

class Declarations final : public OptionVisitor {
public:
  std::vector<OptionDeclaration> out;
  void name(const std::string& key, std::string& value, const std::vector<std::string>& allowed,
            const std::string& doc) override {
    out.push_back({key, value, "one of: " + join(allowed), doc});
  }
  void real(const std::string& key, double& value, const Range& range,
            const std::string& doc) override {
    out.push_back({key, text(value), range.describe(), doc});
  }
  void integer(const std::string& key, int& value, const Range& range,
               const std::string& doc) override {
    out.push_back({key, text(value), range.describe(), doc});
  }
  void flag(const std::string& key, bool& value, const std::string& doc) override {
    out.push_back({key, value ? "true" : "false", "true, false", doc});
  }
};

} // namespace

template <int D>
std::vector<OptionDeclaration> option_declarations(const BasicRegistry<D>& registry) {
  CouplingOptions defaults;
  Declarations d;
  visit_options(defaults, registry, d);
  return d.out;
}

template <int D>
void validate_options(const CouplingOptions& options, const BasicRegistry<D>& registry) {
  CouplingOptions o = options; // the visitor takes fields by reference; nothing is changed
  RangeChecker v("coupling.");
  visit_options(o, registry, v);
  if (o.convergence == "relative" && !(o.tolerance < 1.0))
    throw InputError("coupling.tolerance: value " + text(o.tolerance) +
                     " is out of range: the relative measure needs a tolerance below 1");
}

#define FSI_COUPLING_OPTIONS(D)                                                                    \
  template void visit_options(CouplingOptions&, const BasicRegistry<D>&, OptionVisitor&);          \
  template std::vector<OptionDeclaration> option_declarations(const BasicRegistry<D>&);            \
  template void validate_options(const CouplingOptions&, const BasicRegistry<D>&);
FSI_COUPLING_OPTIONS(2)
FSI_COUPLING_OPTIONS(3)
#undef FSI_COUPLING_OPTIONS

} // namespace fsi::coupling
