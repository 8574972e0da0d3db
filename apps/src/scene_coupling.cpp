// The coupling block of a scene file: scheme, acceleration, recording and one-way replay.
#include "scene_blocks.hpp"

#include "coupling/registry.hpp"
#include "fsi/core/error.hpp"
#include "fsi/core/format.hpp"
#include "fsi_app/output/interface_history.hpp"

#include <filesystem>
#include <string>
#include <utility>

namespace fsi::app {

namespace {

// The first and last time of a recorded interface.h5 of the scene's dimension.
std::pair<double, double> recorded_times(const std::filesystem::path& path, int dimension) {
  if (dimension == 3) {
    const InterfaceHistory3 h(path);
    return {h.first_time(), h.last_time()};
  }
  const InterfaceHistory h(path);
  return {h.first_time(), h.last_time()};
}

// Recording and one-way replay: the replayed file must cover every step of the run.
void read_one_way(Section& s, const TimeSpec& time, CouplingSpec& c) {
  const bool doc = s.context().documenting();
  c.record_interface = s.boolean("record_interface", false,
                                 "write DIR/interface.h5: per step the interface motion the fluid "
                                 "used and the loads the structure took");
  const coupling::SchemeNeeds needs =
      doc ? coupling::SchemeNeeds{} : coupling::builtin_registry().scheme_needs(c.options.scheme);
  auto recorded = [&](const std::string& key, bool needed, const std::string& what) {
    if (!doc && !needed && s.has(key))
      s.fail(key, "scheme '" + c.options.scheme + "' replays no recorded " + what);
    if (!doc && !needed) return std::filesystem::path();
    const auto path = s.file(key, "interface.h5 of a recorded run, its " + what +
                                      " interpolated linearly in time (schemes that replay it)");
    if (doc) return path;
    const double step = time.dt.value_or(time.end);
    const double last = std::ceil(time.end / step - 1e-9) * step; // the run's last step end
    std::ostringstream problem;
    try {
      const auto [first, end] = recorded_times(path, s.context().dimension);
      if (first > 0.0 || end < last * (1.0 - 1e-12))
        problem << path.string() << ": records t = " << first << " .. " << end
                << " s, the run needs 0 .. " << last << " s";
    } catch (const InputError& e) {
      problem << e.what();
    }
    if (!problem.str().empty()) s.fail(key, problem.str());
    return path;
  };
  c.motion = recorded("motion", needs.prescribed_motion, "interface motion");
  c.loads = recorded("loads", needs.prescribed_loads, "interface loads");
}

} // namespace

CouplingSpec read_coupling(Section s, const TimeSpec& time) {
  CouplingSpec c;
  c.line = s.line();
  OptionReader reader(s);
  coupling::visit_options(c.options, coupling::builtin_registry(), reader);
  read_one_way(s, time, c);
  if (!s.context().documenting()) try { // the rules beyond each key's range
      coupling::validate_options(c.options, coupling::builtin_registry());
    } catch (const InputError& e) {
      s.fail("", e.what());
    }
  s.finish();
  return c;
}

} // namespace fsi::app
