#pragma once
// Test helpers over a loaded scene: a probe by name, and the first probe's history through a
// coupled run.
#include "fsi_app/coupled_model.hpp"
#include "fsi_app/scene.hpp"

#include <catch2/catch.hpp>
#include <cmath>
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

} // namespace fsi::app::test
