#pragma once
/// @file The hex8 element: internal force and stiffness, linear and total Lagrangian.
///
/// Total Lagrangian with St Venant–Kirchhoff (ALGORITHMS.md section 7):
///   Fdef = I + sum_a u_a (x) grad_X N_a,  E = 1/2 (Fdef' Fdef - I),  S = lambda tr(E) I + 2 mu E,
///   f_int = sum_gp B_NL' S_v detJ,  K_M = sum_gp B_NL' D B_NL detJ,
///   K_G(a,b) = (grad N_a' S grad N_b) I_3 detJ,  K_T = K_M + K_G.
/// Voigt order [11,22,33,12,23,31], engineering shears in E, plain shears in S.
/// The linear element is the same code with Fdef = I in B and S = D eps(u); then K_G = 0.
/// A temperature change Delta T (interpolated from the nodes) subtracts the thermal strain
/// alpha Delta T I from eps or from E (CalculiX's additive split on the Green-Lagrange strain,
/// fem/temperature_history.hpp): S -= alpha E / (1 - 2 nu) Delta T on the normal components.
/// Element DOFs are node-major: dof 3a + i is component i of node a.

#include "fem/hex8.hpp"
#include "fem/material.hpp"

#include <array>

namespace feticon::fem
{
using ElementVector = Eigen::Matrix<double, 24, 1>;
using ElementMatrix = Eigen::Matrix<double, 24, 24>;
using NodeTemperatures = Eigen::Matrix<double, 8, 1>; ///< T - T_0 per node (K)

/// Which element matrices to compute.
enum class StiffnessKind
{
  none,     ///< internal force only
  material, ///< K_M (the FETI operator in TL: its kernel is the rigid modes of x = X + u)
  tangent,  ///< K_T = K_M + K_G (consistent tangent for full Newton)
  /// K_M with each hyperelastic point's dS/dE replaced by its nearest positive definite matrix:
  /// where K_M is indefinite (fem/cell_element.cpp, make_positive_definite)
  material_definite,
};

/// Internal force and (optionally) stiffness of one hex8 cell.
/// @param[in] X     reference node coordinates (m)
/// @param[in] u     node displacements (m)
/// @param[out] f    internal force (N)
/// @param[out] K    stiffness (N/m); untouched when kind == none
/// @param[in] cell  cell id, for error messages
/// @param[in] temperature_change  T - T_0 per node; null: none
void hex8_element(const NodeCoords& X, const NodeCoords& u, const Material& material, Kinematics kinematics,
                  StiffnessKind kind, ElementVector& f, ElementMatrix* K, int64_t cell,
                  const NodeTemperatures* temperature_change = nullptr);

/// Cauchy stress (Pa) and strain (small strain, or Green-Lagrange E with large displacements;
/// engineering shears) at the Gauss points of hex8_gauss_points(), Voigt [11,22,33,12,23,31],
/// and each point's weight times det J (m^3).
struct Hex8PointResults
{
  std::array<Eigen::Matrix<double, 6, 1>, 8> stress, strain;
  std::array<double, 8> weight;
};
Hex8PointResults hex8_point_results(const NodeCoords& X, const NodeCoords& u, const Material& material,
                                    Kinematics kinematics, int64_t cell,
                                    const NodeTemperatures* temperature_change = nullptr);

/// Volume-averaged Cauchy stress of one cell (Pa), Voigt [11,22,33,12,23,31].
/// Linear: sigma = D eps. TL: sigma = Fdef S Fdef' / det Fdef.
Eigen::Matrix<double, 6, 1> hex8_cauchy_stress(const NodeCoords& X, const NodeCoords& u, const Material& material,
                                               Kinematics kinematics, int64_t cell,
                                               const NodeTemperatures* temperature_change = nullptr);

/// von Mises equivalent stress of a Voigt stress vector (Pa).
double von_mises(const Eigen::Matrix<double, 6, 1>& sigma);
} // namespace feticon::fem
