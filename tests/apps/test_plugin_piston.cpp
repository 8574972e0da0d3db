// A solver pair of the test's own, plugged in through the same registration path as the real
// solvers (solver_plugin.hpp): a fluid of uniform pressure p and a rigid piston of mass M on a
// spring k, coupled by the scene's scheme through the interface the piston describes (its top
// edge, one order-1 edge). The load is constant, -p w, so the piston's displacement is known:
// u(t) = -(p w / k)(1 - cos(omega t)), omega = sqrt(k / M). Nothing outside this file, its scene
// and CMake names the pair.
#include "coupling/projection.hpp"
#include "fsi/core/state_archive.hpp"
#include "fsi_app/cli.hpp"
#include "fsi_app/solver_plugin.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace fsi;
using namespace fsi::app;

namespace {

struct PressureSpec final : SolverSpec {
  double pressure = 0.0;
};

// F: the uniform pressure on every interface edge, -p n |edge| split by the edge's own shape
// functions (2 Gauss points: exact for order 1 and 2), n the normal pointing into the fluid.
class PressureSolver final : public coupling::FluidSolver {
public:
  PressureSolver(double p, std::vector<InterfaceMesh> interfaces)
      : p_(p), interfaces_(std::move(interfaces)) {
    std::size_t n = 0;
    for (const auto& m : interfaces_) n += m.node_count();
    loads_ = coupling::InterfaceLoads::zeros(n);
    x_ = std::vector<Vec2>(n, Vec2::Zero());
  }
  void initialize() override {}
  void set_interface_motion(const coupling::InterfaceMotion& m) override { x_ = m.x; }
  void advance(double, double) override {
    std::size_t first = 0;
    for (const auto& mesh : interfaces_) {
      const std::vector<Vec2> x(x_.begin() + static_cast<std::ptrdiff_t>(first),
                                x_.begin() +
                                    static_cast<std::ptrdiff_t>(first + mesh.node_count()));
      std::vector<coupling::PointLoad> points;
      const double g = 1.0 / std::sqrt(3.0);
      for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
        const Vec2 t = x[mesh.edges[e][2]] - x[mesh.edges[e][0]];
        const Vec2 into_fluid(t.y(), -t.x()); // the solid on the left of a -> b; |t| long
        for (const double xi : {-g, g}) points.push_back({e, xi, -0.5 * p_ * into_fluid});
      }
      coupling::InterfaceLoads part = coupling::InterfaceLoads::zeros(mesh.node_count());
      coupling::project_point_loads(mesh, points, part);
      std::copy(part.f.begin(), part.f.end(),
                loads_.f.begin() + static_cast<std::ptrdiff_t>(first));
      first += mesh.node_count();
    }
  }
  const coupling::InterfaceLoads& interface_loads() const override { return loads_; }
  void save_state() override {}
  void restore_state() override {}
  void write_state(StateArchive&) const override {}
  void read_state(const StateArchive&) override {}

private:
  double p_;
  std::vector<InterfaceMesh> interfaces_;
  std::vector<Vec2> x_;
  coupling::InterfaceLoads loads_;
};

class PressureFluid final : public FluidPart {
public:
  PressureFluid(double p, std::vector<InterfaceMesh> interfaces)
      : solver_(p, std::move(interfaces)) {}
  void advance(double, double) override {}
  void write_frame(FieldsFile&, const std::vector<std::string>&) const override {}
  std::optional<double> probe(const ProbeSpec&) const override { return std::nullopt; }
  void report(JsonObject&) const override {}
  void write_state(StateArchive&) const override {}
  void read_state(const StateArchive&) override {}
  coupling::FluidSolver& coupling_solver() override { return solver_; }

private:
  PressureSolver solver_;
};

struct PistonSpec final : SolverSpec {
  Vec2 top_left = Vec2::Zero();
  double width = 0.0, mass = 0.0, stiffness = 0.0;
};

