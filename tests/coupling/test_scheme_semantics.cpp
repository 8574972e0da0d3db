// Scheme mechanics with counting / recording stand-in solvers: call sequence and save/restore
// (BGS, CSS), sub-cycling, one-way modes, statistics, registry and option checks.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "coupling/acceleration_constant.hpp"
#include "coupling/predictor_second_order.hpp"
#include "coupling/registry.hpp"
#include "fsi/core/error.hpp"

using fsi::Vec2;
using namespace fsi::coupling;

namespace {

using Calls = std::vector<std::string>;

// What both counting stand-ins share: every call recorded as "WHO.call", the number of advances
// since initialize (state_at_advance: its value at each advance), and save/restore of that count
// with the solver's own value (F: its loads, S: its position).
template <class Solver, class Value> class Counting : public Solver {
public:
  Counting(Calls& calls, std::string who) : calls_(calls), who_(std::move(who)) {}
  void save_state() override {
    record("save");
    saved_count_ = count_;
    saved_ = value_;
  }
  void restore_state() override {
    record("restore");
    count_ = saved_count_;
    value_ = saved_;
  }
  void finalize() override { record("finalize"); }
  std::vector<int> state_at_advance;

protected:
  void record(const std::string& call) { calls_.push_back(who_ + "." + call); }
  /// Records the advance and counts it.
  void count_advance() {
    record("advance");
    state_at_advance.push_back(count_);
    ++count_;
  }
  Value value_{};

private:
  Calls& calls_;
  std::string who_;
  int count_ = 0, saved_count_ = -1;
  Value saved_{};
};

// F: load = 0.5 x_in + 1 (x-component); state = number of advances since initialize.
class CountingFluid : public Counting<FluidSolver, InterfaceLoads> {
public:
  explicit CountingFluid(Calls& calls) : Counting(calls, "F") {}
  void initialize() override {
    record("init");
    value_ = InterfaceLoads::zeros(1);
  }
  void set_interface_motion(const InterfaceMotion& m) override {
    record("set");
    x_in_ = m.x[0].x();
  }
  void advance(double, double) override {
    count_advance();
    value_.f[0] = Vec2(0.5 * x_in_ + 1.0, 0.0);
  }
  const InterfaceLoads& interface_loads() const override { return value_; }

private:
  double x_in_ = 0.0;
};

// S: x^{n+1} = x^n + load (x-component); count = number of advances since initialize.
class CountingStructure : public Counting<StructureSolver, double> {
public:
  explicit CountingStructure(Calls& calls) : Counting(calls, "S") {}
  void initialize() override { record("init"); }
  void set_interface_loads(const InterfaceLoads& l) override {
    record("set");
    load_ = l.f[0].x();
  }
  void advance(double, double) override {
    count_advance();
    value_ += load_;
  }
  InterfaceMotion interface_motion() const override {
    InterfaceMotion m = InterfaceMotion::zeros(1);
    m.x[0] = Vec2(value_, 0.0);
    return m;
  }
  double x() const { return value_; }

private:
  double load_ = 0.0;
};

const Calls evaluation{"F.set", "F.advance", "S.set", "S.advance"};

Calls concat(std::initializer_list<Calls> parts) {
  Calls out;
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

// Interface state as a known function of time.
InterfaceMotion g(double t) {
  InterfaceMotion m = InterfaceMotion::zeros(2);
  for (std::size_t i = 0; i < 2; ++i) {
    const double s = 1.0 + static_cast<double>(i);
    m.x[i] = Vec2(1.0 + s * t * t, 2.0 * t);
    m.v[i] = Vec2(2.0 * s * t, 2.0);
    m.a[i] = Vec2(2.0 * s, 0.0);
  }
  return m;
}

struct SubStep {
  InterfaceMotion motion;
  double t, dt;
};

// F recording what it is given; load = (t_end, -2 t_end) at both nodes.
class RecordingFluid : public FluidSolver {
public:
  void initialize() override { loads_ = InterfaceLoads::zeros(2); }
  void set_interface_motion(const InterfaceMotion& m) override { motion_ = m; }
  void advance(double t, double dt) override {
    records.push_back({motion_, t, dt});
    for (auto& f : loads_.f) f = Vec2(t + dt, -2.0 * (t + dt));
  }
  const InterfaceLoads& interface_loads() const override { return loads_; }
  void save_state() override {}
  void restore_state() override {}
  std::vector<SubStep> records;

private:
  InterfaceMotion motion_;
  InterfaceLoads loads_;
};

// S following g(t) whatever the loads; records the loads.
class PrescribedStructure : public StructureSolver {
public:
  void initialize() override { t_ = 0.0; }
  void set_interface_loads(const InterfaceLoads& l) override { loads.push_back(l); }
  void advance(double t, double dt) override { t_ = t + dt; }
  InterfaceMotion interface_motion() const override { return g(t_); }
  void save_state() override { saved_ = t_; }
  void restore_state() override { t_ = saved_; }
  std::vector<InterfaceLoads> loads;

private:
  double t_ = 0.0, saved_ = 0.0;
};

// BGS without acceleration, to `tolerance`.
CouplingOptions plain_bgs(double tolerance) {
  CouplingOptions o;
  o.scheme = "bgs";
  o.acceleration = "none";
  o.tolerance = tolerance;
  return o;
}

void require_equal(const InterfaceMotion& a, const InterfaceMotion& b, double tol) {
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK((a.x[i] - b.x[i]).norm() <= tol);
    CHECK((a.v[i] - b.v[i]).norm() <= tol);
    CHECK((a.a[i] - b.a[i]).norm() <= tol);
  }
}

} // namespace

