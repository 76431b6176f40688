/// The 2D cells (tri3, quad4, tri6, quad8) in plane strain, plane stress and axisymmetry
/// (mesh::Planar, fem/cell_element.hpp), each cell on its own. References: the Kronecker and
/// partition-of-unity properties of the shape functions and central differences for their
/// gradients; closed-form monomial integrals over the reference square and triangle
/// (a! b! / (a + b + 2)!); the in-plane rigid modes (3 zero eigenvalues; 1 in axisymmetry, the
/// axial translation); Hooke's law for a homogeneous strain (plane strain sigma_zz = nu
/// (sigma_xx + sigma_yy), plane stress sigma_zz = 0, axisymmetric hoop strain u_r / r); central
/// differences of the internal force for the tangent stiffness.

#include "common/error.hpp"
#include "fem/cell_element.hpp"
#include "fem/reference_face.hpp"
#include "mesh/cell_type.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace feticon
{
namespace planar_element_test
{
using mesh::CellKind;
using mesh::Planar;
using mesh::PlanarKind;

const fem::Material steel{2e11, 0.3};

Eigen::Vector3d reference_node(CellKind kind, int a)
{
  const auto& p = mesh::cell_type(kind).reference_nodes[a];
  return {p[0], p[1], p[2]};
}

bool triangle(CellKind kind) { return kind == CellKind::tri3 || kind == CellKind::tri6; }

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }
double interval_moment(int p) { return p % 2 ? 0.0 : 2.0 / (p + 1); }

/// A straight-edged cell of positive orientation away from the axis (x in [1, 2]).
Eigen::MatrixX3d affine_cell(CellKind kind)
{
  Eigen::Matrix3d M = Eigen::Matrix3d::Identity();
  M.topLeftCorner<2, 2>() << 0.4, 0.1, -0.05, 0.35;
  const Eigen::Vector3d c(1.5, -0.2, 0);
  Eigen::MatrixX3d X(mesh::cell_type(kind).n_nodes, 3);
  for (int a = 0; a < X.rows(); ++a)
    X.row(a) = (M * reference_node(kind, a) + c).transpose();
  return X;
}

/// The element's K and f restricted to the in-plane components (u_z is eliminated).
struct InPlane
{
  Eigen::VectorXd f;
  Eigen::MatrixXd K;
};
InPlane in_plane_element(CellKind kind, const Eigen::MatrixX3d& X, const Eigen::MatrixX3d& u, const Planar& planar,
                         fem::Kinematics kinematics)
{
  Eigen::VectorXd f;
  Eigen::MatrixXd K;
  fem::cell_element(kind, X, u, steel, kinematics, fem::StiffnessKind::tangent, fem::Integration::full, f, &K, 0,
                    nullptr, nullptr, planar);
  const auto n = X.rows();
  InPlane out{Eigen::VectorXd(2 * n), Eigen::MatrixXd(2 * n, 2 * n)};
  for (Eigen::Index a = 0; a < n; ++a)
    for (int i = 0; i < 2; ++i)
    {
      out.f(2 * a + i) = f(3 * a + i);
      for (Eigen::Index b = 0; b < n; ++b)
        for (int j = 0; j < 2; ++j)
          out.K(2 * a + i, 2 * b + j) = K(3 * a + i, 3 * b + j);
    }
  return out;
}

class PlanarCells : public ::testing::TestWithParam<CellKind>
{
};

TEST_P(PlanarCells, EdgesPointOutAndShapeFunctionsAreNodalWithConsistentGradients)
{
  const CellKind kind = GetParam();
  const mesh::CellType& type = mesh::cell_type(kind);
  EXPECT_EQ(type.dimension, 2);
  EXPECT_EQ(mesh::cell_type_of_gmsh_type(type.gmsh_type), &type);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int a = 0; a < type.n_corners; ++a)
    centre += reference_node(kind, a) / type.n_corners;
  for (const mesh::CellFace& edge : type.faces)
  {
    ASSERT_TRUE(mesh::is_line(edge.kind));
    const Eigen::Vector3d x0 = reference_node(kind, edge.nodes[0]);
    const Eigen::Vector3d outward = (reference_node(kind, edge.nodes[1]) - x0).cross(Eigen::Vector3d::UnitZ());
    EXPECT_GT(outward.dot(x0 - centre), 0);
  }
  const int n = type.n_nodes;
  for (int b = 0; b < n; ++b)
  {
    const Eigen::VectorXd N = fem::shape_values(kind, reference_node(kind, b));
    for (int a = 0; a < n; ++a)
      EXPECT_NEAR(N(a), a == b ? 1.0 : 0.0, 1e-14);
  }
  const Eigen::Vector3d xi(0.21, 0.17, 0);
  EXPECT_NEAR(fem::shape_values(kind, xi).sum(), 1.0, 1e-14);
  const Eigen::MatrixX3d dN = fem::shape_gradients(kind, xi);
  EXPECT_EQ(dN.col(2).norm(), 0);
  for (int j = 0; j < 2; ++j)
  {
    const Eigen::Vector3d e = 1e-6 * Eigen::Vector3d::Unit(j);
    const Eigen::VectorXd fd = (fem::shape_values(kind, xi + e) - fem::shape_values(kind, xi - e)) / 2e-6;
    EXPECT_LT((fd - dN.col(j)).cwiseAbs().maxCoeff(), 1e-8);
  }
}

