#include "fsi_app/coupled_model.hpp"

#include "coupling/registry.hpp"
#include "fsi/core/error.hpp"
#include "fsi_app/output/interface_history.hpp"
#include "fsi_app/output/text_file.hpp"
#include "fsi_app/solver_plugin.hpp"

#include <algorithm>
#include <functional>

namespace fsi::app {

// The fluid adapter as the coupler sees it, keeping the last wall motion it was given: what
// interface.h5 records as the motion of the step. Decomposed: its loads are every rank's summed
// (the same on every rank, so every rank's scheme computes the same iterates), and `after`
// follows each advance (collective: the model's force columns).
template <int D> class BasicCoupledModel<D>::FluidTap final : public coupling::BasicFluidSolver<D> {
public:
  explicit FluidTap(coupling::BasicFluidSolver<D>& fluid) : fluid_(fluid) {}
  /// From now on every rank's loads summed after each advance. Before the first, the loads
  /// are the same on every rank (each built the same fluid and read the same checkpoint).
  void decompose(const Ranks& ranks, std::function<void()> after) {
    ranks_ = &ranks;
    after_ = std::move(after);
    loads_ = fluid_.interface_loads();
  }
  void initialize() override { fluid_.initialize(); }
  void set_interface_motion(const coupling::BasicInterfaceMotion<D>& m) override {
    motion_ = m;
    fluid_.set_interface_motion(m);
  }
  void advance(double t, double dt) override {
    fluid_.advance(t, dt);
    if (!ranks_) return;
    loads_ = fluid_.interface_loads(); // this rank's particles' (eqs. 52-59)
    sum_loads();
    after_();
  }
  const coupling::BasicInterfaceLoads<D>& interface_loads() const override {
    return ranks_ ? loads_ : fluid_.interface_loads();
  }
  void save_state() override { fluid_.save_state(); }
  void restore_state() override { fluid_.restore_state(); }
  std::optional<double> stable_dt() const override { return fluid_.stable_dt(); }
  void finalize() override { fluid_.finalize(); }
  void write_state(StateArchive& archive) const override { fluid_.write_state(archive); }
  void read_state(const StateArchive& archive) override { fluid_.read_state(archive); }
  const coupling::BasicInterfaceMotion<D>& motion() const { return motion_; }

private:
  /// Every rank's part of the loads summed (the fluid's ranks each hold their particles'), the
  /// same on every rank (Ranks::sum), in one message.
  void sum_loads() {
    buffer_.clear();
    for (const VecD<D>& f : loads_.f)
      for (int k = 0; k < D; ++k) buffer_.push_back(f[k]);
    ranks_->sum(buffer_);
    std::size_t i = 0;
    for (VecD<D>& f : loads_.f)
      for (int k = 0; k < D; ++k) f[k] = buffer_[i++];
  }

  coupling::BasicFluidSolver<D>& fluid_;
  coupling::BasicInterfaceMotion<D> motion_;
  const Ranks* ranks_ = nullptr;
  std::function<void()> after_;
  coupling::BasicInterfaceLoads<D> loads_;
  std::vector<double> buffer_;
};

namespace {

// The plug-in API of dimension D: the structure's interface and S, the fluid built on the
// interfaces (2-D also keeping the structures' areas free) and its F.
template <int D> const BasicInterfaceMesh<D>& interface_of(const StructurePart& s) {
  if constexpr (D == 2)
    return s.interface_mesh();
  else
    return s.interface_mesh3();
}
template <int D> coupling::BasicStructureSolver<D>& structure_solver(StructurePart& s) {
  if constexpr (D == 2)
    return s.coupling_solver();
  else
    return s.coupling_solver3();
}
template <int D> coupling::BasicFluidSolver<D>& fluid_solver(FluidPart& f) {
  if constexpr (D == 2)
    return f.coupling_solver();
  else
    return f.coupling_solver3();
}
template <int D>
std::unique_ptr<FluidPart> build_fluid(const Scene& scene,
                                       const std::vector<BasicInterfaceMesh<D>>& interfaces,
                                       const std::vector<Polygon>& solid, const Ranks& ranks) {
  const FluidPlugin& plugin = *find_fluid_plugin(scene.fluid->type);
  if constexpr (D == 2) {
    return plugin.build(scene, interfaces, solid, ranks);
  } else {
    if (!plugin.build3) // the scene reader refuses such a scene first
      fail_at(scene, scene.fluid->line, "fluid.type",
              scene.fluid->type + " has no 3-D coupling to structures");
    return plugin.build3(scene, interfaces, ranks);
  }
}

} // namespace

template <int D>
std::unique_ptr<BasicInterfaceHistory<D>> open_replay(const Scene& scene, std::size_t nodes) {
  const CouplingSpec c = scene.coupling.value_or(CouplingSpec{});
  const coupling::SchemeNeeds needs =
      coupling::builtin_registry<D>().scheme_needs(c.options.scheme);
  if (!needs.prescribed_motion && !needs.prescribed_loads) return nullptr;
  const bool motion = needs.prescribed_motion;
  auto replay = std::make_unique<BasicInterfaceHistory<D>>(motion ? c.motion : c.loads);
  if (replay->nodes() != nodes)
    fail_at(scene, c.line, motion ? "coupling.motion" : "coupling.loads",
            (motion ? c.motion : c.loads).string() + " records " + std::to_string(replay->nodes()) +
                " interface nodes, this interface has " + std::to_string(nodes));
  return replay;
}
template std::unique_ptr<InterfaceHistory> open_replay<2>(const Scene&, std::size_t);
template std::unique_ptr<InterfaceHistory3> open_replay<3>(const Scene&, std::size_t);

template <int D> BasicCoupledModel<D>::~BasicCoupledModel() = default;

template <int D> BasicCoupledModel<D>::BasicCoupledModel(const Scene& scene, const Ranks& ranks) {
  std::vector<BasicInterfaceMesh<D>> interfaces;
  std::vector<Polygon> solid;
  std::vector<coupling::BasicStructureSolver<D>*> members;
  for (std::size_t i = 0; i < scene.structures.size(); ++i) {
    const StructurePlugin& plugin = *find_structure_plugin(scene.structures[i].type);
    structures_.push_back(plugin.build(scene, i));
    interfaces.push_back(interface_of<D>(*structures_.back()));
    if constexpr (D == 2) {
      const auto area = structures_.back()->occupied_area();
      solid.insert(solid.end(), area.begin(), area.end());
    }
    members.push_back(&structure_solver<D>(*structures_.back()));
  }
  std::size_t nodes = 0;
  for (const auto& mesh : interfaces) {
    if constexpr (D == 3) // the group's numbering: the interfaces in scene order
      for (auto face : mesh.faces) {
        for (std::size_t& k : face) k += nodes;
        faces_.push_back(face);
      }
    nodes += mesh.node_count();
  }
  fluid_ = build_fluid<D>(scene, interfaces, solid, ranks);
  group_ = std::make_unique<coupling::BasicStructureGroup<D>>(std::move(members));
  root_ = std::make_unique<RootStructures<D>>(*group_);
  const CouplingSpec c = scene.coupling.value_or(CouplingSpec{});
  tap_ = std::make_unique<FluidTap>(fluid_solver<D>(*fluid_));
  record_ = c.record_interface;
  const auto& registry = coupling::builtin_registry<D>();
  needs_ = registry.scheme_needs(c.options.scheme);
  coupling::BasicParticipants<D> p;
  if (needs_.fluid) p.fluid = tap_.get();
  if (needs_.structure) p.structure = root_.get();
  replay_ = open_replay<D>(scene, nodes);
  if (replay_) {
    BasicInterfaceHistory<D>* h = replay_.get();
    if (needs_.prescribed_motion)
      p.prescribed_motion = [h](double t) { return h->motion_at(t); };
    else
      p.prescribed_loads = [h](double t) { return h->loads_at(t); };
  }
  try {
    scheme_ = registry.make_scheme(c.options, p);
  } catch (const InputError& e) {
    fail_at(scene, c.line, "coupling", e.what());
  }
  scheme_->initialize(0.0);
}

template <int D> std::optional<double> BasicCoupledModel<D>::stable_dt(double courant) const {
  std::optional<double> dt = fluid_->stable_dt(courant);
  std::optional<double> solid; // decomposed: rank 0's, whose structures are solved
  for (const auto& s : structures_)
    if (auto d = s->stable_dt(courant)) solid = solid ? std::min(*solid, *d) : *d;
  if (ranks_ && !structures_.empty()) {
    std::vector<double> shared{solid ? *solid : -1.0};
    ranks_->broadcast(shared);
    solid = shared[0] >= 0.0 ? std::optional(shared[0]) : std::nullopt;
  }
  if (solid) dt = dt ? std::min(*dt, *solid) : *solid;
  return dt;
}

template <int D> bool BasicCoupledModel<D>::decompose(const Ranks& ranks) {
  if (!fluid_->decompose(ranks)) return false;
  ranks_ = &ranks;
  root_->decompose(ranks);
  std::function<void()> forces = [] {}; // 2-D: coupling.csv's force columns
  if constexpr (D == 2) forces = [this] { forces_ = fluid_->force_parts(); }; // collective
  forces();
  tap_->decompose(ranks, forces);
  return true;
}

template <int D> void BasicCoupledModel<D>::gather_frame() {
  fluid_->gather_frame();
}

template <int D> void BasicCoupledModel<D>::advance(double time, double dt) {
  scheme_->advance(time, dt);
  // The motion the fluid used (one_way_structure: the structure's, there is no fluid).
  if (history_)
    history_->append(time + dt, needs_.fluid ? tap_->motion() : scheme_->interface_motion(),
                     scheme_->interface_loads());
}

template <int D>
void BasicCoupledModel<D>::open_logs(const std::filesystem::path& out, bool resume) {
  if (record_ && resume)
    throw InputError("coupling.record_interface: a restarted run cannot continue "
                     "interface.h5; run without --restart or without record_interface");
  if (record_) {
    history_ = std::make_unique<BasicInterfaceHistoryWriter<D>>(
        out / "interface.h5", scheme_->interface_motion().size(), faces_);
    history_->append(0.0, scheme_->interface_motion(), scheme_->interface_loads());
  }
  const std::filesystem::path file = out / "coupling.csv";
  if (resume) // the header and one row per step before the checkpoint
    keep_lines(file, 1 + static_cast<std::size_t>(scheme_->summary().steps));
  step_log_ = std::make_unique<std::ofstream>(file, resume ? std::ios::app : std::ios::trunc);
  if (!*step_log_) throw RunError("output: " + file.string() + ": cannot create");
  if (!resume) {
    *step_log_ << "step,time,dt,iterations,residual_initial,residual_final,omega,converged,"
                  "seconds_fluid,seconds_structure,seconds_coupler";
    if constexpr (D == 2)
      for (const auto& [name, f] : force_parts()) *step_log_ << ",fx_" << name << ",fy_" << name;
    else
      *step_log_ << ",fx_total,fy_total,fz_total";
    *step_log_ << '\n';
  }
  scheme_->set_step_callback([log = step_log_.get(), self = this](const coupling::StepStats& s) {
    *log << s.step << ',' << s.t << ',' << s.dt << ',' << s.iterations << ',' << s.residual_initial
         << ',' << s.residual_final << ',';
    if (s.omega) *log << *s.omega;
    *log << ',' << (s.converged ? 1 : 0) << ',' << s.time_fluid << ',' << s.time_structure << ','
         << s.time_coupler;
    self->write_forces(*log);
    *log << '\n';
    if (s.step % 1000 == 999) log->flush();
  });
}

// The fluid's force on the structures of the step's last iteration: 2-D (N/m) by the term that
// carries it (FluidPart::force_parts), 3-D (N) the sum of the loads the structures took.
template <int D> void BasicCoupledModel<D>::write_forces(std::ostream& log) const {
  if constexpr (D == 2) {
    for (const auto& [name, f] : force_parts()) log << ',' << f.x() << ',' << f.y();
  } else {
    Vec3 total = Vec3::Zero();
    for (const Vec3& f : scheme_->interface_loads().f) total += f;
    const auto precision = log.precision(17); // the sum of interface.h5's loads to round-off
    log << ',' << total.x() << ',' << total.y() << ',' << total.z();
    log.precision(precision);
  }
}

template <int D> void BasicCoupledModel<D>::flush_logs() {
  if (step_log_) step_log_->flush();
  if (history_) history_->flush();
}

template <int D> void BasicCoupledModel<D>::declare(FieldsFile& file) const {
  for (const auto& s : structures_) s->declare(file);
}

template <int D>
void BasicCoupledModel<D>::write_frame(FieldsFile& file,
                                       const std::vector<std::string>& fields) const {
  fluid_->write_frame(file, fields);
  for (const auto& s : structures_) s->write_frame(file, fields);
}

template <int D> std::optional<double> BasicCoupledModel<D>::probe(const ProbeSpec& probe) const {
  for (const auto& s : structures_)
    if (auto v = s->probe(probe)) return v;
  return fluid_->probe(probe);
}

template <int D> std::optional<std::string> BasicCoupledModel<D>::non_finite() const {
  if (auto what = fluid_->non_finite()) return what; // the same walls on every rank
  std::optional<std::string> what;
  if (!ranks_ || ranks_->rank() == 0) // decomposed: rank 0's, whose structures are solved
    for (const auto& st : structures_)
      if ((what = st->non_finite())) break;
  if (!ranks_ || structures_.empty()) return what;
  std::vector<double> found{what ? 1.0 : 0.0}; // every rank stops at the same step
  ranks_->broadcast(found);
  if (found[0] != 0.0 && !what) what = "a structure (solved on rank 0) is not finite";
  return what;
}

template <int D> std::vector<std::string> BasicCoupledModel<D>::take_notes() {
  std::vector<std::string> notes = fluid_->take_notes();
  for (const auto& st : structures_)
    for (auto& n : st->take_notes()) notes.push_back(std::move(n));
  return notes;
}

template <int D> void BasicCoupledModel<D>::report(JsonObject& run) const {
  fluid_->report(run);
  for (const auto& st : structures_) st->report(run);
  const auto& s = scheme_->summary();
  JsonObject c;
  c.add("scheme", std::string(scheme_->name()))
      .add("predictor", scheme_->options().predictor)
      .add("acceleration", scheme_->implicit() ? scheme_->options().acceleration : "none")
      .add("steps", static_cast<long long>(s.steps))
      .add("iterations_mean", s.mean_iterations())
      .add("iterations_max", s.max_iterations)
      .add("unconverged_steps", static_cast<long long>(s.unconverged))
      .add("seconds_fluid", s.time_fluid)
      .add("seconds_structure", s.time_structure)
      .add("seconds_coupler", s.time_coupler);
  run.add("coupling", c);
}

template class BasicCoupledModel<2>;
template class BasicCoupledModel<3>;

} // namespace fsi::app