TEST_CASE("BGS saves once per step and restores F and S before every re-evaluation",
          "[coupling][scheme]") {
  Calls calls;
  CountingFluid fluid(calls);
  CountingStructure structure(calls);
  CouplingOptions o = plain_bgs(1e-12);
  o.max_iterations = 3;
  auto scheme = make_scheme(o, fluid, structure);
  std::vector<StepStats> log;
  scheme->set_step_callback([&](const StepStats& s) { log.push_back(s); });
  scheme->initialize();
  scheme->advance(0.0, 0.1);
  scheme->advance(0.1, 0.1);
  scheme->finalize();

  const Calls restore{"F.restore", "S.restore"};
  const Calls step =
      concat({{"F.save", "S.save"}, evaluation, restore, evaluation, restore, evaluation});
  CHECK(calls == concat({{"F.init", "S.init"}, step, step, {"F.finalize", "S.finalize"}}));
  // Every evaluation starts from the saved state: one advance beyond t^n, not three.
  CHECK(fluid.state_at_advance == std::vector<int>{0, 0, 0, 1, 1, 1});
  CHECK(structure.state_at_advance == std::vector<int>{0, 0, 0, 1, 1, 1});
  // Step 0: x^0 = 0 -> x~ = 1; x^1 = 1 -> 1.5; x^2 = 1.5 -> 1.75, accepted (not 1 + 1.5 + 1.75).
  REQUIRE(log.size() == 2);
  CHECK(log[0].iterations == 3);
  CHECK_FALSE(log[0].converged);
  CHECK_THAT(log[0].residual_initial, Catch::WithinAbs(1.0, 1e-15));
  CHECK_THAT(log[0].residual_final, Catch::WithinAbs(0.25, 1e-15));
  REQUIRE(log[0].omega.has_value());
  CHECK(*log[0].omega == 1.0);
  CHECK(log[1].step == 1);
  CHECK(scheme->summary().steps == 2);
  CHECK(scheme->summary().unconverged == 2);
  CHECK(scheme->summary().max_iterations == 3);
  CHECK_THAT(scheme->summary().mean_iterations(), Catch::WithinAbs(3.0, 1e-15));
  CHECK(log[0].time_fluid >= 0.0);
  CHECK(log[0].time_coupler >= 0.0);
  // Step 1 from x^1 = 1.75: input 1.75 -> 1.75 + 0.5*1.75 + 1 = 3.625, then 4.5390625, then ...
  // closed form after three plain iterations: x = 1.75 + 1 + 0.5 x_prev, x_prev chain.
  double xin = 1.75; // predictor none
  double out = 0.0;
  for (int i = 0; i < 3; ++i) {
    out = 1.75 + 0.5 * xin + 1.0;
    xin = out;
  }
  CHECK_THAT(structure.x(), Catch::WithinAbs(out, 1e-14));
  CHECK_THAT(scheme->interface_motion().x[0].x(), Catch::WithinAbs(out, 1e-14));
}

