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
  OptionReader reader(s);
  emps::visit_options(f.options, reader);
  for (auto& region :
       s.list("regions", "areas filled with particles at spacing l0, each on its own "
                         "lattice from its lower-left corner (l0/2 from its edges)"))
    f.regions.push_back(read_region(region));
  if (!doc && f.regions.empty()) s.fail("regions", "at least one region is required");
  if (auto d = s.block("domain", "particles leaving this box are removed and counted")) {
    Vec2& lo = f.options.domain_min;
    Vec2& hi = f.options.domain_max;
    lo = d->vec2("min", "lower-left corner, m");
    hi = d->vec2("max", "upper-right corner, m");
    if (!doc && (hi.x() <= lo.x() || hi.y() <= lo.y()))
      d->fail("max", "must lie above and right of min");
    f.domain_given = true;
    d->finish();
  }
  if (!doc) {
    for (std::size_t i = 0; i < f.regions.size(); ++i) {
      Vec2 lo = f.regions[i][0], hi = f.regions[i][0];
      for (const auto& p : f.regions[i]) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
      const Vec2 size = hi - lo;
      if (f.options.l0 > size.minCoeff()) {
        std::ostringstream msg;
        msg << "particle spacing " << f.options.l0 << " m is larger than fluid region " << i << " ("
            << size.x() << " x " << size.y() << " m)";
        s.fail("l0", msg.str());
      }
    }
  }
  return spec;
}

} // namespace fsi::app::emps_plugin
