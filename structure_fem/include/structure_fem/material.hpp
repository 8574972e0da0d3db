#pragma once
// Hyperelastic material laws in 2D, written in the Green–Lagrange strain E (eq. 36) and the
// second Piola–Kirchhoff stress S (eq. 34). Voigt order: (11, 22, 12) with engineering shear
// 2 E12 for strain, S12 for stress.
#include <memory>

#include "structure_fem/types.hpp"

namespace fsi::fem {

enum class PlaneModel { plane_strain, plane_stress };

struct MaterialOptions {
  double youngs_modulus = 1.0e6; ///< E [Pa], > 0
  double poisson_ratio = 0.3;    ///< nu, in (-1, 0.5)
  double density = 1000.0;       ///< rho [kg/m^3] in the reference configuration, > 0
  PlaneModel plane = PlaneModel::plane_strain;
};

/// Throws InputError naming the field, its value and the allowed range.
void validate(const MaterialOptions& options);

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

/// Saint Venant–Kirchhoff, W = lambda/2 (tr E)^2 + mu tr(E^2) (eq. 35). Plane stress replaces
/// lambda by lambda* = 2 lambda mu / (lambda + 2 mu).
class StVenantKirchhoff final : public Material {
public:
  explicit StVenantKirchhoff(const MaterialOptions& options);
  double energy(const Mat2& E) const override;
  Mat2 stress(const Mat2& E) const override;
  Mat3 tangent(const Mat2& E) const override;
  double stress_33(const Mat2& E) const override;
  double density() const override { return rho_; }
  double lambda() const { return lambda_; } ///< the in-plane lambda (lambda* in plane stress)
  double mu() const { return mu_; }

private:
  double lambda_, mu_, rho_;
  bool plane_strain_;
};

} // namespace fsi::fem