TEST_CASE("unconverged BGS step throws RunError when asked to", "[coupling][scheme]") {
  Calls calls;
  CountingFluid fluid(calls);
  CountingStructure structure(calls);
  CouplingOptions o = plain_bgs(1e-12); // on this map it does not reach 1e-12 in 3 evaluations
  o.max_iterations = 3;
  o.stop_on_unconverged = true;
  auto scheme = make_scheme(o, fluid, structure);
  int logged = 0;
  scheme->set_step_callback([&](const StepStats&) { ++logged; });
  scheme->initialize();
  try {
    scheme->advance(0.5, 0.1);
    FAIL("no RunError");
  } catch (const fsi::RunError& e) {
    const std::string what = e.what();
    CHECK(what.find("step 0") != std::string::npos);
    CHECK(what.find("t = 0.5") != std::string::npos);
    CHECK(what.find("3 iterations") != std::string::npos);
    CHECK(what.find("residual 0.25") != std::string::npos);
  }
  CHECK(logged == 1); // the step is logged before the throw
}

TEST_CASE("BGS with a converging map stops by eq. 69 and counts nothing as unconverged",
          "[coupling][scheme]") {
  Calls calls;
  CountingFluid fluid(calls);
  CountingStructure structure(calls);
  // Factor 0.5 per iteration: 2^-10 < 1e-3 at the 11th evaluation.
  const CouplingOptions o = plain_bgs(1e-3);
  auto scheme = make_scheme(o, fluid, structure);
  scheme->initialize();
  scheme->advance(0.0, 0.1);
  CHECK(scheme->last_step().iterations == 11);
  CHECK(scheme->last_step().converged);
  CHECK(scheme->summary().unconverged == 0);
  CHECK_THAT(structure.x(), Catch::WithinAbs(2.0, 2.0 * 1e-3)); // fixed point x = 0.5 x + 1
}

TEST_CASE("CSS evaluates once per step without checkpoints", "[coupling][scheme]") {
  Calls calls;
  CountingFluid fluid(calls);
  CountingStructure structure(calls);
  auto scheme = make_scheme(CouplingOptions{}, fluid, structure);
  scheme->initialize();
  scheme->advance(0.0, 0.1);
  scheme->advance(0.1, 0.1);
  CHECK(calls == concat({{"F.init", "S.init"}, evaluation, evaluation}));
  CHECK(scheme->last_step().iterations == 1);
  CHECK_FALSE(scheme->last_step().omega.has_value());
  // Predictor none: x^0 = 0 -> load 1 -> x = 1; then x^1 = 1 -> load 1.5 -> x = 2.5.
  CHECK_THAT(structure.x(), Catch::WithinAbs(2.5, 1e-15));
  CHECK_THAT(scheme->last_step().residual_initial, Catch::WithinAbs(1.5, 1e-15));
}

TEST_CASE("second-order predictor (eqs. 63-65)", "[coupling][scheme]") {
  const InterfaceMotion m = g(0.3);
  const double dt = 0.05;
  const InterfaceMotion p = predict_second_order(m, dt);
  for (std::size_t i = 0; i < m.size(); ++i) {
    CHECK((p.a[i] - m.a[i]).norm() == 0.0);
    // g is quadratic in time with constant acceleration: the predictor is exact.
    CHECK((p.x[i] - g(0.3 + dt).x[i]).norm() <= 1e-15);
    CHECK((p.v[i] - g(0.3 + dt).v[i]).norm() <= 1e-15);
  }
}

