#include "fsi_app/coupled_model.hpp"

#include "coupling/registry.hpp"
#include "fsi/core/error.hpp"
#include "fsi_app/output/text_file.hpp"

namespace fsi::app {

namespace {

coupling::CouplingOptions coupling_options(const CouplingSpec& c) {
  coupling::CouplingOptions o;
  o.scheme = c.scheme;
  o.predictor = c.predictor;
  o.acceleration = c.scheme == "bgs" ? c.acceleration : "none";
  o.tolerance = c.tolerance;
  o.max_iterations = c.max_iterations;
  o.omega = c.omega;
  o.reuse = c.reuse;
  o.stop_on_unconverged = c.stop_on_unconverged;
  o.substeps = c.substeps;
  return o;
}

const StructureSpec& coupled_structure(const Scene& scene) {
  if (scene.structures.size() != 1)
    fail_at(scene, scene.structures[1].line, "structures",
            "a coupled scene has one structure (this build couples one)");
  const StructureSpec& spec = scene.structures.front();
  if (spec.interface.empty())
    fail_at(scene, spec.line, "structures[0].interface",
            "a structure coupled to the fluid needs the boundary tags it is wetted on");
  return spec;
}

} // namespace

CoupledModel::CoupledModel(const Scene& scene) {
  const StructureSpec& spec = coupled_structure(scene);
  structure_ = std::make_unique<StructureModel>(scene, spec);
  fluid_ = std::make_unique<FluidModel>(scene, &structure_->structure().mesh(), spec.interface);
  fluid_adapter_ =
      std::make_unique<FluidAdapter>(fluid_->fluid(), fluid_->walls(), *fluid_->fe_interface());
  structure_adapter_ =
      std::make_unique<StructureAdapter>(structure_->structure(), *fluid_->fe_interface());
  const CouplingSpec c = scene.coupling.value_or(CouplingSpec{"css", "none", "aitken"});
  try {
    scheme_ = coupling::make_scheme(coupling_options(c), *fluid_adapter_, *structure_adapter_);
  } catch (const InputError& e) {
    fail_at(scene, c.line, "coupling", e.what());
  }
  scheme_->initialize(0.0);
}

void CoupledModel::advance(double time, double dt) {
  scheme_->advance(time, dt);
}

void CoupledModel::open_logs(const std::filesystem::path& out, bool resume) {
  const std::filesystem::path file = out / "coupling.csv";
  if (resume) // the header and one row per step before the checkpoint
    keep_lines(file, 1 + static_cast<std::size_t>(scheme_->summary().steps));
  step_log_ = std::make_unique<std::ofstream>(file, resume ? std::ios::app : std::ios::trunc);
  if (!*step_log_) throw RunError("output: " + file.string() + ": cannot create");
  if (!resume)
    *step_log_ << "step,time,dt,iterations,residual_initial,residual_final,omega,converged,"
                  "seconds_fluid,seconds_structure,seconds_coupler\n";
  scheme_->set_step_callback([log = step_log_.get()](const coupling::StepStats& s) {
    *log << s.step << ',' << s.t << ',' << s.dt << ',' << s.iterations << ',' << s.residual_initial
         << ',' << s.residual_final << ',';
    if (s.omega) *log << *s.omega;
    *log << ',' << (s.converged ? 1 : 0) << ',' << s.time_fluid << ',' << s.time_structure << ','
         << s.time_coupler << '\n';
    if (s.step % 1000 == 999) log->flush();
  });
}

void CoupledModel::flush_logs() {
  if (step_log_) step_log_->flush();
}

void CoupledModel::write_frame(FieldsFile& file, const std::vector<std::string>& fields) const {
  fluid_->write_frame(file, fields);
  structure_->write_frame(file, fields);
}

std::optional<double> CoupledModel::probe(const ProbeSpec& probe) const {
  if (auto v = structure_->probe(probe)) return v;
  return fluid_->probe(probe);
}

void CoupledModel::report(JsonObject& run) const {
  fluid_->report(run);
  structure_->report(run);
  const auto& s = scheme_->summary();
  JsonObject c;
  c.add("scheme", std::string(scheme_->name()))
      .add("predictor", scheme_->options().predictor)
      .add("acceleration", scheme_->options().acceleration)
      .add("steps", static_cast<long long>(s.steps))
      .add("iterations_mean", s.mean_iterations())
      .add("iterations_max", s.max_iterations)
      .add("unconverged_steps", static_cast<long long>(s.unconverged))
      .add("seconds_fluid", s.time_fluid)
      .add("seconds_structure", s.time_structure)
      .add("seconds_coupler", s.time_coupler)
      .add("newton_iterations_mean",
           s.steps ? static_cast<double>(structure_adapter_->newton_iterations()) /
                         static_cast<double>(s.steps)
                   : 0.0);
  run.add("coupling", c);
}

} // namespace fsi::app
