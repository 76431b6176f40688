#pragma once
/// @file The element of any cell type (mesh/cell_type.hpp): internal force and stiffness,
/// linear and total Lagrangian, written once over the shape functions and quadrature of
/// fem/reference_element.hpp. The formulation is hex8_element.hpp's (ALGORITHMS.md section 7):
///   Fdef = I + sum_a u_a (x) grad_X N_a,  E = 1/2 (Fdef' Fdef - I),  S = lambda tr(E) I + 2 mu E,
///   f_int = sum_gp B_NL' S_v w detJ,  K_M = sum_gp B_NL' D B_NL w detJ,
///   K_G(a,b) = (grad N_a' S grad N_b) I_3 w detJ;
/// the linear element is the same with Fdef = I in B and S = D eps(u). Element DOFs are
/// node-major: dof 3a + i is component i of node a. A temperature change subtracts the
/// thermal strain as hex8_element.hpp says. A hyperelastic material (fem/hyperelasticity.hpp,
/// total Lagrangian) replaces S = D E and D by its S(E) and dS/dE.
///
/// 2D cells (mesh::Planar; nodes in the x-y plane, u_z zero): the same formulas with no
/// gradient in z and w det J times the out-of-plane measure (thickness, 2 pi r): plane strain
/// is E_33 = 0; plane stress takes E_33 where S_33 = 0 (the in-plane tangent
/// D - D e3 e3' D / D_33; exact for St Venant-Kirchhoff, linear in E); axisymmetry (x = r) has
/// F_33 = 1 + u_r / r, so E_33 = u_r / r + (u_r / r)^2 / 2, with its terms in B and in K_G.
/// u_z is no unknown of a 2D model: of a 2D cell's f and K only the x and y entries are
/// computed (the products on B's rows 11, 22, 33, 12 and its x and y columns), the z entries
/// are to be ignored.

#include "fem/hex8_element.hpp"
#include "fem/j2_plasticity.hpp"
#include "fem/material.hpp"
#include "fem/reference_element.hpp"
#include "mesh/mesh.hpp"

#include <Eigen/Dense>

#include <cstdint>
#include <span>

namespace feticon::fem
{
/// The J2 state of a cell's quadrature points (fem/j2_plasticity.hpp): the committed states
/// the increment starts from, and, where not empty, where the states at u are written.
struct CellPlasticState
{
  std::span<const PlasticPointState> committed;
  std::span<PlasticPointState> updated;
};

/// Internal force (N) and, unless kind == none, stiffness (N/m) of one cell. A plastic material
/// (Material::is_plastic, small strain) needs `plastic` with one committed state per quadrature
/// point; its K is the consistent tangent of the return (Simo and Hughes), D where a point does
/// not yield (K_0 at u = 0).
/// @param[in] X  reference node coordinates, one row per local node (m)
/// @param[in] u  node displacements, likewise (m)
/// @param[in] cell  cell id for error messages (an inverted cell names it)
/// @param[in] temperature_change  T - T_0 per node (K); null: none
void cell_element(mesh::CellKind type, const Eigen::MatrixX3d& X, const Eigen::MatrixX3d& u, const Material& material,
                  Kinematics kinematics, StiffnessKind kind, Integration integration, Eigen::VectorXd& f,
                  Eigen::MatrixXd* K, int64_t cell, const Eigen::VectorXd* temperature_change = nullptr,
                  const CellPlasticState* plastic = nullptr, const mesh::Planar& planar = {});

/// Cauchy stress (Pa) and strain (small strain, or Green-Lagrange E; engineering shears) at the
/// quadrature points of the cell, Voigt [11,22,33,12,23,31], and each point's weight times
/// det J (m^3): hex8_point_results for any cell type. A plastic material's stress is that of
/// its points' committed states at u.
struct CellPointResults
{
  std::vector<Eigen::Matrix<double, 6, 1>> stress, strain;
  std::vector<double> weight;
};
CellPointResults cell_point_results(mesh::CellKind type, const Eigen::MatrixX3d& X, const Eigen::MatrixX3d& u,
                                    const Material& material, Kinematics kinematics, Integration integration,
                                    int64_t cell, const Eigen::VectorXd* temperature_change = nullptr,
                                    std::span<const PlasticPointState> plastic = {}, const mesh::Planar& planar = {});

/// Volume-averaged Cauchy stress of one cell (Pa), Voigt [11,22,33,12,23,31]: the weighted mean
/// of cell_point_results' stresses (at the points of `integration`), as hex8_cauchy_stress.
Eigen::Matrix<double, 6, 1> cell_cauchy_stress(mesh::CellKind type, const Eigen::MatrixX3d& X,
                                               const Eigen::MatrixX3d& u, const Material& material,
                                               Kinematics kinematics, int64_t cell,
                                               Integration integration = Integration::full,
                                               const Eigen::VectorXd* temperature_change = nullptr,
                                               std::span<const PlasticPointState> plastic = {},
                                               const mesh::Planar& planar = {});

/// Small strain (linear) or Green-Lagrange strain (total Lagrangian), Voigt
/// [11,22,33,12,23,31] with engineering shears, at each quadrature point of the cell: the
/// kinematic strain (in plane stress E_33 is the material's: cell_point_results).
std::vector<Eigen::Matrix<double, 6, 1>> cell_point_strains(mesh::CellKind type, const Eigen::MatrixX3d& X,
                                                            const Eigen::MatrixX3d& u, Kinematics kinematics,
                                                            Integration integration, int64_t cell,
                                                            const mesh::Planar& planar = {});
} // namespace feticon::fem
