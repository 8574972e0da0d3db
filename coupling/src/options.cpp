#include "coupling/options.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "coupling/registry.hpp"
#include "fsi/core/error.hpp"

namespace fsi::coupling {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

struct NameSpec {
  const char* key;
  std::string CouplingOptions::*member;
  std::vector<std::string> (Registry::*names)() const;
  const char* doc;
};

struct NumberSpec {
  const char* key;
  double CouplingOptions::*real = nullptr; // exactly one of real, integer is set
  int CouplingOptions::*integer = nullptr;
  double lo, hi;
  bool lo_open, hi_open;
  const char* doc;

  double value(const CouplingOptions& o) const {
    return real ? o.*real : static_cast<double>(o.*integer);
  }
  bool admits(double v) const {
    if (std::isnan(v)) return false;
    const bool above = lo_open ? v > lo : v >= lo;
    const bool below = hi_open ? v < hi : v <= hi;
    return above && below;
  }
  std::string range() const {
    std::ostringstream s;
    s << (lo_open ? "(" : "[") << lo << ", ";
    if (std::isinf(hi))
      s << "inf";
    else
      s << hi;
    s << (hi_open ? ")" : "]");
    return s.str();
  }
};

struct FlagSpec {
  const char* key;
  bool CouplingOptions::*member;
  const char* doc;
};

const std::vector<NameSpec>& name_specs() {
  static const std::vector<NameSpec> specs{
      {"scheme", &CouplingOptions::scheme, &Registry::scheme_names, "coupling scheme"},
      {"predictor", &CouplingOptions::predictor, &Registry::predictor_names,
       "first guess of the interface at t^{n+1} (eqs. 63-65)"},
      {"acceleration", &CouplingOptions::acceleration, &Registry::acceleration_names,
       "acceleration of the BGS iterations"},
      {"convergence", &CouplingOptions::convergence, &Registry::measure_names,
       "convergence measure of the BGS iterations (relative: eq. 69)"},
  };
  return specs;
}

const std::vector<NumberSpec>& number_specs() {
  using O = CouplingOptions;
  static const std::vector<NumberSpec> specs{
      {"tolerance", &O::tolerance, nullptr, 0.0, inf, true, true,
       "relative: ||r^i||/||r^0|| < tolerance; absolute: ||r^i|| < tolerance [m]"},
      {"max_iterations", nullptr, &O::max_iterations, 1, 100000, false, false,
       "BGS evaluations per step before the step is accepted unconverged"},
      {"omega", &O::omega, nullptr, 0.0, 2.0, true, false,
       "constant relaxation factor; initial factor of aitken and iqn-ils"},
      {"reuse", nullptr, &O::reuse, 0, 1000, false, false,
       "iqn-ils: past time steps whose columns are reused"},
      {"iqn_filter", &O::iqn_filter, nullptr, 0.0, 1.0, false, true,
       "iqn-ils QR2 filter: delete columns with orthogonal part < iqn_filter x norm"},
      {"aitken_omega_max", &O::aitken_omega_max, nullptr, 0.01, 100.0, false, false,
       "aitken clamp |omega| <= aitken_omega_max"},
      {"substeps", nullptr, &O::substeps, 1, 100000, false, false,
       "fluid sub-steps per coupling (structure) step"},
  };
  return specs;
}

const std::vector<FlagSpec>& flag_specs() {
  static const std::vector<FlagSpec> specs{
      {"converge_velocities", &CouplingOptions::converge_velocities,
       "BGS also measures the velocity residual"},
      {"stop_on_unconverged", &CouplingOptions::stop_on_unconverged,
       "throw a RunError on the first unconverged step"},
  };
  return specs;
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : " ") + n;
  return out;
}

} // namespace

std::vector<OptionDeclaration> option_declarations(const Registry& registry) {
  const CouplingOptions defaults;
  std::vector<OptionDeclaration> out;
  for (const auto& s : name_specs())
    out.push_back({s.key, defaults.*s.member, "one of: " + join((registry.*s.names)()), s.doc});
  for (const auto& s : number_specs()) {
    std::ostringstream d;
    d << s.value(defaults);
    out.push_back({s.key, d.str(), s.range(), s.doc});
  }
  for (const auto& s : flag_specs())
    out.push_back({s.key, defaults.*s.member ? "true" : "false", "true, false", s.doc});
  return out;
}

void validate_options(const CouplingOptions& o, const Registry& registry) {
  for (const auto& s : name_specs()) {
    const std::vector<std::string> allowed = (registry.*s.names)();
    const std::string& value = o.*s.member;
    if (std::find(allowed.begin(), allowed.end(), value) != allowed.end()) continue;
    throw InputError(std::string("coupling.") + s.key + ": unknown name '" + value +
                     "' (allowed: " + join(allowed) + ")");
  }
  for (const auto& s : number_specs()) {
    const double v = s.value(o);
    if (s.admits(v)) continue;
    std::ostringstream e;
    e << "coupling." << s.key << ": value " << v << " is out of range " << s.range();
    throw InputError(e.str());
  }
}

} // namespace fsi::coupling
