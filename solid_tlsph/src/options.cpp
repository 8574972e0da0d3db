// The solid's user options, each declared once (key, member, range, doc): the scene reader, the
// validator and the generated reference visit them. The material has its own (materials/).
#include "solid_tlsph/solid.hpp"

namespace fsi::tlsph {

void visit_options(TlsphOptions& o, OptionVisitor& v) {
  v.required("dp", o.dp, Range::positive(), "particle spacing dp_S, m");
  v.real("h_factor", o.h_factor, Range::closed(1.0, 2.0),
         "smoothing length h = h_factor dp (Wendland C2, support 2h)");
  v.choice("correction", o.gradient_correction,
           {{"linear", GradientCorrection::linear}, {"quadratic", GradientCorrection::quadratic}},
           "gradient correction: linear, the paper's B0 (eq. 14); quadratic, exact for bending "
           "fields at the surface too (docs/solid_tlsph.md)");
  v.real("hourglass", o.hourglass, Range::non_negative(),
         "hourglass control of the quadratic correction, in units of E (0: off; "
         "docs/solid_tlsph.md)");
  v.real("pair_damping", o.pair_damping, Range::non_negative(),
         "pairwise viscosity nu_d = pair_damping c_s h / 2 (0: off)");
  v.flag("interface_particles", o.interface_particles,
         "hand every particle to the coupling too: an SPH fluid takes the solid's particles as "
         "its boundary instead of points on the interface edges (EMPS ignores them)");
  v.real("mass_damping", o.mass_damping, Range::non_negative(),
         "mass-proportional damping a -= mass_damping v, 1/s (0: off)");
}

} // namespace fsi::tlsph
