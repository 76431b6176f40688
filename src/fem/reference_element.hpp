#pragma once
/// @file Shape functions and quadrature of every cell type (mesh/cell_type.hpp), on its
/// reference cell: hex8 and hex20 on [-1, 1]^3 (trilinear; 20-node serendipity), tet4 and
/// tet10 on the unit tetrahedron (barycentric L = (1 - xi - eta - zeta, xi, eta, zeta): N = L_a;
/// corners L_a (2 L_a - 1), edges 4 L_a L_b), wedge6 as the linear triangle times the linear
/// segment in zeta in [-1, 1] (Zienkiewicz & Taylor, The Finite Element Method, vol. 1, ch. 6).
///
/// Quadrature ("full" integrates the stiffness of an undistorted cell exactly):
///   hex8 2x2x2 Gauss; hex20 3x3x3, reduced 2x2x2 (CalculiX's C3D20R); tet4 1 point; tet10 the
///   4-point rule of degree 2; wedge6 the 3-point triangle rule of degree 2 times 2 Gauss points.
/// 2D cells (x-y plane, zeta = 0): the face rules of their shapes (fem/reference_face.hpp):
/// tri3 and tri6 the 3-point rule of degree 2, quad4 2x2 Gauss, quad8 3x3, reduced 2x2
/// (CalculiX's CPE8R, CPS8R, CAX8R).
/// Reduced integration is offered for hex20 and quad8 (CalculiX's C3D20R): a single cell has zero-energy
/// modes besides the rigid ones, which do not spread through a mesh of several cells; for the
/// other types it is the full rule.

#include "mesh/cell_type.hpp"

#include <Eigen/Dense>

#include <vector>

namespace feticon::fem
{
enum class Integration
{
  full,
  reduced
};

struct QuadratureRule
{
  std::vector<Eigen::Vector3d> points; ///< reference coordinates
  std::vector<double> weights;         ///< summing to the reference cell's volume
};

/// The n-point Gauss rule on [-1, 1], n = 2 or 3 (the tensor rules of hexahedra and
/// quadrilateral faces are built from it).
struct GaussLine
{
  std::vector<double> points, weights;
};
const GaussLine& gauss_line(int n);

/// N_a(xi) for every local node a.
Eigen::VectorXd shape_values(mesh::CellKind kind, const Eigen::Vector3d& xi);
/// dN_a/dxi_j(xi): row a, column j.
Eigen::MatrixX3d shape_gradients(mesh::CellKind kind, const Eigen::Vector3d& xi);
/// The rule of `kind`.
const QuadratureRule& quadrature(mesh::CellKind kind, Integration integration = Integration::full);

/// Shape function values and reference gradients at one quadrature point.
struct PointShapes
{
  Eigen::VectorXd N;
  Eigen::MatrixX3d dN;
};
/// shape_values and shape_gradients at each point of quadrature(kind, integration), computed
/// once: element loops read them instead of evaluating the functions at every cell's points.
const std::vector<PointShapes>& quadrature_shapes(mesh::CellKind kind, Integration integration = Integration::full);
} // namespace feticon::fem
