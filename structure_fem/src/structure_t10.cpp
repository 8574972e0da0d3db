#include "structure_fem/structure_t10.hpp"

#include <sstream>
#include <string>

#include "fsi/core/error.hpp"

namespace fsi::fem {

void validate(const StructureT10Options& o) {
  materials::validate_constants(o.material);
  validate(o.newmark);
  validate(o.newton);
  validate(o.linear_solver);
  if (!o.gravity.allFinite()) throw InputError("structure: gravity must be finite");
}

StructureT10::StructureT10(TetMesh mesh, StructureT10Options options)
    : mesh_(std::move(mesh)), options_(std::move(options)) {
  validate(options_);
  material_ = make_material_3d(options_.material);
  dofs_ = std::make_unique<DofMap>(mesh_, options_.clamped);
  assembler_ = std::make_unique<AssemblerT10>(mesh_, *material_, *dofs_);
  solver_ = make_linear_solver(options_.linear_solver);
  M_ = assembler_->mass();
  K_ = K_eff_ = assembler_->pattern();
  f_g_ = assembler_->gravity_forces(options_.gravity);
  const auto n = static_cast<Eigen::Index>(3 * mesh_.num_nodes());
  u_ = v_ = a_ = f_ext_ = f_int_ = Vector::Zero(n);
  if (dofs_->num_free() > 0) {
    solver_->analyze(M_); // M, K and K_eff share the pattern: analysed once per mesh
    update_acceleration();
  }
}

void StructureT10::set_external_forces(const Vector& f_ext) {
  if (f_ext.size() != u_.size())
    throw InputError("structure: external forces have size " + std::to_string(f_ext.size()) +
                     ", need 3 * nodes = " + std::to_string(u_.size()));
  f_ext_ = f_ext;
  for (int d = 0; d < dofs_->num_dofs(); ++d)
    if (dofs_->free_index(d) < 0) f_ext_[d] = 0.0;
}

void StructureT10::newton(Vector& u, const NewtonResidual& residual, StepReport& report) {
  newton_raphson(
      options_.newton, *dofs_, dofs_->restrict_to_free(f_ext_ + f_g_).norm(), residual,
      [&](const Vector& rhs, int& iterations) {
        solver_->factorize(K_eff_);
        iterations = solver_->iterations();
        return solver_->solve(rhs);
      },
      u, report);
}

void StructureT10::update_acceleration() {
  assembler_->assemble(u_, f_int_, nullptr);
  solver_->factorize(M_);
  a_.setZero();
  dofs_->add_free(solver_->solve(dofs_->restrict_to_free(f_ext_ + f_g_ - f_int_)), a_);
}

std::vector<StepReport> StructureT10::solve_static(int load_steps) {
  if (load_steps < 1)
    throw InputError("static: load_steps = " + std::to_string(load_steps) + ": must be >= 1");
  std::vector<StepReport> reports;
  for (int i = 1; i <= load_steps; ++i) {
    const double lambda = static_cast<double>(i) / load_steps;
    StepReport report;
    report.step = i;
    report.time = lambda;
    auto residual = [&](const Vector& u, Vector& R) {
      assembler_->assemble(u, f_int_, &K_);
      R = dofs_->restrict_to_free(f_int_ - lambda * (f_ext_ + f_g_));
      K_eff_ = K_;
    };
    try {
      if (dofs_->num_free() > 0) newton(u_, residual, report);
    } catch (const RunError& e) {
      std::ostringstream msg;
      msg << e.what() << " (static load step " << i << " of " << load_steps << ", load factor "
          << lambda << ")";
      throw RunError(msg.str());
    }
    reports.push_back(std::move(report));
  }
  v_.setZero();
  a_.setZero();
  return reports;
}

void StructureT10::set_initial_conditions(const Vector& u, const Vector& v) {
  if (u.size() != u_.size() || v.size() != v_.size())
    throw InputError("structure: initial conditions need size 3 * nodes = " +
                     std::to_string(u_.size()));
  u_ = u;
  v_ = v;
  if (dofs_->num_free() > 0) update_acceleration();
}

const StepReport& StructureT10::advance(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw InputError("structure: time step dt = " + std::to_string(dt) + ": must be > 0");
  const Newmark nm{options_.newmark.beta, options_.newmark.gamma, dt};
  const double c0 = nm.mass_factor();
  StepReport report;
  report.time = time_ + dt;
  Vector u = u_ + dt * v_ + 0.5 * dt * dt * a_; // constrained entries stay zero
  auto residual = [&](const Vector& u_next, Vector& R) {
    assembler_->assemble(u_next, f_int_, &K_);
    const Vector a_next = nm.acceleration(u_next, u_, v_, a_); // eq. 40
    R = M_ * dofs_->restrict_to_free(a_next) + dofs_->restrict_to_free(f_int_ - f_ext_ - f_g_);
    K_eff_ = c0 * M_ + K_; // same pattern
  };
  try {
    if (dofs_->num_free() > 0) newton(u, residual, report);
  } catch (const RunError& e) {
    throw RunError(std::string(e.what()) + " (structure t = " + std::to_string(report.time) + ")");
  }
  const Vector a = nm.acceleration(u, u_, v_, a_);
  v_ = nm.velocity(a, v_, a_); // eq. 41
  a_ = a;
  u_ = u;
  time_ = report.time;
  report_ = std::move(report);
  return report_;
}

materials::SolidEnergies StructureT10::energies() const {
  materials::SolidEnergies e;
  const Vector v = dofs_->restrict_to_free(v_);
  e.kinetic = 0.5 * v.dot(M_ * v);
  e.strain = assembler_->strain_energy(u_);
  e.gravity_work = f_g_.dot(u_);
  e.external_work = f_ext_.dot(u_);
  return e;
}

} // namespace fsi::fem
