#pragma once
// Hyperelastic material laws in 2D shared by every solid solver (structure_fem, solid_tlsph),
// written in the Green–Lagrange strain E (eq. 36) and the second Piola–Kirchhoff stress S (eq. 34).
// Voigt order: (11, 22, 12) with engineering shear 2 E12 for strain, S12 for stress.
#include <memory>

#include <Eigen/Core>
#include <Eigen/LU>

#include "fsi/core/options.hpp"
#include "fsi/core/types.hpp"

namespace fsi::materials {

using Mat3 = Eigen::Matrix3d; ///< Voigt-form tangent

enum class PlaneModel { plane_strain, plane_stress };

/// The strain energy W(E). St. Venant–Kirchhoff is the paper's law (eq. 35); compressible
/// neo-Hookean keeps W finite only for det F > 0, so an element cannot be crushed flat under a
/// finite load (St. Venant–Kirchhoff in compression has a limit load at a stretch of 1/sqrt(3)
/// and a finite energy at det F = 0; docs/structure_fem.md).
enum class MaterialModel { saint_venant_kirchhoff, neo_hookean };

struct MaterialOptions {
  double youngs_modulus = 1.0e6; ///< E [Pa], > 0
  double poisson_ratio = 0.3;    ///< nu, in (-1, 0.5)
  double density = 1000.0;       ///< rho [kg/m^3] in the reference configuration, > 0
  PlaneModel plane = PlaneModel::plane_strain;
  MaterialModel model = MaterialModel::saint_venant_kirchhoff; ///< neo_hookean: plane strain only
};

/// Throws InputError naming the field, its value and the allowed range.
void validate(const MaterialOptions& options);

/// The keys a user sets, each once (E, nu and rho are required; fsi/core/options.hpp). A visitor
/// that reads them still needs validate() for the rule across keys (neo_hookean: plane strain).
void visit_options(MaterialOptions& options, OptionVisitor& visitor);

class Material;
/// The law options.model names.
std::unique_ptr<Material> make_material(const MaterialOptions& options);

class Material {
public:
  virtual ~Material() = default;
  /// Strain energy density W(E) [J/m^3] (eq. 35).
  virtual double energy(const Mat2& E) const = 0;
  /// S(E) = dW/dE (eq. 34).
  virtual Mat2 stress(const Mat2& E) const = 0;
  /// Material tangent dS/dE in Voigt form.
  virtual Mat3 tangent(const Mat2& E) const = 0;
  /// Out-of-plane S33 (plane strain: from E33 = 0; plane stress: zero).
  virtual double stress_33(const Mat2& E) const = 0;
  virtual double density() const = 0;
};

/// Von Mises equivalent of the Cauchy stress sigma = F S(E) F^T / J, with sigma_33 = S33 / J
/// (F33 = 1), for the deformation gradient F and its Green–Lagrange strain E (passed in: callers
/// compute E in their own form).
double von_mises(const Material& law, const Mat2& F, const Mat2& E);

} // namespace fsi::materials
