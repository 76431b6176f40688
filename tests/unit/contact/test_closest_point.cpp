/// Tests of project_to_quad (ALGORITHMS.md section 4, "Closest point").
/// References: (1) points built as x(xi0) + h n(xi0), whose closest point is xi0 by construction
/// (r_alpha = -h x_,alpha . n = 0) for |h| below the curvature radius; (2) brute-force
/// minimization of |x(xi) - x_s| by a dense grid in (xi, eta) refined by successively finer local
/// grids, which knows nothing of Newton; (3) closed forms for a flat square.

#include "contact/closest_point.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace feticon::contact
{
namespace
{
/// A clearly non-planar quad (corner heights differ by 0.35 over a size of about 1) that is also
/// not a parallelogram, so x_,xi eta != 0 both in and out of plane.
QuadCoordinates warped_quad()
{
  QuadCoordinates quad;
  quad << 0.0, 0.0, 0.0, //
      1.0, -0.1, 0.15,   //
      1.1, 0.9, -0.1,    //
      -0.1, 1.0, 0.25;
  return quad;
}

/// Hyperbolic paraboloid z = w/2 (1 - xi eta) over [-1, 1]^2 (corner heights 0, w, 0, w).
QuadCoordinates saddle_quad(double w)
{
  QuadCoordinates quad;
  quad << -1, -1, 0, //
      1, -1, w,      //
      1, 1, 0,       //
      -1, 1, w;
  return quad;
}

/// Brute-force closest point over the closed square [-1, 1]^2: 201 x 201 grid, then local 21 x 21
/// grids shrinking by 10 around the best sample until the spacing is 1e-13.
Eigen::Vector2d brute_force_closest(const QuadCoordinates& quad, const Eigen::Vector3d& point)
{
  auto distance2 = [&](const Eigen::Vector2d& xi) { return (quad_point(quad, xi) - point).squaredNorm(); };
  Eigen::Vector2d best(0, 0);
  double best_d2 = distance2(best);
  auto scan = [&](const Eigen::Vector2d& centre, double half_width, int n) {
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
      {
        Eigen::Vector2d xi = centre + half_width * Eigen::Vector2d(2.0 * i / n - 1, 2.0 * j / n - 1);
        xi = xi.cwiseMax(-1.0).cwiseMin(1.0);
        const double d2 = distance2(xi);
        if (d2 < best_d2)
        {
          best_d2 = d2;
          best = xi;
        }
      }
  };
  scan({0, 0}, 1.0, 200);
  for (double half_width = 0.01; half_width > 1e-13; half_width /= 10)
    scan(best, half_width, 20);
  return best;
}
} // namespace

TEST(ShapeFunctions, PartitionOfUnityAndCorners)
{
  for (int a = 0; a < 4; ++a)
  {
    const Eigen::Vector4d n = quad_shape_functions(quad_corner(a));
    EXPECT_EQ(n, Eigen::Vector4d::Unit(a)) << "corner " << a;
  }
  EXPECT_NEAR(quad_shape_functions(Eigen::Vector2d(0.3, -0.7)).sum(), 1.0, 1e-15);
}

TEST(ProjectToQuad, FlatSquareClosedForm)
{
  // Square [0, 2]^2 in z = 0, counter-clockwise from +z: normal +z, xi = x - 1, eta = y - 1.
  QuadCoordinates quad;
  quad << 0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0;
  const QuadProjection above = project_to_quad(quad, Eigen::Vector3d(1.5, 0.25, 0.3));
  EXPECT_TRUE(above.accepted());
  EXPECT_NEAR(above.xi(0), 0.5, 1e-14);
  EXPECT_NEAR(above.xi(1), -0.75, 1e-14);
  EXPECT_NEAR(above.gap, 0.3, 1e-14);
  EXPECT_NEAR((above.normal - Eigen::Vector3d(0, 0, 1)).norm(), 0, 1e-15);
  // Affine map: Newton is exact in one step, the second step is below the tolerance.
  EXPECT_LE(above.iterations, 2);

  const QuadProjection below = project_to_quad(quad, Eigen::Vector3d(0.5, 1.0, -0.2));
  EXPECT_TRUE(below.accepted());
  EXPECT_NEAR(below.gap, -0.2, 1e-14);

  // Outside across the edge x = 2: converged, but xi = 1.5 is not accepted.
  const QuadProjection outside = project_to_quad(quad, Eigen::Vector3d(3.0, 1.0, 0.1));
  EXPECT_TRUE(outside.converged);
  EXPECT_FALSE(outside.inside);
  EXPECT_FALSE(outside.accepted());
  EXPECT_NEAR(outside.xi(0), 2.0, 1e-14);

  // Just inside the acceptance tolerance 1e-6 and just beyond it.
  EXPECT_TRUE(project_to_quad(quad, Eigen::Vector3d(2 + 0.5e-6, 1, 0.1)).accepted());
  EXPECT_FALSE(project_to_quad(quad, Eigen::Vector3d(2 + 4e-6, 1, 0.1)).accepted());
}

TEST(ProjectToQuad, WarpedQuadConstructedPointsConvergeInFiveIterations)
{
  const QuadCoordinates quad = warped_quad();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  int max_iterations = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    const Eigen::Vector2d xi0(0.9 * unit(rng), 0.9 * unit(rng));
    const double h = 0.2 * unit(rng);
    const Eigen::Vector3d point = quad_point(quad, xi0) + h * quad_normal(quad, xi0);
    const QuadProjection p = project_to_quad(quad, point);
    ASSERT_TRUE(p.accepted()) << "trial " << trial;
    EXPECT_NEAR((p.xi - xi0).norm(), 0, 1e-12) << "trial " << trial;
    EXPECT_NEAR(p.gap, h, 1e-13) << "trial " << trial;
    max_iterations = std::max(max_iterations, p.iterations);
  }
  EXPECT_LE(max_iterations, 5);
}