TEST_CASE("sub-cycling: fluid sees linear interpolation and structure gets averaged loads",
          "[coupling][scheme]") {
  RecordingFluid fluid;
  PrescribedStructure structure;
  CouplingOptions o;
  o.scheme = "bgs";
  o.acceleration = "none";
  o.substeps = 4;
  auto scheme = make_scheme(o, fluid, structure);
  scheme->initialize();
  const double dt = 0.1;
  scheme->advance(0.0, dt);
  const InterfaceMotion start = scheme->interface_motion(); // structure state at t = 0.1
  require_equal(start, g(0.1), 0.0);
  fluid.records.clear();
  structure.loads.clear();
  scheme->advance(0.1, dt);
  // Iteration 0 against x^0 = x^n (predictor none), iteration 1 against S's state at 0.2:
  // r = 0 there, so the step ends after two evaluations.
  REQUIRE(scheme->last_step().iterations == 2);
  REQUIRE(fluid.records.size() == 8);
  const InterfaceMotion end = structure.interface_motion();
  for (int k = 1; k <= 4; ++k) {
    const SubStep& r = fluid.records[static_cast<std::size_t>(4 + k - 1)];
    CHECK_THAT(r.t, Catch::WithinAbs(0.1 + (k - 1) * 0.025, 1e-15));
    CHECK_THAT(r.dt, Catch::WithinAbs(0.025, 1e-15));
    require_equal(r.motion, interpolate(start, end, k / 4.0), 1e-15);
  }
  // The last sub-step ends exactly on the structure's state at t^{n+1}.
  require_equal(fluid.records.back().motion, end, 0.0);
  // Interpolation ends: s = 0 and s = 1 give the states themselves, exactly.
  require_equal(interpolate(start, end, 0.0), start, 0.0);
  require_equal(interpolate(start, end, 1.0), end, 0.0);
  // Loads: mean of (t_end, -2 t_end) over t_end = 0.125, 0.15, 0.175, 0.2.
  const Vec2 mean(0.1625, -0.325);
  REQUIRE(structure.loads.size() == 2);
  for (const Vec2& f : structure.loads.back().f) CHECK((f - mean).norm() <= 1e-15);
  for (const Vec2& f : scheme->interface_loads().f) CHECK((f - mean).norm() <= 1e-15);
}

TEST_CASE("one-way fluid: prescribed motion at every sub-step", "[coupling][scheme]") {
  RecordingFluid fluid;
  CouplingOptions o;
  o.scheme = "one_way_fluid";
  o.substeps = 2;
  Participants p;
  p.fluid = &fluid;
  p.prescribed_motion = g;
  auto scheme = make_scheme(o, p);
  scheme->initialize(0.0);
  scheme->advance(0.0, 0.1);
  scheme->advance(0.1, 0.1);
  REQUIRE(fluid.records.size() == 4);
  for (std::size_t k = 0; k < 4; ++k)
    require_equal(fluid.records[k].motion, g(0.05 * static_cast<double>(k + 1)), 1e-15);
  require_equal(scheme->interface_motion(), g(0.2), 1e-15);
  CHECK(scheme->last_step().iterations == 1);
  CHECK(scheme->last_step().residual_final == 0.0);
  for (const Vec2& f : scheme->interface_loads().f)
    CHECK((f - Vec2(0.175, -0.35)).norm() <= 1e-15); // mean over t_end = 0.15, 0.2
}

TEST_CASE("one-way structure: prescribed loads at the end of each step", "[coupling][scheme]") {
  PrescribedStructure structure;
  CouplingOptions o;
  o.scheme = "one_way_structure";
  Participants p;
  p.structure = &structure;
  p.prescribed_loads = [](double t) {
    InterfaceLoads l = InterfaceLoads::zeros(2);
    l.f[1] = Vec2(t, 3.0 * t);
    return l;
  };
  auto scheme = make_scheme(o, p);
  scheme->initialize();
  scheme->advance(0.0, 0.25);
  scheme->advance(0.25, 0.25);
  REQUIRE(structure.loads.size() == 2);
  CHECK((structure.loads[0].f[1] - Vec2(0.25, 0.75)).norm() <= 1e-15);
  CHECK((structure.loads[1].f[1] - Vec2(0.5, 1.5)).norm() <= 1e-15);
  require_equal(scheme->interface_motion(), g(0.5), 1e-15);
}

