#pragma once
/// @file Shape functions and quadrature of the face types (mesh/cell_type.hpp): tri3 and tri6 on
/// the unit triangle (barycentric L = (1 - xi - eta, xi, eta): N = L_a; corners L_a (2 L_a - 1),
/// edges 4 L_a L_b), quad4 and quad8 on [-1, 1]^2 (bilinear; 8-node serendipity). Nodes in the
/// order of a mesh::Face: corners counter-clockwise seen from outside, then the edge midpoints
/// of the edges c0 c1, c1 c2, ...; so x_,xi x x_,eta points out of the body. The edges of 2D
/// cells, line2 and line3, on [-1, 1] in xi (linear; corners xi (xi -+ 1) / 2, midpoint
/// 1 - xi^2), nothing varying with eta; their x_,xi x e_z points out of the body.
///
/// Quadrature: tri3 the 3-point rule of degree 2, tri6 the 6-point rule of degree 4 (Dunavant
/// 1985), quad4 2x2 Gauss, quad8 3x3 Gauss: the consistent nodal forces of a uniform traction on
/// a flat face exactly; line2 2 Gauss points, line3 3.

#include "mesh/cell_type.hpp"

#include <Eigen/Dense>

#include <vector>

namespace feticon::fem
{
struct FaceQuadrature
{
  std::vector<Eigen::Vector2d> points; ///< reference coordinates (xi, eta)
  std::vector<double> weights;         ///< summing to the reference face's area (1/2, 4; a line's 2)
};

/// A face's vectors and matrices are sized at run time but bounded by the largest face (quad8):
/// evaluating them allocates nothing (the contact search evaluates them at every segment point).
constexpr int max_face_nodes = 8;
using FaceValues = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, max_face_nodes, 1>;
using FaceGradients = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::ColMajor, max_face_nodes, 2>;

/// N_a(xi) for every face node a.
FaceValues face_shape_values(mesh::FaceKind kind, const Eigen::Vector2d& xi);
/// dN_a/dxi_j(xi): row a, column j.
FaceGradients face_shape_gradients(mesh::FaceKind kind, const Eigen::Vector2d& xi);
/// The rule of `kind`.
const FaceQuadrature& face_quadrature(mesh::FaceKind kind);
} // namespace feticon::fem
