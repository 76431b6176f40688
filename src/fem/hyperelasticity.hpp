#pragma once
/// @file Rubber-like hyperelasticity in CalculiX's and Abaqus's definitions (total Lagrangian):
/// the strain energy per reference volume
///   W = C10 (I1b - 3) + C01 (I2b - 3) + (J - 1)^2 / D1,
/// I1b = J^(-2/3) I1 and I2b = J^(-4/3) I2 the invariants of the isochoric part of
/// C = F'F = I + 2 E, J = det F. C01 = 0 is Neo-Hooke, C01 != 0 Mooney-Rivlin (CalculiX's
/// POLYNOMIAL, N=1). At E = 0 it is Hooke's law with mu_0 = 2 (C10 + C01) and
/// K_0 = 2 / D1. S = 2 dW/dC and its tangent dS/dE = 4 d^2W/dC^2 are written out below
/// (Holzapfel, Nonlinear Solid Mechanics, 6.4-6.6, for the isochoric/volumetric split).

#include <Eigen/Dense>

#include <string>

namespace feticon::fem
{
struct Hyperelastic
{
  double c10 = 0; ///< Pa
  double c01 = 0; ///< Pa (0: Neo-Hooke)
  double d1 = 0;  ///< 1/Pa; 0: no hyperelastic law (the material is St Venant-Kirchhoff)

  bool empty() const { return d1 == 0 && c10 == 0 && c01 == 0; }
  double initial_shear_modulus() const { return 2 * (c10 + c01); }
  double initial_bulk_modulus() const { return 2 / d1; }
  /// Young's modulus and Poisson's ratio of the law at E = 0 (the small-strain stiffness
  /// K_0 the outer loop starts from): E = 9 K mu / (3 K + mu), nu = (3 K - 2 mu) / (6 K + 2 mu).
  double initial_young() const;
  double initial_poisson() const;
  /// Throws feticon::Error naming `where` unless C10 > 0, C01 >= 0 and D1 > 0 are finite (the
  /// law is then polyconvex and has a positive initial shear and bulk modulus).
  void check(const std::string& where) const;
};

/// The second Piola-Kirchhoff stress S (Pa) at Green-Lagrange strain E, both Voigt
/// [11,22,33,12,23,31] (E with engineering shears), and, where `tangent` is not null, dS/dE
/// in the same Voigt order (the element's material tangent, symmetric).
/// @throws feticon::Error if det C <= 0 (an inverted point)
Eigen::Matrix<double, 6, 1> hyperelastic_stress(const Hyperelastic& law, const Eigen::Matrix<double, 6, 1>& E,
                                                Eigen::Matrix<double, 6, 6>* tangent = nullptr);
} // namespace feticon::fem
