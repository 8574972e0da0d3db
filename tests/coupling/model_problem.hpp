#pragma once
// Stand-in solvers with known answers: a mass-spring structure (Newmark, beta = 1/4,
// gamma = 1/2) under an added-mass "fluid" load -m_a a + f(t). The monolithic reference is the
// same Newmark with mass m + m_a. One interface node, both components.
#include <functional>

#include "coupling/interface.hpp"

namespace model {

using fsi::Vec2;
using fsi::coupling::InterfaceLoads;
using fsi::coupling::InterfaceMotion;

/// One Newmark (average acceleration) step of M a + k u = load for a point mass.
struct NewmarkPoint {
  Vec2 u = Vec2::Zero(), v = Vec2::Zero(), a = Vec2::Zero();
  void step(double mass, double k, const Vec2& load, double dt) {
    const Vec2 a_new = (load - k * (u + dt * v + 0.25 * dt * dt * a)) / (mass + 0.25 * dt * dt * k);
    u += dt * v + 0.25 * dt * dt * (a + a_new);
    v += 0.5 * dt * (a + a_new);
    a = a_new;
  }
};

struct Parameters {
  double m = 1.0, k = 100.0, ma = 0.5;
  Vec2 u0 = Vec2(0.1, 0.05);
  Vec2 x0 = Vec2(1.0, 2.0); // reference position of the interface node
  std::function<Vec2(double)> f = [](double) { return Vec2::Zero(); };
  /// Initial acceleration consistent with the coupled problem: (f(0) - k u0) / (m + m_a).
  Vec2 a0() const { return (f(0.0) - k * u0) / (m + ma); }
};

/// F: load = -m_a a_wall + f(t + dt), a_wall the acceleration of the motion it was given.
class AddedMassFluid : public fsi::coupling::FluidSolver {
public:
  explicit AddedMassFluid(const Parameters& p) : p_(p) {}
  void initialize() override { loads_ = InterfaceLoads::zeros(1); }
  void set_interface_motion(const InterfaceMotion& m) override { wall_a_ = m.a[0]; }
  void advance(double t, double dt) override { loads_.f[0] = -p_.ma * wall_a_ + p_.f(t + dt); }
  const InterfaceLoads& interface_loads() const override { return loads_; }
  void save_state() override { saved_ = loads_; }
  void restore_state() override { loads_ = saved_; }

private:
  Parameters p_;
  Vec2 wall_a_ = Vec2::Zero();
  InterfaceLoads loads_, saved_;
};

/// S: Newmark mass-spring under the interface load.
class SpringStructure : public fsi::coupling::StructureSolver {
public:
  explicit SpringStructure(const Parameters& p) : p_(p) {}
  void initialize() override {
    s_ = NewmarkPoint{p_.u0, Vec2::Zero(), p_.a0()};
    load_ = Vec2::Zero();
  }
  void set_interface_loads(const InterfaceLoads& l) override { load_ = l.f[0]; }
  void advance(double, double dt) override { s_.step(p_.m, p_.k, load_, dt); }
  InterfaceMotion interface_motion() const override {
    InterfaceMotion m = InterfaceMotion::zeros(1);
    m.x[0] = p_.x0 + s_.u;
    m.v[0] = s_.v;
    m.a[0] = s_.a;
    return m;
  }
  void save_state() override { saved_ = s_; }
  void restore_state() override { s_ = saved_; }
  Vec2 displacement() const { return s_.u; }

private:
  Parameters p_;
  NewmarkPoint s_, saved_;
  Vec2 load_ = Vec2::Zero();
};

/// The monolithic reference: Newmark with mass m + m_a under f.
class Monolithic {
public:
  explicit Monolithic(const Parameters& p) : p_(p), s_{p.u0, Vec2::Zero(), p.a0()} {}
  void advance(double t, double dt) { s_.step(p_.m + p_.ma, p_.k, p_.f(t + dt), dt); }
  Vec2 displacement() const { return s_.u; }

private:
  Parameters p_;
  NewmarkPoint s_;
};

} // namespace model