TEST_P(PlanarCells, QuadratureIntegratesTheStiffnessDegree)
{
  const CellKind kind = GetParam();
  const fem::QuadratureRule& rule = fem::quadrature(kind);
  // Full rules: a straight-edged cell's stiffness (degree 2 (p - 1) per direction on quads,
  // total degree 2 (p - 1) on triangles) exactly.
  const int order = mesh::cell_type(kind).order;
  for (int a = 0; a <= 4; ++a)
    for (int b = 0; b <= 4; ++b)
    {
      const bool needed = triangle(kind) ? a + b <= 2 * (order - 1) : a <= 2 * order && b <= 2 * order;
      if (!needed)
        continue;
      double sum = 0;
      for (size_t q = 0; q < rule.points.size(); ++q)
        sum += rule.weights[q] * std::pow(rule.points[q].x(), a) * std::pow(rule.points[q].y(), b);
      const double exact =
          triangle(kind) ? factorial(a) * factorial(b) / factorial(a + b + 2) : interval_moment(a) * interval_moment(b);
      EXPECT_NEAR(sum, exact, 1e-14) << "x^" << a << " y^" << b;
    }
}

/// Zero eigenvalues of the in-plane K at u = 0.
int zero_eigenvalues(const Eigen::MatrixXd& K)
{
  const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
  int zero = 0;
  for (double lambda : eigenvalues)
    zero += std::abs(lambda) < 1e-10 * eigenvalues.maxCoeff();
  return zero;
}

TEST_P(PlanarCells, StiffnessIsSymmetricWithTheRigidModesOfEachFormulationInItsKernel)
{
  const CellKind kind = GetParam();
  const Eigen::MatrixX3d X = affine_cell(kind);
  const Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(X.rows(), 3);
  for (const PlanarKind planar : {PlanarKind::plane_strain, PlanarKind::plane_stress, PlanarKind::axisymmetric})
  {
    const InPlane e = in_plane_element(kind, X, u, {planar, 0.5}, fem::Kinematics::linear);
    EXPECT_LT((e.K - e.K.transpose()).norm(), 1e-12 * e.K.norm());
    // Plane: two translations and the rotation about z. Axisymmetric: the axial translation
    // only (a radial motion strains the hoops).
    EXPECT_EQ(zero_eigenvalues(e.K), planar == PlanarKind::axisymmetric ? 1 : 3) << mesh::planar_name(planar);
    Eigen::VectorXd axial = Eigen::VectorXd::Zero(e.K.rows());
    for (Eigen::Index a = 0; a < X.rows(); ++a)
      axial(2 * a + 1) = 1;
    EXPECT_LT((e.K * axial).norm(), 1e-12 * e.K.norm());
  }
}