// S: a rigid block under its top edge (a = top right, b = top left: the solid below, on the left
// of a -> b), moving vertically on a spring; each step is the exact solution of
// M u'' + k u = F for the step's constant load F.
class Piston final : public StructurePart {
public:
  Piston(std::string name, const PistonSpec& s) : StructurePart(std::move(name)), s_(s) {
    mesh_.order = 1;
    mesh_.X0 = {s.top_left + Vec2(s.width, 0.0), s.top_left};
    mesh_.edges = {{0, 0, 1}};
  }
  // Model
  void advance(double, double dt) override {
    const double w = std::sqrt(s_.stiffness / s_.mass), u_static = force_ / s_.stiffness;
    const double c = std::cos(w * dt), sn = std::sin(w * dt);
    const double u = u_static + (u_ - u_static) * c + v_ / w * sn;
    v_ = -(u_ - u_static) * w * sn + v_ * c;
    u_ = u;
    a_ = (force_ - s_.stiffness * u_) / s_.mass;
  }
  void write_frame(FieldsFile&, const std::vector<std::string>&) const override {}
  std::optional<double> probe(const ProbeSpec& p) const override {
    if (p.structure == name()) return u_;
    return std::nullopt;
  }
  void report(JsonObject&) const override {}
  void write_state(StateArchive& a) const override {
    a.put("piston/" + name(), std::vector<double>{u_, v_, a_});
  }
  void read_state(const StateArchive& a) override {
    const auto& s = a.reals("piston/" + name(), 3);
    u_ = s[0], v_ = s[1], a_ = s[2];
  }
  const InterfaceMesh& interface_mesh() const override { return mesh_; }
  std::vector<Polygon> occupied_area() const override { return {}; }
  coupling::StructureSolver& coupling_solver() override { return adapter_; }

private:
  // S: the piston itself behind the coupler's interface.
  struct Adapter final : coupling::StructureSolver {
    explicit Adapter(Piston& p) : piston(p) {}
    void initialize() override {}
    void set_interface_loads(const coupling::InterfaceLoads& loads) override {
      piston.force_ = loads.f[0].y() + loads.f[1].y();
    }
    void advance(double t, double dt) override { piston.advance(t, dt); }
    coupling::InterfaceMotion interface_motion() const override {
      coupling::InterfaceMotion m = coupling::InterfaceMotion::zeros(2);
      for (std::size_t k = 0; k < 2; ++k)
        m.x[k] = piston.mesh_.X0[k] + Vec2(0.0, piston.u_), m.v[k] = Vec2(0.0, piston.v_),
        m.a[k] = Vec2(0.0, piston.a_);
      return m;
    }
    void save_state() override { saved = {piston.u_, piston.v_, piston.a_}; }
    void restore_state() override {
      piston.u_ = saved[0], piston.v_ = saved[1], piston.a_ = saved[2];
    }
    void write_state(StateArchive& a) const override { piston.write_state(a); }
    void read_state(const StateArchive& a) override { piston.read_state(a); }
    Piston& piston;
    std::array<double, 3> saved{};
  };

  PistonSpec s_;
  InterfaceMesh mesh_;
  double u_ = 0.0, v_ = 0.0, a_ = 0.0, force_ = 0.0;
  Adapter adapter_{*this};
};

void register_pair() {
  static const bool once = [] {
    FluidPlugin f;
    f.name = "uniform_pressure";
    f.doc = "test stand-in: a uniform pressure on every interface";
    f.read = [](Section& s) {
      auto spec = std::make_shared<PressureSpec>();
      spec->pressure = s.real("pressure", Range::any(), "Pa");
      return spec;
    };
    f.check = [](const Scene&, Section&, std::vector<Section>&) {};
    f.build = [](const Scene& scene, const std::vector<InterfaceMesh>& interfaces,
                 const std::vector<Polygon>&, const Ranks&) -> std::unique_ptr<FluidPart> {
      return std::make_unique<PressureFluid>(scene.fluid->as<PressureSpec>().pressure, interfaces);
    };
    f.footprint = [](const Scene&) { return Footprint{}; };
    add_fluid_plugin(f);
    StructurePlugin s;
    s.name = "piston";
    s.doc = "test stand-in: a rigid piston on a spring";
    s.read = [](Section& sec) {
      auto spec = std::make_shared<PistonSpec>();
      spec->top_left = sec.vec2("top_left", "m");
      spec->width = sec.real("width", Range::positive(), "m");
      spec->mass = sec.real("mass", Range::positive(), "kg/m");
      spec->stiffness = sec.real("stiffness", Range::positive(), "N/m^2");
      return spec;
    };
    s.check = [](const Scene&, std::size_t, Section&, std::vector<Section>&) {};
    s.build = [](const Scene& scene, std::size_t i) -> std::unique_ptr<StructurePart> {
      return std::make_unique<Piston>(scene.structures[i].name,
                                      scene.structures[i].as<PistonSpec>());
    };
    s.footprint = [](const Scene&, std::size_t) { return Footprint{}; };
    s.probe_quantities = {"piston_displacement"};
    add_structure_plugin(s);
    return true;
  }();
  (void)once;
}

} // namespace

TEST_CASE("apps: a solver pair of one's own couples through the plug-in registration",
          "[apps][plugin]") {
  register_pair();
  namespace fs = std::filesystem;
  const fs::path root = fs::path(FSI_BINARY_DIR) / "test_plugin_piston";
  fs::remove_all(root);
  const double p = 1000.0, w = 0.2, M = 10.0, k = 1.0e4, omega = std::sqrt(k / M);
  for (const std::string scheme : {"css", "bgs"}) {
    INFO("scheme " << scheme);
    const fs::path out = root / scheme;
    std::ostringstream o, e;
    const int status = run_cli({"run", FSI_TEST_DATA "/piston.yaml", "--out", out.string(), "--set",
                                "coupling.scheme=" + scheme},
                               o, e, false);
    INFO(e.str());
    REQUIRE(status == 0);
    std::ifstream csv(out / "probes.csv");
    std::string line;
    std::getline(csv, line);
    CHECK(line == "time,u");
    int rows = 0;
    double worst = 0.0, lowest = 0.0;
    while (std::getline(csv, line)) {
      double t = 0.0, u = 0.0;
      char comma = 0;
      std::istringstream(line) >> t >> comma >> u;
      const double exact = -(p * w / k) * (1.0 - std::cos(omega * t));
      worst = std::max(worst, std::abs(u - exact));
      lowest = std::min(lowest, u);
      ++rows;
    }
    CHECK(rows == 51);
    // The exact step of a constant load: only probes.csv's 10 significant digits remain.
    CHECK(worst < 1e-9 * p * w / k);
    CHECK(lowest < -1.99 * p * w / k); // it did move: through -2 p w / k at omega t = pi
  }
}
