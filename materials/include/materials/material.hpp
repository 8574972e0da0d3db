#pragma once
// Hyperelastic material laws shared by every solid solver (structure_fem, solid_tlsph), written
// once for D = 2 and 3 (docs/architecture.md, "Two and three dimensions") in the Green–Lagrange
// strain E (eq. 36) and the second Piola–Kirchhoff stress S (eq. 34). In 2-D they are the plane
// laws (plane strain, or plane stress for St. Venant–Kirchhoff).
// Voigt order: 2-D (11, 22, 12), 3-D (11, 22, 33, 23, 13, 12), with engineering shear 2 E_ij for
// strain and S_ij for stress.
#include <array>
#include <memory>
#include <type_traits>
#include <utility>

#include <Eigen/Core>
#include <Eigen/LU>

#include "fsi/core/options.hpp"
#include "fsi/core/types.hpp"

namespace fsi::materials {

/// Number of independent components of a symmetric D x D tensor.
template <int D> inline constexpr int voigt_size = D*(D + 1) / 2;
/// The tensor index pair (i, j) of each Voigt row.
template <int D>
inline constexpr std::array<std::pair<int, int>, voigt_size<D>> voigt_pairs = [] {
  if constexpr (D == 2)
    return std::array<std::pair<int, int>, 3>{{{0, 0}, {1, 1}, {0, 1}}};
  else
    return std::array<std::pair<int, int>, 6>{{{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}}};
}();
/// A tangent dS/dE in Voigt form.
template <int D> using VoigtMatD = Eigen::Matrix<double, voigt_size<D>, voigt_size<D>>;

using Mat3 = VoigtMatD<2>; ///< 2-D Voigt-form tangent
using Mat6 = VoigtMatD<3>; ///< 3-D Voigt-form tangent

enum class PlaneModel { plane_strain, plane_stress };

/// The strain energy W(E). St. Venant–Kirchhoff is the paper's law (eq. 35); compressible
/// neo-Hookean keeps W finite only for det F > 0, so an element cannot be crushed flat under a
/// finite load (St. Venant–Kirchhoff in compression has a limit load at a stretch of 1/sqrt(3)
/// and a finite energy at det F = 0; docs/structure_fem.md).
enum class MaterialModel { saint_venant_kirchhoff, neo_hookean };

struct MaterialOptions {
  double youngs_modulus = 1.0e6;               ///< E [Pa], > 0
  double poisson_ratio = 0.3;                  ///< nu, in (-1, 0.5)
  double density = 1000.0;                     ///< rho [kg/m^3] in the reference configuration, > 0
  PlaneModel plane = PlaneModel::plane_strain; ///< 2-D only
  MaterialModel model = MaterialModel::saint_venant_kirchhoff; ///< neo_hookean: plane strain only
};

/// Throws InputError naming the field, its value and the allowed range: E, nu and rho.
void validate_constants(const MaterialOptions& options);
/// validate_constants and the 2-D rule across keys (neo_hookean: plane strain).
void validate(const MaterialOptions& options);

/// The keys a user sets, each once (E, nu and rho are required; fsi/core/options.hpp). A visitor
/// that reads them still needs validate() for the rule across keys (neo_hookean: plane strain).
void visit_options(MaterialOptions& options, OptionVisitor& visitor);

/// W, S and dS/dE of a law in D dimensions.
template <int D> class BasicMaterial {
public:
  virtual ~BasicMaterial() = default;
  /// Strain energy density W(E) [J/m^3] (eq. 35).
  virtual double energy(const MatD<D>& E) const = 0;
  /// S(E) = dW/dE (eq. 34).
  virtual MatD<D> stress(const MatD<D>& E) const = 0;
  /// Material tangent dS/dE in Voigt form.
  virtual VoigtMatD<D> tangent(const MatD<D>& E) const = 0;
  virtual double density() const = 0;
};

/// The 2-D (plane) law: adds the out-of-plane stress.
class Material : public BasicMaterial<2> {
public:
  /// Out-of-plane S33 (plane strain: from E33 = 0; plane stress: zero).
  virtual double stress_33(const Mat2& E) const = 0;
};

using Material3 = BasicMaterial<3>;

/// The interface a law of dimension D implements.
template <int D> using MaterialInterface = std::conditional_t<D == 2, Material, Material3>;

/// The law options.model names, in 2-D (options.plane) and in 3-D (options.plane unused).
std::unique_ptr<Material> make_material(const MaterialOptions& options);
std::unique_ptr<Material3> make_material_3d(const MaterialOptions& options);

/// Von Mises equivalent sqrt(3/2 s : s) of a Cauchy stress sigma, s its deviator:
/// sqrt([(s11 - s22)^2 + (s22 - s33)^2 + (s33 - s11)^2] / 2 + 3 (s12^2 + s23^2 + s13^2)).
double von_mises(const MatD<3>& sigma);
/// Von Mises equivalent of the Cauchy stress sigma = F S(E) F^T / J, with sigma_33 = S33 / J
/// (F33 = 1), for the deformation gradient F and its Green–Lagrange strain E (passed in: callers
/// compute E in their own form).
double von_mises(const Material& law, const Mat2& F, const Mat2& E);
/// The same in 3-D: sigma = F S(E) F^T / J.
double von_mises(const Material3& law, const MatD<3>& F, const MatD<3>& E);

} // namespace fsi::materials
