/// Tests of the building blocks of the dual mortar integration (mortar_integration.hpp).
/// References: closed-form integrals of monomials on an interval and a triangle, closed-form
/// polygon areas, and the biorthogonality int Phi_j N_k dA = delta_jk D_j that defines the dual
/// basis, checked with an independent finer Gauss rule.

#include "contact/mortar_integration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace feticon::contact
{
TEST(MortarIntegration, QuadratureRulesAreExact)
{
  // Gauss-Legendre with n points integrates x^k, k <= 2n - 1, over [-1, 1]: 2 / (k + 1) for even k.
  for (int n = 1; n <= 6; ++n)
  {
    const QuadratureRule2d line = gauss_legendre_1d(n);
    for (int k = 0; k <= 2 * n - 1; ++k)
    {
      double sum = 0;
      for (size_t q = 0; q < line.points.size(); ++q)
        sum += line.weights[q] * std::pow(line.points[q](0), k);
      EXPECT_NEAR(sum, k % 2 == 0 ? 2.0 / (k + 1) : 0.0, 1e-14) << "n = " << n << ", k = " << k;
    }
  }
  // Collapsed rule on the unit triangle: int x^a y^b = a! b! / (a + b + 2)! for a + b <= 2n - 2
  // (the rule's weights sum to 1, so times the area 1/2).
  const int n = SegmentOptions{}.triangle_points;
  const QuadratureRule2d triangle = gauss_triangle(n);
  for (int a = 0; a <= 2 * n - 2; ++a)
    for (int b = 0; a + b <= 2 * n - 2; ++b)
    {
      double sum = 0;
      for (size_t q = 0; q < triangle.points.size(); ++q)
        sum += 0.5 * triangle.weights[q] * std::pow(triangle.points[q](0), a) * std::pow(triangle.points[q](1), b);
      const double exact = std::tgamma(a + 1) * std::tgamma(b + 1) / std::tgamma(a + b + 3);
      EXPECT_NEAR(sum / exact, 1.0, 1e-13) << "x^" << a << " y^" << b;
    }
}

TEST(MortarIntegration, ClippingAndDualBasis)
{
  // Square [-1,1]^2 clipped by itself rotated by 45 degrees: a regular octagon of area
  // 8 (sqrt(2) - 1); by a disjoint square: empty; by [0,2]^2: the unit square.
  const std::vector<Eigen::Vector2d> square = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const double r = std::sqrt(2.0);
  const std::vector<Eigen::Vector2d> diamond = {{0, -r}, {r, 0}, {0, r}, {-r, 0}};
  EXPECT_NEAR(polygon_area(clip_polygon(square, diamond)), 8 * (r - 1), 1e-14);
  EXPECT_TRUE(clip_polygon(square, {{3, 3}, {4, 3}, {4, 4}, {3, 4}}).empty());
  EXPECT_NEAR(polygon_area(clip_polygon(square, {{0, 0}, {2, 0}, {2, 2}, {0, 2}})), 1.0, 1e-15);

  // Biorthogonality int Phi_j N_k dA = delta_jk D_j on a flat trapezoid in a tilted plane,
  // checked with a finer 8 x 8 Gauss rule (exact: the integrand has degree 3 per direction), and
  // sum_j Phi_j = 1. D_j sums to the trapezoid area (1 + 2) / 2 * 1 = 1.5.
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -1, 2).normalized()).toRotationMatrix();
  QuadCoordinates quad;
  quad << 0, 0, 0, 2, 0, 0, 1.5, 1, 0, 0.5, 1, 0;
  quad = (quad * rotation.transpose()).eval();
  const DualBasis dual = dual_basis(quad);
  EXPECT_NEAR(dual.nodal_area.sum(), 1.5, 1e-14);
  const QuadratureRule2d fine = gauss_square(8);
  Eigen::Matrix4d product = Eigen::Matrix4d::Zero();
  for (size_t q = 0; q < fine.points.size(); ++q)
  {
    const Eigen::Vector2d& xi = fine.points[q];
    // Area element |x_,xi x x_,eta| from the tangents of the bilinear map.
    Eigen::Vector3d d_xi = Eigen::Vector3d::Zero(), d_eta = Eigen::Vector3d::Zero();
    for (int a = 0; a < 4; ++a)
    {
      d_xi += 0.25 * quad_corners[a][0] * (1 + quad_corners[a][1] * xi(1)) * quad.row(a).transpose();
      d_eta += 0.25 * quad_corners[a][1] * (1 + quad_corners[a][0] * xi(0)) * quad.row(a).transpose();
    }
    const double area = fine.weights[q] * d_xi.cross(d_eta).norm();
    product += area * dual_shape_functions(dual, xi) * quad_shape_functions(xi).transpose();
    EXPECT_NEAR(dual_shape_functions(dual, xi).sum(), 1.0, 1e-14);
  }
  EXPECT_LT((product - Eigen::Matrix4d(dual.nodal_area.asDiagonal())).cwiseAbs().maxCoeff(), 1e-14);
}
} // namespace feticon::contact
