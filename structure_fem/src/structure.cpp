#include "structure_fem/structure.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <sstream>

#include "fsi/core/error.hpp"
#include "fsi/core/state_archive.hpp"

namespace fsi::fem {

template <class Family> void validate(const BasicStructureOptions<Family>& o) {
  if constexpr (Family::dim == 2)
    validate(o.material); // with the 2-D rule across keys
  else
    materials::validate_constants(o.material);
  validate(o.newmark);
  validate(o.linear_solver);
  validate(o.newton);
  if (!o.gravity.allFinite()) throw InputError("structure: gravity must be finite");
}

template <class Family>
BasicStructure<Family>::BasicStructure(typename Family::Mesh mesh,
                                       BasicStructureOptions<Family> options)
    : mesh_(std::move(mesh)), options_(std::move(options)) {
  validate(options_);
  validate_mesh(mesh_);
  if constexpr (dim == 2)
    material_ = make_material(options_.material);
  else
    material_ = make_material_3d(options_.material);
  dofs_ = std::make_unique<DofMap>(mesh_, options_.clamped);
  assembler_ = std::make_unique<BasicAssembler<Family>>(mesh_, *material_, *dofs_);
  solver_ = make_linear_solver(options_.linear_solver);
  solver_->set_near_null_space(rigid_body_modes<dim>(*dofs_, mesh_.X));
  M_ = assembler_->mass();
  M_all_ = assembler_->full_mass();
  for (int d = 0; d < dofs_->num_dofs(); ++d)
    if (dofs_->free_index(d) < 0) constrained_.emplace_back(d, dofs_->condition(d));
  K_ = assembler_->pattern();
  K_eff_ = assembler_->pattern();
  f_g_ = assembler_->gravity_forces(options_.gravity);
  const auto n = static_cast<Eigen::Index>(dim * mesh_.num_nodes());
  state_.u = state_.v = state_.a = state_.f_ext = Vector::Zero(n);
  f_ext_next_ = Vector::Zero(n);
  f_int_ = Vector::Zero(n);
  prescribe(0.0, state_.u, state_.v, state_.a);
  if (dofs_->num_free() > 0) {
    solver_->analyze(M_); // the pattern of M, K and K_eff is the same: analysed once per mesh
    update_acceleration();
  }
}

template <class Family> BasicStructure<Family>::~BasicStructure() = default;

template <class Family> void BasicStructure<Family>::set_external_forces(const Vector& f_ext) {
  if (f_ext.size() != static_cast<Eigen::Index>(dim * mesh_.num_nodes()))
    throw InputError("structure: external forces have size " + std::to_string(f_ext.size()) +
                     ", need " + std::to_string(dim) +
                     " * nodes = " + std::to_string(dim * mesh_.num_nodes()));
  for (Eigen::Index d = 0; d < f_ext.size(); ++d)
    if (!std::isfinite(f_ext[d]))
      throw RunError("structure: the external force on node " + std::to_string(d / dim) +
                     " is not finite (before structure step " + std::to_string(state_.step + 1) +
                     ", t = " + std::to_string(state_.time) + " s)");
  f_ext_next_ = f_ext;
  for (int d = 0; d < dofs_->num_dofs(); ++d)
    if (dofs_->free_index(d) < 0) f_ext_next_[d] = 0.0;
}

template <class Family>
void BasicStructure<Family>::factor_and_solve(const SparseMatrix& K, const Vector& rhs, Vector& x,
                                              int& iterations) {
  solver_->factorize(K);
  x = solver_->solve(rhs);
  iterations = solver_->iterations();
}

template <class Family>
void BasicStructure<Family>::prescribe(double t, Vector& u, Vector& v, Vector& a) const {
  for (const auto& [dof, condition] : constrained_) {
    const auto& motion = options_.clamped[static_cast<std::size_t>(condition)].motion;
    if (!motion) {
      u[dof] = v[dof] = a[dof] = 0.0;
      continue;
    }
    const auto k = motion(mesh_.X[static_cast<std::size_t>(dof / dim)], t);
    u[dof] = k.u[dof % dim];
    v[dof] = k.v[dof % dim];
    a[dof] = k.a[dof % dim];
  }
}

template <class Family> Vector BasicStructure<Family>::constrained_inertia(const Vector& a) const {
  Vector a_c = Vector::Zero(a.size());
  for (const auto& entry : constrained_) a_c[entry.first] = a[entry.first];
  return dofs_->restrict_to_free(M_all_ * a_c);
}

template <class Family> void BasicStructure<Family>::update_acceleration() {
  Vector u = state_.u, v = state_.v;
  prescribe(state_.time, u, v, state_.a);
  assembler_->assemble(state_.u, f_int_, nullptr);
  const Vector r =
      dofs_->restrict_to_free(f_ext_next_ + f_g_ - f_int_) - constrained_inertia(state_.a);
  Vector a_free;
  int its = 0;
  factor_and_solve(M_, r, a_free, its);
  for (int d = 0; d < dofs_->num_dofs(); ++d)
    if (dofs_->free_index(d) >= 0) state_.a[d] = 0.0;
  dofs_->add_free(a_free, state_.a);
  state_.f_ext = f_ext_next_; // the forces a^n balances
}

template <class Family>
void BasicStructure<Family>::newton(Vector& u, const NewtonResidual& residual, StepReport& report) {
  newton_raphson(
      options_.newton, *dofs_, dofs_->restrict_to_free(f_ext_next_ + f_g_).norm(), residual,
      [&](const Vector& rhs, int& iterations) {
        Vector x;
        factor_and_solve(K_eff_, rhs, x, iterations);
        return x;
      },
      u, report);
}

template <class Family> const StepReport& BasicStructure<Family>::advance(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw InputError("structure: time step dt = " + std::to_string(dt) + ": must be > 0");
  const StructureState start = state_;
  const Vector f_end = f_ext_next_;
  std::string first_failure;
  for (int level = 0; level <= options_.newton.max_substep_levels; ++level) {
    const int n = 1 << level; // sub-steps dt / n, the loads linear in time from f^n to f^{n+1}
    StepReport total;
    try {
      for (int i = 1; i <= n; ++i) {
        f_ext_next_ = i == n ? f_end : Vector(start.f_ext + (f_end - start.f_ext) * i / n);
        const StepReport r = step(i == n ? start.time + dt - state_.time : dt / n);
        total.iterations += r.iterations;
        total.halvings += r.halvings;
        total.roundoff_stops += r.roundoff_stops;
        total.guess_retries += r.guess_retries;
        total.final_residual = r.final_residual;
        total.history.insert(total.history.end(), r.history.begin(), r.history.end());
      }
    } catch (const RunError& e) {
      if (level == 0) first_failure = e.what();
      state_ = start;
      f_ext_next_ = f_end;
      continue;
    }
    if (level > 0) { // the work integral over the sub-steps, with the step's forces as one
      state_.external_work =
          start.external_work + 0.5 * (start.f_ext + f_end).dot(state_.u - start.u);
    }
    state_.step = start.step + 1;
    state_.time = start.time + dt;
    total.step = state_.step;
    total.time = state_.time;
    total.substeps = n;
    report_ = std::move(total);
    return report_;
  }
  std::ostringstream msg;
  msg << first_failure;
  if (options_.newton.max_substep_levels > 0)
    msg << "; also with " << (1 << options_.newton.max_substep_levels) << " sub-steps";
  msg << " (structure step " << start.step + 1 << ", t = " << start.time + dt << ")";
  throw RunError(msg.str());
}

template <class Family> StepReport BasicStructure<Family>::step(double dt) {
  const Newmark nm{options_.newmark.beta, options_.newmark.gamma, dt};
  const StructureState& s = state_;
  StepReport report;
  report.step = s.step + 1;
  report.time = s.time + dt;
  const Prediction prescribed = predict(dt); // constrained entries: the prescribed motion
  Vector u = prescribed.u;                   // eq. 64 as the first guess
  const Vector inertia_c = constrained_inertia(prescribed.a);
  const double c0 = nm.mass_factor();
  auto residual = [&](const Vector& u_next, Vector& R) {
    assembler_->assemble(u_next, f_int_, &K_);
    const Vector a_next = nm.acceleration(u_next, s.u, s.v, s.a); // eq. 40
    R = M_ * dofs_->restrict_to_free(a_next) + inertia_c +
        dofs_->restrict_to_free(f_int_ - f_ext_next_ - f_g_);
    const Eigen::Index nnz = K_.nonZeros();
    Eigen::Map<Eigen::VectorXd>(K_eff_.valuePtr(), nnz) =
        c0 * Eigen::Map<const Eigen::VectorXd>(M_.valuePtr(), nnz) +
        Eigen::Map<const Eigen::VectorXd>(K_.valuePtr(), nnz);
  };
  if (dofs_->num_free() > 0) {
    try {
      newton(u, residual, report);
    } catch (const RunError& first) {
      // Eq. 64's guess carries dt^2 a^n / 2. After a sudden load the consistent mass's a^n is
      // large and oscillatory in thin elements, and the tangent at that guess can be indefinite
      // (CHOLMOD refuses it) or Newton can fail from it: Newton once more from u^n + dt v^n.
      u = s.u + dt * s.v;
      for (const auto& entry : constrained_) u[entry.first] = prescribed.u[entry.first];
      try {
        newton(u, residual, report);
      } catch (const RunError& second) {
        throw RunError(std::string(first.what()) + "; from u^n + dt v^n: " + second.what());
      }
      report.guess_retries = 1;
    }
  }
  Vector a = nm.acceleration(u, s.u, s.v, s.a);
  Vector v = nm.velocity(a, s.v, s.a); // eq. 41
  for (const auto& entry : constrained_) {
    v[entry.first] = prescribed.v[entry.first];
    a[entry.first] = prescribed.a[entry.first];
  }
  state_.external_work += 0.5 * (state_.f_ext + f_ext_next_).dot(u - state_.u);
  state_.u = u;
  state_.v = v;
  state_.a = a;
  state_.f_ext = f_ext_next_;
  state_.time = report.time;
  state_.step = report.step;
  return report;
}

template <class Family>
std::vector<StepReport> BasicStructure<Family>::solve_static(const StaticOptions& options) {
  if (options.load_steps < 1)
    throw InputError("static: load_steps = " + std::to_string(options.load_steps) +
                     ": must be >= 1");
  std::vector<StepReport> reports;
  Vector u = state_.u;
  const Vector f_total = f_ext_next_ + f_g_;
  const double time = options.time.value_or(state_.time);
  Vector u_target = u, v_target = state_.v, a_target = state_.a;
  prescribe(time, u_target, v_target, a_target);
  for (int i = 1; i <= options.load_steps; ++i) {
    const double lambda = static_cast<double>(i) / options.load_steps;
    for (const auto& entry : constrained_)
      u[entry.first] =
          state_.u[entry.first] + lambda * (u_target[entry.first] - state_.u[entry.first]);
    StepReport report;
    report.step = i;
    report.time = lambda;
    auto residual = [&](const Vector& u_k, Vector& R) {
      assembler_->assemble(u_k, f_int_, &K_);
      R = dofs_->restrict_to_free(f_int_ - lambda * f_total);
      K_eff_ = K_;
    };
    try {
      if (dofs_->num_free() > 0) newton(u, residual, report);
    } catch (const RunError& e) {
      std::ostringstream msg;
      msg << e.what() << " (static load step " << i << " of " << options.load_steps
          << ", load factor " << lambda << ")";
      throw RunError(msg.str());
    }
    reports.push_back(std::move(report));
  }
  state_.external_work += 0.5 * (state_.f_ext + f_ext_next_).dot(u - state_.u);
  state_.u = u;
  state_.v.setZero();
  state_.a.setZero();
  for (const auto& entry : constrained_) {
    state_.v[entry.first] = v_target[entry.first];
    state_.a[entry.first] = a_target[entry.first];
  }
  state_.f_ext = f_ext_next_;
  state_.time = time;
  return reports;
}

template <class Family> auto BasicStructure<Family>::positions() const -> std::vector<VecD<dim>> {
  std::vector<VecD<dim>> x(mesh_.num_nodes());
  for (std::size_t k = 0; k < x.size(); ++k)
    x[k] =
        mesh_.X[k] + state_.u.template segment<dim>(dim * static_cast<Eigen::Index>(k)); // eq. 60
  return x;
}

template <class Family> Prediction BasicStructure<Family>::predict(double dt) const {
  const StructureState& s = state_;
  Prediction p{s.u + dt * s.v + 0.5 * dt * dt * s.a, // eq. 64
               s.v + dt * s.a,                       // eq. 65
               s.a};                                 // eq. 63
  prescribe(s.time + dt, p.u, p.v, p.a);
  return p;
}

template <class Family> void BasicStructure<Family>::restore(const StructureState& state) {
  assert(state.u.size() == state_.u.size());
  state_ = state;
  f_ext_next_ = state.f_ext;
}

template <class Family> Vector BasicStructure<Family>::von_mises() const {
  return assembler_->nodal_von_mises(state_.u);
}

template <class Family> Energies BasicStructure<Family>::energies() const {
  Energies e;
  e.kinetic = 0.5 * state_.v.dot(M_all_ * state_.v);
  e.strain = assembler_->strain_energy(state_.u);
  e.gravity_work = f_g_.dot(state_.u);
  e.external_work = state_.external_work;
  return e;
}

namespace {
std::vector<double> to_std(const Vector& v) {
  return {v.data(), v.data() + v.size()};
}
} // namespace

template <class Family>
void BasicStructure<Family>::write_state(StateArchive& a, const std::string& prefix) const {
  a.put(prefix + "u", to_std(state_.u));
  a.put(prefix + "v", to_std(state_.v));
  a.put(prefix + "a", to_std(state_.a));
  a.put(prefix + "f_ext", to_std(state_.f_ext));
  a.put(prefix + "f_ext_next", to_std(f_ext_next_));
  a.put_real(prefix + "time", state_.time);
  a.put_integer(prefix + "step", state_.step);
  a.put_real(prefix + "external_work", state_.external_work);
}

template <class Family>
void BasicStructure<Family>::read_state(const StateArchive& a, const std::string& prefix) {
  const std::size_t n = dim * mesh_.num_nodes();
  auto vector = [&](const char* name) {
    const auto& v = a.reals(prefix + name, n);
    return Vector(Eigen::Map<const Vector>(v.data(), static_cast<Eigen::Index>(n)));
  };
  state_.u = vector("u");
  state_.v = vector("v");
  state_.a = vector("a");
  state_.f_ext = vector("f_ext");
  f_ext_next_ = vector("f_ext_next");
  state_.time = a.real(prefix + "time");
  state_.step = a.integer(prefix + "step");
  state_.external_work = a.real(prefix + "external_work");
}

template void validate(const BasicStructureOptions<T6>&);
template void validate(const BasicStructureOptions<T10>&);
template class BasicStructure<T6>;
template class BasicStructure<T10>;

} // namespace fsi::fem
