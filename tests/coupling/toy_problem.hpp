#pragma once
// A toy coupled problem for D = 2 and 3 with answers in closed form: n interface nodes, each a
// point mass m on springs of stiffness k (one per node and axis) under the added-mass "fluid"
// load -m_a a_wall + f(t) (eqs. 66-67 with an added-mass fluid). Newmark (beta = 1/4,
// gamma = 1/2) component by component, so the fixed point of every coupled step is the
// monolithic Newmark step with mass m + m_a:
//   (m + m_a + k dt^2/4) a^{n+1} = f(t + dt) - k (u^n + dt v^n + dt^2/4 a^n),
// and CSS without predictor (the fluid sees a^n) is the same step with mass m and load
// f(t + dt) - m_a a^n.
#include <functional>
#include <string>
#include <vector>

#include "coupling/interface.hpp"
#include "fsi/core/state_archive.hpp"

namespace toy {

using fsi::VecD;

template <int D> struct Problem {
  double m = 1.0, ma = 2.0;
  std::vector<VecD<D>> k, x0, u0; ///< per node: stiffness per axis, reference position, u(0)
  std::function<VecD<D>(std::size_t node, double t)> f;
  std::size_t size() const { return k.size(); }
};

/// Newmark state of the nodes.
template <int D> struct Points {
  std::vector<VecD<D>> u, v, a;

  /// u0 at rest with the monolithic acceleration (f(0) - k u0) / (m + m_a).
  static Points initial(const Problem<D>& p) {
    Points s{p.u0, std::vector<VecD<D>>(p.size(), VecD<D>::Zero()), {}};
    for (std::size_t i = 0; i < p.size(); ++i)
      s.a.push_back((p.f(i, 0.0) - p.k[i].cwiseProduct(p.u0[i])) / (p.m + p.ma));
    return s;
  }

  /// One Newmark step with mass `mass` under the nodal loads `load`.
  void step(const Problem<D>& p, double mass, const std::vector<VecD<D>>& load, double dt) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      const VecD<D> pred = u[i] + dt * v[i] + 0.25 * dt * dt * a[i];
      const VecD<D> a_new = (load[i] - p.k[i].cwiseProduct(pred))
                                .cwiseQuotient((mass + 0.25 * dt * dt * p.k[i].array()).matrix());
      u[i] += dt * v[i] + 0.25 * dt * dt * (a[i] + a_new);
      v[i] += 0.5 * dt * (a[i] + a_new);
      a[i] = a_new;
    }
  }
};

/// F: loads -m_a a_wall + f(t + dt), a_wall the accelerations of the motion it was given.
template <int D> class Fluid final : public fsi::coupling::BasicFluidSolver<D> {
public:
  explicit Fluid(const Problem<D>& p) : p_(p) {}
  void initialize() override { loads_ = fsi::coupling::BasicInterfaceLoads<D>::zeros(p_.size()); }
  void set_interface_motion(const fsi::coupling::BasicInterfaceMotion<D>& m) override {
    wall_a_ = m.a;
  }
  void advance(double t, double dt) override {
    for (std::size_t i = 0; i < p_.size(); ++i) loads_.f[i] = -p_.ma * wall_a_[i] + p_.f(i, t + dt);
  }
  const fsi::coupling::BasicInterfaceLoads<D>& interface_loads() const override { return loads_; }
  void save_state() override { saved_ = loads_; }
  void restore_state() override { loads_ = saved_; }
  void write_state(fsi::StateArchive& a) const override {
    a.put("toy_fluid/loads", fsi::flatten(loads_.f));
  }
  void read_state(const fsi::StateArchive& a) override {
    loads_.f = fsi::unflatten<D>(a.reals("toy_fluid/loads", D * p_.size()));
  }

private:
  Problem<D> p_;
  std::vector<VecD<D>> wall_a_;
  fsi::coupling::BasicInterfaceLoads<D> loads_, saved_;
};

/// S: the Newmark mass-springs under the interface loads.
template <int D> class Structure final : public fsi::coupling::BasicStructureSolver<D> {
public:
  explicit Structure(const Problem<D>& p) : p_(p) {}
  void initialize() override { s_ = Points<D>::initial(p_); }
  void set_interface_loads(const fsi::coupling::BasicInterfaceLoads<D>& l) override { load_ = l.f; }
  void advance(double, double dt) override { s_.step(p_, p_.m, load_, dt); }
  fsi::coupling::BasicInterfaceMotion<D> interface_motion() const override {
    auto m = fsi::coupling::BasicInterfaceMotion<D>::zeros(p_.size());
    for (std::size_t i = 0; i < p_.size(); ++i) m.x[i] = p_.x0[i] + s_.u[i];
    m.v = s_.v;
    m.a = s_.a;
    return m;
  }
  void save_state() override { saved_ = s_; }
  void restore_state() override { s_ = saved_; }
  void write_state(fsi::StateArchive& a) const override {
    a.put("toy_structure/u", fsi::flatten(s_.u));
    a.put("toy_structure/v", fsi::flatten(s_.v));
    a.put("toy_structure/a", fsi::flatten(s_.a));
  }
  void read_state(const fsi::StateArchive& a) override {
    s_.u = field(a, "u");
    s_.v = field(a, "v");
    s_.a = field(a, "a");
  }

private:
  std::vector<VecD<D>> field(const fsi::StateArchive& a, const std::string& key) const {
    return fsi::unflatten<D>(a.reals("toy_structure/" + key, D * p_.size()));
  }

  Problem<D> p_;
  Points<D> s_, saved_;
  std::vector<VecD<D>> load_;
};

} // namespace toy
