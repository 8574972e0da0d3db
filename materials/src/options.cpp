#include "materials/material.hpp"

namespace fsi::materials {

void visit_options(MaterialOptions& o, OptionVisitor& v) {
  v.required("youngs_modulus", o.youngs_modulus, Range::positive(), "E, Pa");
  v.required("poisson_ratio", o.poisson_ratio, Range::open(-1.0, 0.5), "nu");
  // Issue 41: a denormal density (5e-324) made the mass matrix unfactorisable mid-run.
  v.required("density", o.density, Range::closed(1e-3, 1e6),
             "rho_s, kg/m^3 (a tiny or denormal density leaves the mass matrix unfactorisable)");
  v.choice("plane", o.plane,
           {{"strain", PlaneModel::plane_strain}, {"stress", PlaneModel::plane_stress}},
           "2D idealisation");
  v.choice("model", o.model,
           {{"saint_venant_kirchhoff", MaterialModel::saint_venant_kirchhoff},
            {"neo_hookean", MaterialModel::neo_hookean}},
           "strain energy: the paper's St. Venant-Kirchhoff (eq. 35), or compressible neo-Hookean "
           "(plane strain only), which cannot be crushed flat by a finite load "
           "(docs/structure_fem.md)");
}

} // namespace fsi::materials
