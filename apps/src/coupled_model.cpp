#include "fsi_app/coupled_model.hpp"

#include "coupling/registry.hpp"
#include "fsi/core/error.hpp"
#include "fsi_app/output/interface_history.hpp"
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

// The fluid adapter as the coupler sees it, keeping the last wall motion it was given: what
// interface.h5 records as the motion of the step.
class CoupledModel::FluidTap final : public coupling::FluidSolver {
public:
  explicit FluidTap(coupling::FluidSolver& fluid) : fluid_(fluid) {}
  void initialize() override { fluid_.initialize(); }
  void set_interface_motion(const coupling::InterfaceMotion& m) override {
    motion_ = m;
    fluid_.set_interface_motion(m);
  }
  void advance(double t, double dt) override { fluid_.advance(t, dt); }
  const coupling::InterfaceLoads& interface_loads() const override {
    return fluid_.interface_loads();
  }
  void save_state() override { fluid_.save_state(); }
  void restore_state() override { fluid_.restore_state(); }
  std::optional<double> stable_dt() const override { return fluid_.stable_dt(); }
  void finalize() override { fluid_.finalize(); }
  void write_state(StateArchive& archive) const override { fluid_.write_state(archive); }
  void read_state(const StateArchive& archive) override { fluid_.read_state(archive); }
  const coupling::InterfaceMotion& motion() const { return motion_; }

private:
  coupling::FluidSolver& fluid_;
  coupling::InterfaceMotion motion_;
};

CoupledModel::~CoupledModel() = default;

CoupledModel::CoupledModel(const Scene& scene) {
  const StructureSpec& spec = coupled_structure(scene);
  structure_ = std::make_unique<StructureModel>(scene, spec);
  fluid_ = std::make_unique<FluidModel>(scene, &structure_->structure().mesh(), spec.interface);
  fluid_adapter_ =
      std::make_unique<FluidAdapter>(fluid_->fluid(), fluid_->walls(), *fluid_->fe_interface());
  structure_adapter_ =
      std::make_unique<StructureAdapter>(structure_->structure(), *fluid_->fe_interface());
  const CouplingSpec c = scene.coupling.value_or(CouplingSpec{"css", "none", "aitken"});
  tap_ = std::make_unique<FluidTap>(*fluid_adapter_);
  record_ = c.record_interface;
  coupling::Participants p;
  if (c.scheme != "one_way_structure") p.fluid = tap_.get();
  if (c.scheme != "one_way_fluid") p.structure = structure_adapter_.get();
  if (c.scheme == "one_way_fluid" || c.scheme == "one_way_structure") {
    const bool motion = c.scheme == "one_way_fluid";
    replay_ = std::make_unique<InterfaceHistory>(motion ? c.motion : c.loads);
    const auto nodes = static_cast<std::size_t>(fluid_->fe_interface()->node_count());
    if (replay_->nodes() != nodes)
      fail_at(scene, c.line, motion ? "coupling.motion" : "coupling.loads",
              (motion ? c.motion : c.loads).string() + " records " +
                  std::to_string(replay_->nodes()) + " interface nodes, this interface has " +
                  std::to_string(nodes));
    InterfaceHistory* h = replay_.get();
    if (motion)
      p.prescribed_motion = [h](double t) { return h->motion_at(t); };
    else
      p.prescribed_loads = [h](double t) { return h->loads_at(t); };
  }
  try {
    scheme_ = coupling::make_scheme(coupling_options(c), p);
  } catch (const InputError& e) {
    fail_at(scene, c.line, "coupling", e.what());
  }
  scheme_->initialize(0.0);
}

void CoupledModel::advance(double time, double dt) {
  scheme_->advance(time, dt);
  // The motion the fluid used (one_way_structure: the structure's, there is no fluid).
  if (history_)
    history_->append(time + dt,
                     scheme_->name() == "one_way_structure" ? scheme_->interface_motion()
                                                            : tap_->motion(),
                     scheme_->interface_loads());
}

void CoupledModel::open_logs(const std::filesystem::path& out, bool resume) {
  if (record_ && resume)
    throw InputError("coupling.record_interface: a restarted run cannot continue "
                     "interface.h5; run without --restart or without record_interface");
  if (record_) {
    history_ = std::make_unique<InterfaceHistoryWriter>(out / "interface.h5",
                                                        scheme_->interface_motion().size());
    history_->append(0.0, scheme_->interface_motion(), scheme_->interface_loads());
  }
  const std::filesystem::path file = out / "coupling.csv";
  if (resume) // the header and one row per step before the checkpoint
    keep_lines(file, 1 + static_cast<std::size_t>(scheme_->summary().steps));
  step_log_ = std::make_unique<std::ofstream>(file, resume ? std::ios::app : std::ios::trunc);
  if (!*step_log_) throw RunError("output: " + file.string() + ": cannot create");
  if (!resume)
    *step_log_ << "step,time,dt,iterations,residual_initial,residual_final,omega,converged,"
                  "seconds_fluid,seconds_structure,seconds_coupler,fx_pressure,fy_pressure,"
                  "fx_repulsive,fy_repulsive,fx_viscous,fy_viscous\n";
  // The fluid's force on the structure (N/m) of the step's last iteration, by wall term (eq. 52).
  const emps::EmpsFluid* fluid = &fluid_->fluid();
  const int first = fluid_->fe_interface()->first_segment();
  const int last = first + fluid_->fe_interface()->segment_count();
  scheme_->set_step_callback(
      [log = step_log_.get(), fluid, first, last](const coupling::StepStats& s) {
        *log << s.step << ',' << s.t << ',' << s.dt << ',' << s.iterations << ','
             << s.residual_initial << ',' << s.residual_final << ',';
        if (s.omega) *log << *s.omega;
        *log << ',' << (s.converged ? 1 : 0) << ',' << s.time_fluid << ',' << s.time_structure
             << ',' << s.time_coupler;
        const emps::WallForceParts f = fluid->wall_force_parts(first, last);
        for (const Vec2& v : {f.pressure, f.repulsive, f.viscous})
          *log << ',' << v.x() << ',' << v.y();
        *log << '\n';
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
                   : 0.0)
      .add("newton_halvings", static_cast<long long>(structure_adapter_->newton_halvings()))
      .add("steps_with_newton_halvings",
           static_cast<long long>(structure_adapter_->steps_with_halvings()))
      .add("substepped_steps", static_cast<long long>(structure_adapter_->substepped_steps()))
      .add("substeps", static_cast<long long>(structure_adapter_->substeps()));
  run.add("coupling", c);
}

} // namespace fsi::app
