#include "fem/hex8.hpp"

#include "common/error.hpp"

#include <cmath>

namespace feticon::fem
{
Eigen::Matrix<double, 8, 1> hex8_shape(const Eigen::Vector3d& xi)
{
  Eigen::Matrix<double, 8, 1> N;
  for (int a = 0; a < 8; ++a)
  {
    const auto& r = hex8_reference_nodes[a];
    N(a) = 0.125 * (1 + r[0] * xi(0)) * (1 + r[1] * xi(1)) * (1 + r[2] * xi(2));
  }
  return N;
}

ShapeGradients hex8_reference_gradients(const Eigen::Vector3d& xi)
{
  ShapeGradients dN;
  for (int a = 0; a < 8; ++a)
  {
    const auto& r = hex8_reference_nodes[a];
    const double fx = 1 + r[0] * xi(0), fy = 1 + r[1] * xi(1), fz = 1 + r[2] * xi(2);
    dN(a, 0) = 0.125 * r[0] * fy * fz;
    dN(a, 1) = 0.125 * fx * r[1] * fz;
    dN(a, 2) = 0.125 * fx * fy * r[2];
  }
  return dN;
}

const std::array<Eigen::Vector3d, 8>& hex8_gauss_points()
{
  static const std::array<Eigen::Vector3d, 8> points = [] {
    const double g = 1.0 / std::sqrt(3.0);
    std::array<Eigen::Vector3d, 8> p;
    for (int a = 0; a < 8; ++a)
    {
      const auto& r = hex8_reference_nodes[a];
      p[a] = Eigen::Vector3d(g * r[0], g * r[1], g * r[2]);
    }
    return p;
  }();
  return points;
}

GaussGeometry hex8_gauss_geometry(const NodeCoords& X, const Eigen::Vector3d& xi, int64_t cell)
{
  const ShapeGradients dN = hex8_reference_gradients(xi);
  const Eigen::Matrix3d J = X.transpose() * dN; // J_ij = dX_i / dxi_j
  const double det = J.determinant();
  FETICON_CHECK(det > 0,
                "element " << cell << " is inverted or degenerate (det J = " << det
                           << " at a Gauss point); check its node order and geometry");
  GaussGeometry g;
  g.dN_dX = dN * J.inverse();
  g.det_j = det;
  g.weight_det_j = det; // Gauss weights are 1
  return g;
}
} // namespace feticon::fem
