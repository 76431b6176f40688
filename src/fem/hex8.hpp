#pragma once
/// @file Trilinear hexahedron (hex8): shape functions and 2x2x2 Gauss quadrature.
///
/// Reference node a has coordinates (xi_a, eta_a, zeta_a) in {-1,+1}^3 in VTK order
/// (mesh/mesh.hpp); N_a = 1/8 (1 + xi_a xi)(1 + eta_a eta)(1 + zeta_a zeta).

#include <Eigen/Dense>
#include <array>

namespace feticon::fem
{
using NodeCoords = Eigen::Matrix<double, 8, 3>;     ///< one row per element node
using ShapeGradients = Eigen::Matrix<double, 8, 3>; ///< row a: gradient of N_a

/// Reference coordinates of the 8 nodes (VTK order).
inline constexpr std::array<std::array<double, 3>, 8> hex8_reference_nodes = {{
    {-1, -1, -1},
    {1, -1, -1},
    {1, 1, -1},
    {-1, 1, -1},
    {-1, -1, 1},
    {1, -1, 1},
    {1, 1, 1},
    {-1, 1, 1},
}};

/// Shape function values at reference point `xi`.
Eigen::Matrix<double, 8, 1> hex8_shape(const Eigen::Vector3d& xi);
/// Gradients of the shape functions with respect to the reference coordinates.
ShapeGradients hex8_reference_gradients(const Eigen::Vector3d& xi);

/// The 8 Gauss points (+-1/sqrt(3))^3, all with weight 1.
const std::array<Eigen::Vector3d, 8>& hex8_gauss_points();

/// Geometry of one Gauss point in the reference configuration X.
struct GaussGeometry
{
  ShapeGradients dN_dX; ///< gradients with respect to X
  double weight_det_j;  ///< Gauss weight times det(dX/dxi) (m^3)
  double det_j;         ///< det(dX/dxi)
};

/// Computes the geometry at reference point `xi`; throws feticon::Error naming `cell`
/// if det J <= 0 (inverted or degenerate element).
GaussGeometry hex8_gauss_geometry(const NodeCoords& X, const Eigen::Vector3d& xi, int64_t cell);
} // namespace feticon::fem