TEST(ProjectToQuad, WarpedQuadMatchesBruteForceSampling)
{
  const QuadCoordinates quad = warped_quad();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  int n_checked = 0;
  for (int trial = 0; trial < 40; ++trial)
  {
    const Eigen::Vector3d point(-0.1 + 1.2 * unit(rng), -0.1 + 1.2 * unit(rng), -0.4 + 0.8 * unit(rng));
    const Eigen::Vector2d reference = brute_force_closest(quad, point);
    const QuadProjection p = project_to_quad(quad, point);
    if (reference.cwiseAbs().maxCoeff() > 0.999)
    {
      // The minimum over the closed square is on its boundary: no interior stationary point.
      EXPECT_FALSE(p.accepted() && p.xi.cwiseAbs().maxCoeff() < 0.99) << "trial " << trial;
      continue;
    }
    ++n_checked;
    ASSERT_TRUE(p.accepted()) << "trial " << trial;
    // The sampled squared distance is flat to round-off 1e-16 near its minimum, which limits the
    // brute-force xi to about 1e-8; the distance itself agrees to round-off.
    EXPECT_NEAR((p.xi - reference).norm(), 0, 1e-7) << "trial " << trial;
    EXPECT_NEAR((p.point - point).norm(), (quad_point(quad, reference) - point).norm(), 1e-13);
    EXPECT_NEAR(std::abs(p.gap), (p.point - point).norm(), 1e-13);
    EXPECT_LE(p.iterations, 5) << "trial " << trial;
  }
  EXPECT_GE(n_checked, 20); // most points project inside
}

TEST(ProjectToQuad, GaussNewtonFallbackOnIndefiniteJacobian)
{
  // Saddle with w = 1 and x_s = (0.3, 0.2, 0.5 + 1.5): at the start xi = 0 the curvature term is
  // x_,xi eta . (x - x_s) = (-w/2)(-1.5) = 0.75 and J = [[1, 0.75], [0.75, 1]] is positive
  // definite, while farther up (H = 3, J_01 = 1.5) it is indefinite and Gauss-Newton is used.
  const QuadCoordinates quad = saddle_quad(1.0);
  for (const double height : {1.5, 3.0})
  {
    const Eigen::Vector3d point(0.3, 0.2, 0.5 + height);
    const QuadProjection p = project_to_quad(quad, point);
    const Eigen::Vector2d reference = brute_force_closest(quad, point);
    ASSERT_TRUE(p.converged) << "height " << height;
    if (height > 2)
      EXPECT_GT(p.gauss_newton_steps, 0);
    else
      EXPECT_EQ(p.gauss_newton_steps, 0);
    if (reference.cwiseAbs().maxCoeff() < 0.999)
    {
      EXPECT_TRUE(p.accepted()) << "height " << height;
      EXPECT_NEAR((p.xi - reference).norm(), 0, 1e-7) << "height " << height;
    }
    else
    {
      EXPECT_FALSE(p.accepted()) << "height " << height << " xi " << p.xi.transpose();
    }
    // Whatever the path, the result is a stationary point of the distance: r = 0.
    const Eigen::Vector3d d = p.point - point;
    const Eigen::Vector2d xi = p.xi;
    const Eigen::Vector3d d_xi(1, 0, -0.5 * xi(1));
    const Eigen::Vector3d d_eta(0, 1, -0.5 * xi(0));
    EXPECT_NEAR(d_xi.dot(d), 0, 1e-12);
    EXPECT_NEAR(d_eta.dot(d), 0, 1e-12);
  }
}

TEST(ProjectToQuad, DegenerateQuadIsNotConverged)
{
  QuadCoordinates quad; // all corners on one line: no tangent plane
  quad << 0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0;
  const QuadProjection p = project_to_quad(quad, Eigen::Vector3d(1, 1, 0));
  EXPECT_FALSE(p.converged);
  EXPECT_FALSE(p.accepted());
}

TEST(ClosestOnSegment, InteriorAndClampedEnds)
{
  const Eigen::Vector3d a(0, 0, 0), b(2, 0, 0);
  EXPECT_DOUBLE_EQ(closest_on_segment(a, b, Eigen::Vector3d(0.5, 1, 0)), 0.25);
  EXPECT_DOUBLE_EQ(closest_on_segment(a, b, Eigen::Vector3d(-1, 1, 0)), 0.0);
  EXPECT_DOUBLE_EQ(closest_on_segment(a, b, Eigen::Vector3d(3, -1, 2)), 1.0);
}
} // namespace feticon::contact