TEST_CASE("registry: components by name and option checks and plugging in",
          "[coupling][registry]") {
  Calls calls;
  CountingFluid fluid(calls);
  CountingStructure structure(calls);
  auto throws_with = [&](const CouplingOptions& o, const std::string& text) {
    try {
      make_scheme(o, fluid, structure);
      FAIL("no InputError for " << text);
    } catch (const fsi::InputError& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).find(text) != std::string::npos);
    }
  };
  CouplingOptions o;
  o.scheme = "jacobi";
  throws_with(o, "coupling.scheme: unknown name 'jacobi' (allowed: bgs css one_way_fluid");
  o = {};
  o.acceleration = "broyden";
  throws_with(o, "coupling.acceleration: unknown name 'broyden'");
  o = {};
  o.tolerance = 0.0;
  throws_with(o, "coupling.tolerance: value 0 is out of range: must be > 0");
  o = {};
  o.tolerance = 2.0; // fine for the absolute measure (metres), not for the relative one
  throws_with(o, "coupling.tolerance: value 2 is out of range: the relative measure");
  o.convergence = "absolute";
  CHECK_NOTHROW(validate_options(o, builtin_registry()));
  o = {};
  o.omega = 2.5;
  throws_with(o, "coupling.omega");
  o = {};
  o.substeps = 0;
  throws_with(o, "coupling.substeps");
  o = {};
  o.max_iterations = 0;
  throws_with(o, "coupling.max_iterations");
  o = {};
  o.scheme = "one_way_fluid";
  throws_with(o, "coupling.scheme: 'one_way_fluid' needs a prescribed motion (coupling.motion)");

  CHECK(builtin_registry().acceleration_names() ==
        std::vector<std::string>{"aitken", "constant", "iqn-ils", "none"});
  CHECK(make_acceleration("iqn-ils", CouplingOptions{})->name() == "iqn-ils");
  CHECK(make_predictor("second_order", CouplingOptions{})->name() == "second_order");

  // A new acceleration plugs in by one registration on a registry.
  Registry r;
  register_builtin_components(r);
  r.add_acceleration("quarter", "constant relaxation 0.25", [](const CouplingOptions&) {
    return std::make_unique<ConstantRelaxation>(0.25);
  });
  o = {};
  o.scheme = "bgs";
  o.acceleration = "quarter";
  o.max_iterations = 2;
  Participants p;
  p.fluid = &fluid;
  p.structure = &structure;
  auto scheme = r.make_scheme(o, p);
  scheme->initialize();
  scheme->advance(0.0, 0.1);
  REQUIRE(scheme->last_step().omega.has_value());
  CHECK(*scheme->last_step().omega == 0.25);
}

TEST_CASE("option declarations cover every field with its default and range",
          "[coupling][registry]") {
  const auto decl = option_declarations(builtin_registry());
  REQUIRE(decl.size() == 13);
  auto find = [&](const std::string& key) {
    for (const auto& d : decl)
      if (d.key == key) return d;
    FAIL("no declaration " << key);
    return OptionDeclaration{};
  };
  CHECK(find("tolerance").default_value == "0.0001");
  CHECK(find("tolerance").range == "> 0");
  CHECK(find("max_iterations").default_value == "200");
  CHECK(find("omega").range == "in (0, 2]");
  CHECK(find("acceleration").default_value == "aitken");
  CHECK(find("reuse").range == "in [0, 1000]");
  CHECK(find("acceleration").range == "one of: aitken constant iqn-ils none");
  CHECK(find("stop_on_unconverged").default_value == "false");
  CHECK_NOTHROW(validate_options(CouplingOptions{}, builtin_registry()));
}
