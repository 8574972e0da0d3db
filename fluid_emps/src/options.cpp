#include "fluid_emps/options.hpp"

#include "particles/fluid_keys.hpp"

namespace fsi::emps {

namespace {

void visit_options(WallPndOptions& o, OptionVisitor& v) {
  v.choice("wall_density", o.density,
           {{"added", WallDensity::added}, {"scaled", WallDensity::scaled}},
           "wall part of pnd: added, n_i + z(r) as eq. 20; scaled, n_i + z max(1, n_i / (n0 - z)): "
           "the virtual particles compressed like the fluid next to them (equal to eq. 20 at rest "
           "and in expansion)");
}

void visit_options(MirrorOptions& o, OptionVisitor& v) {
  v.choice("wall_condition", o.condition,
           {{"no_slip", WallCondition::no_slip}, {"slip", WallCondition::slip}},
           "viscous wall condition (eq. 24)");
  v.choice("wall_pressure", o.pressure,
           {{"own", WallPressure::own}, {"neighbours", WallPressure::neighbours}},
           "p_i' of eqs. 25-26: own, p_i (eq. 26); neighbours, at a free-surface particle within "
           "r_e of a wall its neighbours' mean pressure, sum p_j w_ij / sum w_ij");
  v.flag("mirror_same_side", o.same_side,
         "the mirror sums (eqs. 24-26) over the neighbours of the mirror point on the particle's "
         "side of its wall only (false: all within r_e, as in the paper, which across a wall "
         "thinner than about 2 r_e reflects the fluid on the far side into the particle's side)");
  v.real("wall_approach_viscosity", o.approach_viscosity, Range::non_negative(),
         "alpha of the closing-pair viscosity alpha c l0 between a particle and the mirror "
         "images of its neighbours closing in across a wall (a wall force; 0 = off)");
}

void visit_options(WallContactOptions& o, OptionVisitor& v) {
  v.real("alpha_rep", o.alpha_rep, Range::non_negative(), "repulsive coefficient of eq. 27, N/m^3");
  v.choice(
      "wall_contact", o.model,
      {{"paper", WallContact::paper},
       {"damped", WallContact::damped},
       {"viscous", WallContact::viscous}},
      "particle-wall contact: paper, the repulsive term of eq. 27 alone; damped, eq. 27 plus a "
      "damper on the wall-normal approach velocity within l0 of a wall (rate wall_damping "
      "c/l0 (1 - r/l0), a wall force); viscous, eq. 27 plus the closing-pair viscosity "
      "wall_viscosity c l0 on pairs with a particle within r_e of a wall");
  v.real("wall_damping", o.damping, Range::non_negative(),
         "wall_contact damped: damping rate in units of c / l0");
  v.real("wall_viscosity", o.viscosity, Range::non_negative(),
         "wall_contact viscous: alpha of the near-wall closing-pair viscosity");
}

void visit_options(WallOptions& o, OptionVisitor& v) {
  v.flag("corner_faces", o.corner_faces,
         "at concave wall corners also apply the nearest other face (its z, mirror terms and "
         "repulsion, the doubly counted quadrant once); false: the nearest wall only, eq. 18");
  v.flag("convex_corners", o.convex_corners,
         "at convex wall corners (3-D: convex edges and corners) count the solid's own virtual "
         "lattice in pnd and in the wall pressure term (eqs. 20 and 25 assume a half-plane "
         "there; false: as in the paper)");
  visit_options(o.pnd, v);
  visit_options(o.mirror, v);
  visit_options(o.contact, v);
  v.real("wall_gap_courant", o.gap_courant, Range::closed(0.0, 1.0),
         "C_gap: a step closes at most C_gap of a particle's gap r to a wall it approaches, dt <= "
         "C_gap r / (-(v - v_wall) . n) (keeps fast splashes from stepping through a wall that "
         "eq. 27 would stop; 0 = off)");
}

} // namespace

template <int D> void apply_wall_preset(BasicFluidOptions<D>& o, WallModel model) {
  const double alpha_rep = o.wall.contact.alpha_rep;
  o.wall = WallOptions{}; // the paper's terms
  o.wall.model = model;
  o.wall.contact.alpha_rep = alpha_rep;
  o.artificial_viscosity = 0.0;
  if (model == WallModel::paper) return;
  o.wall.pnd.density = WallDensity::scaled;
  o.wall.mirror.same_side = true;
  o.wall.mirror.approach_viscosity = 0.5;
  o.wall.gap_courant = 0.5;
  o.artificial_viscosity = 0.2;
}

template <int D> void visit_options(BasicFluidOptions<D>& o, OptionVisitor& v) {
  particles::visit_fluid_keys(o.density, o.viscosity, o.l0, o.sound_speed, o.damping_time, v);
  v.real("re_over_l0", o.re_over_l0, Range::closed(2.0, 5.0), "effective radius r_e / l0");
  v.real("beta", o.beta, Range::left_open(0.0, 1.5), "free-surface threshold, eq. 17");
  const WallModel before = o.wall.model;
  v.choice("wall_model", o.wall.model,
           {{"paper", WallModel::paper}, {"default", WallModel::standard}},
           "the wall model's preset: paper, Mitsume 2023 as printed (eqs. 18-27, with the corner "
           "faces and convex corners below); default, the wall of every shipped EMPS scene "
           "(docs/fluid_emps.md, \"The wall model\"): the paper's plus wall_density scaled, "
           "mirror_same_side, wall_approach_viscosity 0.5, wall_gap_courant "
           "0.5 and artificial_viscosity 0.2. The wall keys below and "
           "artificial_viscosity are expert overrides of one term each, applied after the preset");
  if (o.wall.model != before) apply_wall_preset(o, o.wall.model);
  v.real("artificial_viscosity", o.artificial_viscosity, Range::non_negative(),
         "alpha: closing particle pairs feel a viscosity alpha c l0 along their line of centres "
         "(damps acoustic noise; not in the paper, 0 = off)");
  visit_options(o.wall, v);
}

template void apply_wall_preset<2>(FluidOptions&, WallModel);
template void apply_wall_preset<3>(FluidOptions3&, WallModel);
template void visit_options<2>(FluidOptions&, OptionVisitor&);
template void visit_options<3>(FluidOptions3&, OptionVisitor&);

} // namespace fsi::emps
