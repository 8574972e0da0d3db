#pragma once
// Test helpers over a loaded scene: a probe by name, the first probe's history through a
// coupled run, and a run continued from a checkpoint against the uninterrupted one.
#include "fsi_app/coupled_model.hpp"
#include "fsi_app/output/checkpoint_file.hpp"
#include "fsi_app/run.hpp"
#include "fsi_app/scene.hpp"
#include "fsi_process.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace fsi::app::test {

inline const ProbeSpec& named(const Scene& scene, const std::string& name) {
  const ProbeSpec* found = nullptr;
  for (const auto& p : scene.output.probes)
    if (p.name == name) found = &p;
  REQUIRE(found != nullptr);
  return *found;
}

/// The scene's first probe after every `every` of `steps` coupled steps at the scene's fixed dt.
inline std::vector<double> first_probe_history(const Scene& scene, int steps, int every) {
  CoupledModel model(scene);
  const double dt = *scene.time.dt;
  std::vector<double> out;
  for (int k = 0; k < steps; ++k) {
    model.advance(k * dt, dt);
    if ((k + 1) % every == 0) out.push_back(*model.probe(scene.output.probes.front()));
  }
  return out;
}

/// The tiny obstacle's corner (tests/apps/data/tiny_coupled*.yaml: the first probe, dt = 2e-5 s)
/// at t = 0.01 .. 0.06 s, under EMPS + FEM (CSS) and under `file` with `overrides`; the second
/// follows the first within `bound` (relative) at 0.02 .. 0.06 s, both pushed in +x.
inline void check_tiny_obstacle_follows(const std::string& file,
                                        const std::vector<std::string>& overrides, double bound) {
  const auto reference = first_probe_history(
      load_scene(FSI_TEST_DATA "/tiny_coupled.yaml", {"coupling.scheme=css", "time.end=0.06"}),
      3000, 500);
  const auto other = first_probe_history(load_scene(file, overrides), 3000, 500);
  REQUIRE(reference.size() == 6);
  REQUIRE(other.size() == 6);
  for (std::size_t i = 1; i < reference.size(); ++i) {
    INFO("t = " << 0.01 * static_cast<double>(i + 1) << " s: emps + fem " << reference[i] << ", "
                << file << " " << other[i]);
    CHECK(reference[i] > 1e-3); // the water pushes the obstacle in +x
    CHECK(other[i] > 1e-3);
    CHECK(std::abs(other[i] - reference[i]) < bound * reference[i]);
  }
}

/// Runs `scene` (which writes checkpoints every `every` steps) whole in `dir`/whole, then again
/// from its checkpoint at step `every` in a copy; probes.csv and the last checkpoint (at `last`
/// steps) must be bitwise equal (wall-clock statistics aside), and the checkpoint must hold more
/// than `values` reals.
inline void check_restart_bitwise(const Scene& scene, const std::filesystem::path& dir, long every,
                                  long last, std::size_t values) {
  namespace fs = std::filesystem;
  const auto checkpoint = [](long step) {
    std::ostringstream name;
    name << "checkpoint_" << std::setw(9) << std::setfill('0') << step << ".h5";
    return name.str();
  };
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ostringstream log;
  {
    auto models = build_models(scene);
    RunOptions o;
    o.out = dir / "whole";
    o.log = &log;
    run_scene(scene, models, o);
  }
  fs::copy(dir / "whole", dir / "continued");
  {
    auto models = build_models(scene);
    RunOptions o;
    o.out = dir / "continued";
    o.log = &log;
    o.restart = dir / "continued" / checkpoint(every);
    run_scene(scene, models, o);
  }
  CHECK(fsi_test::slurp(dir / "whole" / "probes.csv") ==
        fsi_test::slurp(dir / "continued" / "probes.csv"));
  const StateArchive a = read_checkpoint(dir / "whole" / checkpoint(last));
  const StateArchive b = read_checkpoint(dir / "continued" / checkpoint(last));
  REQUIRE(a.all_reals().size() == b.all_reals().size());
  std::size_t compared = 0;
  for (const auto& [key, x] : a.all_reals()) {
    if (key.ends_with("seconds")) continue; // wall-clock statistics, not state
    INFO(key);
    const auto& y = b.reals(key);
    REQUIRE(x.size() == y.size());
    CHECK(std::memcmp(x.data(), y.data(), x.size() * sizeof(double)) == 0);
    compared += x.size();
  }
  CHECK(a.all_integers() == b.all_integers());
  CHECK(compared > values);
}

} // namespace fsi::app::test
