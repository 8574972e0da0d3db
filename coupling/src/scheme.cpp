#include "coupling/scheme.hpp"

#include <cassert>
#include <cmath>
#include <sstream>

#include "coupling/reduction.hpp"
#include "fsi/core/error.hpp"
#include "fsi/core/state_archive.hpp"

namespace fsi::coupling {

template <int D> Eigen::VectorXd pack(const BasicInterfaceMotion<D>& m) {
  const auto n = static_cast<Eigen::Index>(m.size());
  Eigen::VectorXd z(3 * D * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    z.segment<D>(D * i) = m.x[k];
    z.segment<D>(D * n + D * i) = m.v[k];
    z.segment<D>(2 * D * n + D * i) = m.a[k];
  }
  return z;
}

template <int D> BasicInterfaceMotion<D> unpack(const Eigen::VectorXd& z) {
  assert(z.size() % (3 * D) == 0);
  const Eigen::Index n = z.size() / (3 * D);
  auto m = BasicInterfaceMotion<D>::zeros(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    m.x[k] = z.segment<D>(D * i);
    m.v[k] = z.segment<D>(D * n + D * i);
    m.a[k] = z.segment<D>(2 * D * n + D * i);
  }
  return m;
}

template Eigen::VectorXd pack(const InterfaceMotion&);
template Eigen::VectorXd pack(const InterfaceMotion3&);
template InterfaceMotion unpack<2>(const Eigen::VectorXd&);
template InterfaceMotion3 unpack<3>(const Eigen::VectorXd&);

template <int D> Eigen::VectorXd coupling_scale(std::size_t n, double dt) {
  const auto m = static_cast<Eigen::Index>(D * n);
  Eigen::VectorXd s(3 * m);
  s.head(m).setOnes();
  s.segment(m, m).setConstant(dt);
  s.tail(m).setConstant(dt * dt);
  return s;
}

template Eigen::VectorXd coupling_scale<2>(std::size_t, double);
template Eigen::VectorXd coupling_scale<3>(std::size_t, double);

namespace {

template <int D> bool all_finite(const BasicInterfaceMotion<D>& m) {
  for (std::size_t i = 0; i < m.size(); ++i)
    if (!m.x[i].allFinite() || !m.v[i].allFinite() || !m.a[i].allFinite()) return false;
  return true;
}

} // namespace

template <int D>
BasicCouplingScheme<D>::BasicCouplingScheme(std::string name, const CouplingOptions& options,
                                            BasicSchemeComponents<D> components)
    : options_(options), name_(std::move(name)), components_(std::move(components)) {
  assert(components_.predictor != nullptr);
  assert(components_.acceleration == nullptr || !components_.measures.empty());
}

template <int D> void BasicCouplingScheme<D>::initialize(double t0) {
  state_ = initialize_participants(t0);
  n_nodes_ = state_.size();
  check_sizes(state_, "initial interface motion");
  loads_ = Loads::zeros(n_nodes_);
  step_index_ = 0;
  summary_ = {};
  initialized_ = true;
}

template <int D> void BasicCouplingScheme<D>::finalize() {
  if (initialized_) finalize_participants();
  initialized_ = false;
}

template <int D>
BasicInterfaceMotion<D> BasicCouplingScheme<D>::first_input(double /*t*/, double dt) {
  return components_.predictor->predict(state_, dt);
}

template <int D> void BasicCouplingScheme<D>::check_sizes(const Motion& m, const char* what) const {
  if (m.x.size() == n_nodes_ && m.v.size() == n_nodes_ && m.a.size() == n_nodes_) return;
  std::ostringstream s;
  s << "coupling (" << name_ << "): step " << step_index_ << ": " << what << " has x/v/a sizes "
    << m.x.size() << "/" << m.v.size() << "/" << m.a.size() << ", expected " << n_nodes_
    << " interface nodes";
  throw RunError(s.str());
}

template <int D> void BasicCouplingScheme<D>::advance(double t, double dt) {
  assert(initialized_ && "CouplingScheme::advance before initialize");
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    std::ostringstream s;
    s << "coupling (" << name_ << "): step " << step_index_ << " at t = " << t << " s: dt = " << dt
      << " is not a positive finite time step";
    throw RunError(s.str());
  }
  const auto start = std::chrono::steady_clock::now();
  step_ = StepStats{};
  step_.step = step_index_;
  step_.t = t;
  step_.dt = dt;
  Acceleration* acceleration = components_.acceleration.get();
  const bool iterate = acceleration != nullptr;