TEST_P(PlanarCells, HomogeneousStrainGivesHookesStressInEachFormulation)
{
  const CellKind kind = GetParam();
  const Eigen::MatrixX3d X = affine_cell(kind);
  const double exx = 1e-3, eyy = -4e-4, gxy = 6e-4;
  Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(X.rows(), 3);
  for (Eigen::Index a = 0; a < X.rows(); ++a)
    u.row(a) << exx * X(a, 0) + gxy * X(a, 1), eyy * X(a, 1), 0;
  const double E = steel.young, nu = steel.poisson;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  for (const PlanarKind planar : {PlanarKind::plane_strain, PlanarKind::plane_stress, PlanarKind::axisymmetric})
  {
    const fem::CellPointResults r = fem::cell_point_results(kind, X, u, steel, fem::Kinematics::linear,
                                                            fem::Integration::full, 0, nullptr, {}, {planar, 1});
    for (size_t q = 0; q < r.stress.size(); ++q)
    {
      Eigen::Matrix<double, 6, 1> expected;
      if (planar == PlanarKind::plane_stress)
      {
        const double c = E / (1 - nu * nu);
        expected << c * (exx + nu * eyy), c * (eyy + nu * exx), 0, mu * gxy, 0, 0;
      }
      else
      {
        // Axisymmetric: u_r = exx r + gxy z gives the hoop strain u_r / r at the point.
        double ezz = 0;
        if (planar == PlanarKind::axisymmetric)
        {
          const Eigen::Vector3d x = X.transpose() * fem::shape_values(kind, fem::quadrature(kind).points[q]);
          ezz = exx + gxy * x(1) / x(0);
        }
        const double tr = exx + eyy + ezz;
        expected << lambda * tr + 2 * mu * exx, lambda * tr + 2 * mu * eyy, lambda * tr + 2 * mu * ezz, mu * gxy, 0, 0;
      }
      EXPECT_LT((r.stress[q] - expected).norm(), 1e-9 * expected.norm()) << mesh::planar_name(planar) << " point " << q;
    }
  }
}

TEST_P(PlanarCells, TangentIsTheDerivativeOfTheInternalForceWithLargeDisplacements)
{
  const CellKind kind = GetParam();
  const Eigen::MatrixX3d X = affine_cell(kind);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> d(-0.02, 0.02);
  Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(X.rows(), 3);
  for (Eigen::Index a = 0; a < X.rows(); ++a)
    u.row(a) << d(rng), d(rng), 0;
  for (const PlanarKind planar : {PlanarKind::plane_strain, PlanarKind::plane_stress, PlanarKind::axisymmetric})
  {
    const InPlane e = in_plane_element(kind, X, u, {planar, 0.5}, fem::Kinematics::total_lagrangian);
    EXPECT_LT((e.K - e.K.transpose()).norm(), 1e-10 * e.K.norm());
    const double h = 1e-7;
    for (Eigen::Index a = 0; a < X.rows(); ++a)
      for (int i = 0; i < 2; ++i)
      {
        Eigen::MatrixX3d up = u, um = u;
        up(a, i) += h;
        um(a, i) -= h;
        const Eigen::VectorXd fd = (in_plane_element(kind, X, up, {planar, 0.5}, fem::Kinematics::total_lagrangian).f -
                                    in_plane_element(kind, X, um, {planar, 0.5}, fem::Kinematics::total_lagrangian).f) /
            (2 * h);
        EXPECT_LT((fd - e.K.col(2 * a + i)).norm(), 1e-6 * e.K.norm())
            << mesh::planar_name(planar) << " node " << a << " component " << i;
      }
  }
}

