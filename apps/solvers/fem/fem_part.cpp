#include "fem/fem_part.hpp"

#include "fsi/core/error.hpp"
#include "fsi_app/finite_guard.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace fsi::app::fem_plugin {

void FemCounters::add(const fem::StepReport& report, long fallbacks) {
  newton_iterations += report.iterations;
  newton_max = std::max(newton_max, report.iterations);
  newton_halvings += report.halvings;
  steps_with_halvings += report.halvings > 0 ? 1 : 0;
  if (report.substeps > 1) ++substepped_steps, substeps += report.substeps;
  roundoff_stops += report.roundoff_stops;
  guess_retries += report.guess_retries;
  ++steps;
  lu_fallbacks += fallbacks - lu_fallbacks_seen;
  lu_fallbacks_seen = fallbacks;
}

void FemCounters::write(StateArchive& archive, const std::string& name) const {
  const std::string prefix = "run/structures/" + name + "/";
  archive.put(prefix + "newton", std::vector<std::int64_t>{newton_iterations, steps, newton_max});
  archive.put(prefix + "halvings", std::vector<std::int64_t>{newton_halvings, steps_with_halvings,
                                                             substepped_steps, substeps});
  archive.put(prefix + "roundoff_stops", std::vector<std::int64_t>{roundoff_stops});
  archive.put(prefix + "guess_retries", std::vector<std::int64_t>{guess_retries});
  archive.put(prefix + "lu_fallbacks", std::vector<std::int64_t>{lu_fallbacks});
}

void FemCounters::read(const StateArchive& archive, const std::string& name) {
  const std::string prefix = "run/structures/" + name + "/";
  const auto& counts = archive.integers(prefix + "newton", 3);
  newton_iterations = counts[0], steps = counts[1], newton_max = static_cast<int>(counts[2]);
  if (archive.all_integers().count(prefix + "halvings")) { // absent before the safeguard
    const auto& h = archive.integers(prefix + "halvings", 4);
    newton_halvings = h[0], steps_with_halvings = h[1];
    substepped_steps = h[2], substeps = h[3];
  }
  if (archive.all_integers().count(prefix + "roundoff_stops")) // absent before the count
    roundoff_stops = archive.integers(prefix + "roundoff_stops", 1)[0];
  if (archive.all_integers().count(prefix + "guess_retries")) // absent before the retry
    guess_retries = archive.integers(prefix + "guess_retries", 1)[0];
  if (archive.all_integers().count(prefix + "lu_fallbacks")) // absent before the count
    lu_fallbacks = archive.integers(prefix + "lu_fallbacks", 1)[0];
}

void FemCounters::report(JsonObject& run, const std::string& name, std::size_t nodes,
                         std::size_t elements) const {
  JsonObject s;
  s.add("nodes", static_cast<long long>(nodes))
      .add("elements", static_cast<long long>(elements))
      .add("newton_iterations_mean",
           steps ? static_cast<double>(newton_iterations) / static_cast<double>(steps) : 0.0)
      .add("newton_iterations_max", newton_max)
      .add("newton_halvings", static_cast<long long>(newton_halvings))
      .add("steps_with_newton_halvings", static_cast<long long>(steps_with_halvings))
      .add("substepped_steps", static_cast<long long>(substepped_steps))
      .add("substeps", static_cast<long long>(substeps))
      .add("newton_roundoff_stops", static_cast<long long>(roundoff_stops))
      .add("newton_guess_retries", static_cast<long long>(guess_retries))
      .add("linear_solver_lu_fallbacks", static_cast<long long>(lu_fallbacks));
  run.add("structure_" + name, s);
}

template <class Family>
BasicFemPart<Family>::BasicFemPart(std::string name,
                                   std::unique_ptr<fem::BasicStructure<Family>> structure)
    : StructurePart(std::move(name)), structure_(std::move(structure)) {}

template <class Family> void BasicFemPart<Family>::advance(double /*time*/, double dt) {
  const fem::StepReport* step = nullptr;
  try { // the library's message has the step and time; the run names the structure (issue 41)
    step = &structure_->advance(dt);
  } catch (const RunError& e) {
    throw RunError("structure '" + name() + "': " + e.what());
  }
  counters_.add(*step, structure_->linear_solver_fallbacks());
}

template <class Family> std::optional<std::string> BasicFemPart<Family>::non_finite() const {
  constexpr int dim = Family::dim;
  const auto& u = structure_->displacement();
  const auto& v = structure_->velocity();
  const auto& X = structure_->mesh().X;
  for (std::size_t k = 0; k < X.size(); ++k) {
    const auto d = dim * static_cast<Eigen::Index>(k);
    const std::string what = "structure '" + name() + "' node " + std::to_string(k);
    const VecD<dim> x = X[k] + u.template segment<dim>(d), vk = v.template segment<dim>(d);
    std::optional<std::string> bad;
    if constexpr (dim == 2)
      bad = non_finite_point(what, x, vk);
    else
      bad = non_finite_point3(what, x, vk);
    if (bad) return bad;
  }
  return std::nullopt;
}

template <class Family> void BasicFemPart<Family>::report(JsonObject& run) const {
  counters_.report(run, name(), structure_->mesh().num_nodes(), structure_->mesh().num_elements());
}

template <class Family> void BasicFemPart<Family>::write_state(StateArchive& archive) const {
  structure_->write_state(archive, "structures/" + name() + "/");
  counters_.write(archive, name());
}

template <class Family> void BasicFemPart<Family>::read_state(const StateArchive& archive) {
  structure_->read_state(archive, "structures/" + name() + "/");
  counters_.read(archive, name());
}

template class BasicFemPart<fem::T6>;
template class BasicFemPart<fem::T10>;

} // namespace fsi::app::fem_plugin
