#pragma once
/// @file Isotropic St Venant–Kirchhoff material (linear elasticity at small strain), with its
/// thermal expansion and, at small strain, J2 plasticity; or a hyperelastic law.

#include "fem/hyperelasticity.hpp"
#include "fem/yield_curve.hpp"

#include <Eigen/Dense>
#include <string>

namespace feticon::fem
{
/// Isotropic elastic constants. In the total Lagrangian setting S = lambda tr(E) I + 2 mu E
/// (St Venant–Kirchhoff); at small strain the same constants give Hooke's law.
struct Material
{
  double young = 2.0e11; ///< Young's modulus E_Y (Pa)
  double poisson = 0.3;  ///< Poisson's ratio nu, in (-1, 0.5)
  double density = 0;    ///< rho (kg/m^3): only body loads (fem/body_loads.hpp) use it; 0: none given
  /// alpha (1/K): the thermal strain alpha (T - T_0) I of a temperature change from the
  /// initial temperature T_0 (fem/temperature_history.hpp); 0: none
  double expansion = 0;
  /// J2 plasticity with isotropic hardening (fem/j2_plasticity.hpp) by this yield curve; empty:
  /// elastic. Small strain only (Problem::check refuses it with large displacements).
  YieldCurve plastic = {};
  /// Neo-Hooke or Mooney-Rivlin (fem/hyperelasticity.hpp) in place of St Venant-Kirchhoff;
  /// empty: none. young and poisson are then its moduli at E = 0 (set_hyperelastic), which K_0
  /// and the solver's scalings use. Total Lagrangian only (the Assembler refuses small strain).
  Hyperelastic hyperelastic = {};
  /// A hyperelastic or (large displacements) plastic body's linear cells (quad4, hex8) take
  /// F-bar (fem/cell_element.hpp), which keeps nearly incompressible laws and isochoric plastic
  /// flow from locking them; the settings hyperelastic.fbar and plasticity.fbar.
  bool fbar = false;

  bool is_plastic() const { return !plastic.empty(); }
  bool is_hyperelastic() const { return !hyperelastic.empty(); }
  /// St Venant-Kirchhoff (the hex8 fast path's material): neither plastic nor hyperelastic.
  bool is_st_venant_kirchhoff() const { return !is_plastic() && !is_hyperelastic(); }
  /// The hyperelastic law and young, poisson at its E = 0.
  void set_hyperelastic(const Hyperelastic& law);

  double lame_lambda() const { return young * poisson / ((1 + poisson) * (1 - 2 * poisson)); }
  double lame_mu() const { return young / (2 * (1 + poisson)); }
  /// The normal stress of a unit temperature change with the strain held, alpha E / (1 - 2 nu)
  /// (Pa/K): D applied to alpha (1, 1, 1, 0, 0, 0).
  double thermal_stress() const { return expansion * young / (1 - 2 * poisson); }
  /// 6x6 elasticity matrix in Voigt order [11,22,33,12,23,31] with engineering shears.
  Eigen::Matrix<double, 6, 6> elasticity_matrix() const;
  /// Throws feticon::Error naming `where` if E <= 0, nu is outside (-1, 0.5), rho is negative or not
  /// finite, alpha is not finite, or the yield curve is malformed (YieldCurve::check) or softens
  /// faster than 3 G (the radial return would have no solution), or a hyperelastic law is
  /// malformed (Hyperelastic::check) or has a plastic table or thermal expansion (not implemented).
  void check(const std::string& where) const;
};

/// Contact modulus E* of two elastic bodies in frictionless contact,
/// 1/E* = (1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2 (Johnson 1985, Contact Mechanics, eq. 4.22).
inline double contact_modulus(const Material& first, const Material& second)
{
  return 1 / ((1 - first.poisson * first.poisson) / first.young + (1 - second.poisson * second.poisson) / second.young);
}

/// Small strain (linear) or total Lagrangian (Green–Lagrange strain, finite rotations).
enum class Kinematics
{
  linear,
  total_lagrangian
};
} // namespace feticon::fem
