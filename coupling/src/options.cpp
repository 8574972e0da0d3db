#include "coupling/options.hpp"

#include <cmath>
#include <sstream>

#include "coupling/registry.hpp"
#include "fsi/core/error.hpp"

namespace fsi::coupling {

namespace {

[[noreturn]] void out_of_range(const char* key, double value, const char* range) {
  std::ostringstream s;
  s << "coupling." << key << ": value " << value << " is out of range " << range;
  throw InputError(s.str());
}

void check_name(const char* key, const std::string& value, bool known,
                const std::vector<std::string>& allowed) {
  if (known) return;
  std::ostringstream s;
  s << "coupling." << key << ": unknown name '" << value << "' (allowed:";
  for (const auto& a : allowed) s << " " << a;
  s << ")";
  throw InputError(s.str());
}

} // namespace

void validate_options(const CouplingOptions& o, const Registry& r) {
  check_name("scheme", o.scheme, r.has_scheme(o.scheme), r.scheme_names());
  check_name("predictor", o.predictor, r.has_predictor(o.predictor), r.predictor_names());
  check_name("acceleration", o.acceleration, r.has_acceleration(o.acceleration),
             r.acceleration_names());
  check_name("convergence", o.convergence, r.has_measure(o.convergence), r.measure_names());
  if (!(o.tolerance > 0.0) || !std::isfinite(o.tolerance))
    out_of_range("tolerance", o.tolerance, "(0, inf)");
  if (o.max_iterations < 1 || o.max_iterations > 100000)
    out_of_range("max_iterations", o.max_iterations, "[1, 100000]");
  if (!(o.omega > 0.0 && o.omega <= 2.0)) out_of_range("omega", o.omega, "(0, 2]");
  if (o.reuse < 0 || o.reuse > 1000) out_of_range("reuse", o.reuse, "[0, 1000]");
  if (!(o.iqn_filter >= 0.0 && o.iqn_filter < 1.0))
    out_of_range("iqn_filter", o.iqn_filter, "[0, 1)");
  if (!(o.aitken_omega_max >= 0.01 && o.aitken_omega_max <= 100.0))
    out_of_range("aitken_omega_max", o.aitken_omega_max, "[0.01, 100]");
  if (o.substeps < 1 || o.substeps > 100000) out_of_range("substeps", o.substeps, "[1, 100000]");
}

} // namespace fsi::coupling
