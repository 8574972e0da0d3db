// The EMPS fluid's scene keys, each declared once where it is read.
#include "emps/emps_spec.hpp"

#include <sstream>

namespace fsi::app::emps_plugin {

namespace {

std::vector<Vec2> read_region(Section s) {
  const bool doc = s.context().documenting();
  std::vector<Vec2> polygon;
  if (doc || s.has("polygon")) polygon = s.points("polygon", 3, "closed polygon to fill, m");
  if (doc || !s.has("polygon")) {
    const Vec2 lo = s.vec2("min", "lower-left corner of a rectangle to fill, m");
    const Vec2 hi = s.vec2("max", "upper-right corner, m");
    if (!doc && (hi.x() <= lo.x() || hi.y() <= lo.y()))
      s.fail("max", "must lie above and right of min");
    if (!doc) polygon = {lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}};
  }
  s.finish();
  return polygon;
}

} // namespace

std::shared_ptr<const SolverSpec> read_fluid(Section& s) {
  auto spec = std::make_shared<FluidSpec>();
  FluidSpec& f = *spec;
  const bool doc = s.context().documenting();
  f.density = s.real("density", Range::positive(), "rho, kg/m^3");
  f.viscosity = s.real("viscosity", 0.0, Range::non_negative(),
                       "kinematic viscosity nu, m^2/s; 0 skips the viscous loop");
  f.l0 = s.real("l0", Range::positive(), "initial particle spacing, m");
  f.re_over_l0 = s.real("re_over_l0", 3.1, Range::closed(2.0, 5.0), "effective radius r_e / l0");
  f.sound_speed = s.real("sound_speed", Range::positive(), "c of eq. 15, m/s");
  f.beta = s.real("beta", 1.0, Range::left_open(0.0, 1.5), "free-surface threshold, eq. 17");
  f.alpha_rep =
      s.real("alpha_rep", 0.0, Range::non_negative(), "repulsive coefficient of eq. 27, N/m^3");
  f.wall_condition =
      s.choice("wall_condition", {"no_slip", "slip"}, "no_slip", "viscous wall condition (eq. 24)");
  f.wall_contact = s.choice(
      "wall_contact", {"paper", "damped", "viscous"}, "paper",
      "particle-wall contact: paper, the repulsive term of eq. 27 alone; damped, eq. 27 plus a "
      "damper on the wall-normal approach velocity within l0 of a wall (rate wall_damping c/l0 "
      "(1 - r/l0), a wall force); viscous, eq. 27 plus the closing-pair viscosity "
      "wall_viscosity c l0 on pairs with a particle within r_e of a wall");
  f.wall_damping = s.real("wall_damping", 1.0, Range::non_negative(),
                          "wall_contact damped: damping rate in units of c / l0");
  f.wall_viscosity = s.real("wall_viscosity", 0.05, Range::non_negative(),
                            "wall_contact viscous: alpha of the near-wall closing-pair viscosity");
  f.artificial_viscosity = s.real(
      "artificial_viscosity", 0.0, Range::non_negative(),
      "alpha: closing particle pairs feel a viscosity alpha c l0 along their line of centres "
      "(damps acoustic noise; not in the paper, 0 = off)");
  f.wall_density = s.choice(
      "wall_density", {"added", "scaled"}, "added",
      "wall part of pnd: added, n_i + z(r) as eq. 20; scaled, n_i + z max(1, n_i / (n0 - z)): "
      "the virtual particles compressed like the fluid next to them (equal to "
      "eq. 20 at rest and in expansion)");
  f.corner_faces = s.boolean(
      "corner_faces", true,
      "at concave wall corners also apply the nearest other face (its z, mirror terms and "
      "repulsion, the doubly counted quadrant once); false: the nearest wall only, eq. 18");
  f.convex_corners = s.boolean(
      "convex_corners", true,
      "at convex wall corners count the solid's own virtual lattice in pnd and in the wall "
      "pressure term (eqs. 20 and 25 assume a half-plane there; false: as in the paper)");
  f.damping_time =
      s.real("damping_time", 0.0, Range::non_negative(),
             "initial damping phase T_d: velocities damped at a rate 20/T_d (1 - t/T_d) "
             "(quiet hydrostatic starts), s");
  for (auto& region :
       s.list("regions", "areas filled with particles at spacing l0, each on its own "
                         "lattice from its lower-left corner (l0/2 from its edges)"))
    f.regions.push_back(read_region(region));
  if (!doc && f.regions.empty()) s.fail("regions", "at least one region is required");
  if (auto d = s.block("domain", "particles leaving this box are removed and counted")) {
    f.domain_min = d->vec2("min", "lower-left corner, m");
    f.domain_max = d->vec2("max", "upper-right corner, m");
    if (!doc && (f.domain_max.x() <= f.domain_min.x() || f.domain_max.y() <= f.domain_min.y()))
      d->fail("max", "must lie above and right of min");
    d->finish();
  }
  if (!doc) {
    for (std::size_t i = 0; i < f.regions.size(); ++i) {
      Vec2 lo = f.regions[i][0], hi = f.regions[i][0];
      for (const auto& p : f.regions[i]) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
      const Vec2 size = hi - lo;
      if (f.l0 > size.minCoeff()) {
        std::ostringstream msg;
        msg << "particle spacing " << f.l0 << " m is larger than fluid region " << i << " ("
            << size.x() << " x " << size.y() << " m)";
        s.fail("l0", msg.str());
      }
    }
  }
  return spec;
}

} // namespace fsi::app::emps_plugin