  Motion input = first_input(t, dt);
  check_sizes(input, "first interface input");
  if (iterate) {
    save_checkpoint();
    acceleration->begin_step(coupling_scale<D>(n_nodes_, dt));
    for (auto& m : components_.measures) m->begin_step();
  }

  Motion output;
  bool converged = true;
  std::size_t worst = 0; // interface node with the largest position residual, for messages
  for (int it = 0;; ++it) {
    if (it > 0) restore_checkpoint();
    output = evaluate(t, dt, input);
    check_sizes(output, "structure interface motion");
    ++step_.iterations;
    double rx = 0.0, rv = 0.0;
    if (has_residual()) {
      rx = norm_of_difference(output.x, input.x); // eq. 68
      rv = norm_of_difference(output.v, input.v);
    }
    if (!std::isfinite(rx) || !std::isfinite(rv) || !all_finite(output)) {
      std::ostringstream s;
      s << "coupling (" << name_ << "): step " << step_index_ << " at t = " << t << " s, iteration "
        << it + 1 << ": non-finite interface state or residual";
      throw RunError(s.str());
    }
    if (it == 0) step_.residual_initial = rx;
    step_.residual_final = rx;
    if (!iterate) break;

    bool done = components_.measures[0]->measure(rx, norm(output.x));
    for (std::size_t k = 1; k < components_.measures.size(); ++k)
      done = components_.measures[k]->measure(rv, norm(output.v)) && done;
    if (done) break;
    if (it + 1 >= options_.max_iterations) {
      converged = false;
      for (std::size_t k = 0; k < n_nodes_; ++k)
        if (norm(output.x[k] - input.x[k]) > norm(output.x[worst] - input.x[worst])) worst = k;
      break;
    }
    Eigen::VectorXd next;
    acceleration->update(pack(input), pack(output), next);
    step_.omega = acceleration->relaxation();
    input = unpack<D>(next);
  }
  if (iterate) acceleration->end_step(converged);
  state_ = std::move(output);
  step_.converged = converged;

  const double total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  step_.time_coupler = std::max(0.0, total - step_.time_fluid - step_.time_structure);
  last_ = step_;
  summary_.add(last_);
  ++step_index_;
  if (callback_) callback_(last_);

  if (!converged && options_.stop_on_unconverged) {
    std::ostringstream s;
    s << "coupling (" << name_ << "): step " << last_.step << " at t = " << t
      << " s did not converge in " << last_.iterations << " iterations: residual "
      << last_.residual_final << " m, largest at interface node " << worst << " (";
    for (std::size_t k = 0; k < components_.measures.size(); ++k)
      s << (k ? "; " : "") << (k ? "velocities " : "positions ")
        << components_.measures[k]->criterion() << ", value " << components_.measures[k]->value();
    s << ")";
    throw RunError(s.str());
  }
}