TEST_P(PlanarCells, RigidMotionsHaveNoInternalForceWithLargeDisplacements)
{
  const CellKind kind = GetParam();
  const Eigen::MatrixX3d X = affine_cell(kind);
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::MatrixX3d rotated = X * (Q - Eigen::Matrix3d::Identity()).transpose();
  for (const PlanarKind planar : {PlanarKind::plane_strain, PlanarKind::plane_stress})
  {
    const InPlane e = in_plane_element(kind, X, rotated, {planar, 1}, fem::Kinematics::total_lagrangian);
    EXPECT_LT(e.f.norm(), 1e-12 * e.K.norm() * X.norm()) << mesh::planar_name(planar);
  }
  Eigen::MatrixX3d axial = Eigen::MatrixX3d::Zero(X.rows(), 3);
  axial.col(1).setConstant(0.3);
  const InPlane e = in_plane_element(kind, X, axial, {PlanarKind::axisymmetric, 1}, fem::Kinematics::total_lagrangian);
  EXPECT_LT(e.f.norm(), 1e-12 * e.K.norm() * X.norm());
}

INSTANTIATE_TEST_SUITE_P(AllTypes, PlanarCells, ::testing::ValuesIn(mesh::planar_cell_kinds),
                         [](const auto& info) { return std::string(mesh::cell_type(info.param).name); });

TEST(PlanarCell, VolumeIsTheAreaTimesThicknessOrTheSolidOfRevolution)
{
  // A unit square at x in [1, 2]: volume t (plane) and 2 pi * 1.5 (Pappus) in axisymmetry.
  Eigen::MatrixX3d X(4, 3);
  X << 1, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0;
  const Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(4, 3);
  const auto volume = [&](const Planar& planar) {
    double v = 0;
    for (const double w : fem::cell_point_results(CellKind::quad4, X, u, steel, fem::Kinematics::linear,
                                                  fem::Integration::full, 0, nullptr, {}, planar)
                              .weight)
      v += w;
    return v;
  };
  EXPECT_NEAR(volume({PlanarKind::plane_strain, 0.25}), 0.25, 1e-15);
  EXPECT_NEAR(volume({PlanarKind::axisymmetric, 1}), 2 * std::numbers::pi * 1.5, 1e-13);
}

TEST(PlanarCell, ClockwiseCellAndAxisymmetricCellLeftOfTheAxisAreNamed)
{
  Eigen::MatrixX3d X(3, 3);
  X << 0, 0, 0, 0, 1, 0, 1, 0, 0; // clockwise
  Eigen::VectorXd f;
  Eigen::MatrixXd K;
  EXPECT_THROW(fem::cell_element(CellKind::tri3, X, Eigen::MatrixX3d::Zero(3, 3), steel, fem::Kinematics::linear,
                                 fem::StiffnessKind::material, fem::Integration::full, f, &K, 7, nullptr, nullptr,
                                 {PlanarKind::plane_strain, 1}),
               Error);
  X << -2, 0, 0, -1, 0, 0, -1, 1, 0; // counter-clockwise at x < 0
  EXPECT_THROW(fem::cell_element(CellKind::tri3, X, Eigen::MatrixX3d::Zero(3, 3), steel, fem::Kinematics::linear,
                                 fem::StiffnessKind::material, fem::Integration::full, f, &K, 7, nullptr, nullptr,
                                 {PlanarKind::axisymmetric, 1}),
               Error);
  // A 2D cell without a planar formulation.
  EXPECT_THROW(fem::cell_element(CellKind::tri3, X, Eigen::MatrixX3d::Zero(3, 3), steel, fem::Kinematics::linear,
                                 fem::StiffnessKind::material, fem::Integration::full, f, &K, 7),
               Error);
}
} // namespace planar_element_test
} // namespace feticon
