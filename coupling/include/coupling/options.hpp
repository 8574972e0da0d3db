#pragma once
// Coupling options: a plain struct filled by the config layer (no YAML here). Defaults are the
// member initialisers; keys, allowed ranges or names and one-line docs are declared once, in
// visit_options() (options.cpp), which the scene reader, validate_options() and
// option_declarations() all go through.
#include <string>
#include <vector>

#include "fsi/core/options.hpp"

namespace fsi::coupling {

template <int D> class BasicRegistry;

struct CouplingOptions {
  /// Scheme by registry name: "css", "bgs", "one_way_fluid", "one_way_structure".
  std::string scheme = "css";
  /// Interface predictor by name: "none" (keep x^n, v^n, a^n) or "second_order" (eqs. 63-65).
  std::string predictor = "none";
  /// Acceleration of iterative schemes (bgs) by name: "none", "constant", "aitken", "iqn-ils".
  /// Explicit schemes (css) have none, whatever this says.
  std::string acceleration = "aitken";
  /// BGS convergence measure by name: "relative" (eq. 69) or "absolute".
  std::string convergence = "relative";
  /// (0, inf): relative measure: ||r^i|| / ||r^0|| < tolerance; absolute: ||r^i|| < tolerance [m].
  double tolerance = 1e-4;
  /// [1, 100000]: BGS iterations (F + S evaluations) per step before giving up.
  int max_iterations = 200;
  /// (0, 2]: constant relaxation factor; initial factor of aitken and iqn-ils.
  double omega = 0.5;
  /// [0, 1000]: iqn-ils reuses the columns of this many past time steps.
  int reuse = 8;
  /// [0, 1): iqn-ils QR2 filter: a column whose part orthogonal to the newer columns is below
  /// iqn_filter times its own norm is deleted.
  double iqn_filter = 1e-2;
  /// [0.01, 100]: aitken factor clamp, |omega| <= aitken_omega_max.
  double aitken_omega_max = 2.0;
  /// BGS also requires the velocity residual to satisfy the measure (positions always do).
  bool converge_velocities = false;
  /// Throw fsi::RunError on the first step that does not converge within max_iterations.
  bool stop_on_unconverged = false;
  /// [1, 100000]: fluid sub-steps per coupling (structure) step.
  int substeps = 1;
};

/// Calls `visitor` once per CouplingOptions field, in declaration order, with the field itself:
/// the one declaration of every coupling option (names list the registry's entries).
template <int D>
void visit_options(CouplingOptions& options, const BasicRegistry<D>& registry,
                   OptionVisitor& visitor);

/// One option as declared: scene key coupling.<key>, default, allowed range, one-line doc.
struct OptionDeclaration {
  std::string key, default_value, range, doc;
};

/// Every CouplingOptions field in declaration order; name ranges list the registry's names.
template <int D>
std::vector<OptionDeclaration> option_declarations(const BasicRegistry<D>& registry);

/// Throws fsi::InputError (`coupling.KEY: value V is out of range R` or `unknown name`) for the
/// first invalid field. Component names are checked against `registry`.
template <int D>
void validate_options(const CouplingOptions& options, const BasicRegistry<D>& registry);

// Instantiated for D = 2 and 3 in options.cpp.
extern template void visit_options(CouplingOptions&, const BasicRegistry<2>&, OptionVisitor&);
extern template void visit_options(CouplingOptions&, const BasicRegistry<3>&, OptionVisitor&);
extern template std::vector<OptionDeclaration> option_declarations(const BasicRegistry<2>&);
extern template std::vector<OptionDeclaration> option_declarations(const BasicRegistry<3>&);
extern template void validate_options(const CouplingOptions&, const BasicRegistry<2>&);
extern template void validate_options(const CouplingOptions&, const BasicRegistry<3>&);

} // namespace fsi::coupling