template <int D>
const BasicInterfaceLoads<D>&
BasicCouplingScheme<D>::run_fluid(Fluid& fluid, double t, double dt,
                                  const std::function<Motion(double s)>& motion_at) {
  const int m = options_.substeps;
  const double dts = dt / m;
  Loads sum = Loads::zeros(n_nodes_);
  for (int k = 1; k <= m; ++k) {
    const double s = static_cast<double>(k) / static_cast<double>(m); // exactly 1 at k = m
    const Motion motion = motion_at(s);
    check_sizes(motion, "fluid interface input");
    time_fluid([&] {
      fluid.set_interface_motion(motion);
      fluid.advance(t + (k - 1) * dts, dts);
    });
    const Loads& f = fluid.interface_loads();
    if (f.size() != n_nodes_) {
      std::ostringstream e;
      e << "coupling (" << name_ << "): step " << step_index_ << ": fluid returned " << f.size()
        << " interface loads, expected " << n_nodes_;
      throw RunError(e.str());
    }
    if (m == 1) {
      loads_ = f;
      return loads_;
    }
    for (std::size_t i = 0; i < n_nodes_; ++i) sum.f[i] += f.f[i];
  }
  for (auto& f : sum.f) f /= static_cast<double>(m);
  loads_ = std::move(sum);
  return loads_;
}

template <int D>
BasicInterfaceMotion<D> BasicCouplingScheme<D>::run_structure(Structure& structure,
                                                              const Loads& loads, double t,
                                                              double dt) {
  Motion out;
  time_structure([&] {
    structure.set_interface_loads(loads);
    structure.advance(t, dt);
    out = structure.interface_motion();
  });
  return out;
}

template <int D>
BasicInterfaceMotion<D> BasicCouplingScheme<D>::serial_evaluate(Fluid& fluid, Structure& structure,
                                                                double t, double dt,
                                                                const Motion& input) {
  // Sub-step k of m sees (1 - k/m) x^n + (k/m) x^{n+1}, the same for v and a (linear in time).
  const Loads& loads = run_fluid(
      fluid, t, dt, [&](double s) { return s == 1.0 ? input : interpolate(state_, input, s); });
  return run_structure(structure, loads, t, dt);
}

template <int D> void BasicCouplingScheme<D>::write_state(StateArchive& a) const {
  a.put_integer("coupling/step", step_index_);
  a.put("coupling/state/x", flatten(state_.x));
  a.put("coupling/state/v", flatten(state_.v));
  a.put("coupling/state/a", flatten(state_.a));
  a.put("coupling/loads", flatten(loads_.f));
  a.put("coupling/summary/counts",
        std::vector<std::int64_t>{summary_.steps, summary_.iterations, summary_.max_iterations,
                                  summary_.unconverged});
  a.put("coupling/summary/seconds",
        std::vector<double>{summary_.time_fluid, summary_.time_structure, summary_.time_coupler});
  if (components_.acceleration) components_.acceleration->write_state(a, "coupling/acceleration/");
  write_participants(a);
}

template <int D> void BasicCouplingScheme<D>::read_state(const StateArchive& a) {
  assert(initialized_ && "CouplingScheme::read_state before initialize");
  const std::size_t n = D * n_nodes_;
  step_index_ = a.integer("coupling/step");
  state_.x = unflatten<D>(a.reals("coupling/state/x", n));
  state_.v = unflatten<D>(a.reals("coupling/state/v", n));
  state_.a = unflatten<D>(a.reals("coupling/state/a", n));
  loads_.f = unflatten<D>(a.reals("coupling/loads", n));
  const auto& counts = a.integers("coupling/summary/counts", 4);
  const auto& seconds = a.reals("coupling/summary/seconds", 3);
  summary_.steps = counts[0];
  summary_.iterations = counts[1];
  summary_.max_iterations = static_cast<int>(counts[2]);
  summary_.unconverged = counts[3];
  summary_.time_fluid = seconds[0];
  summary_.time_structure = seconds[1];
  summary_.time_coupler = seconds[2];
  if (components_.acceleration) components_.acceleration->read_state(a, "coupling/acceleration/");
  read_participants(a);
}

template class BasicCouplingScheme<2>;
template class BasicCouplingScheme<3>;

} // namespace fsi::coupling
