/// Element-level verification of the hex8 linear and total Lagrangian element
/// (ALGORITHMS.md section 7, verification checklist).

#include "common/error.hpp"
#include "fem/hex8_element.hpp"
#include "fem_test_meshes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace feticon;
using fem::ElementMatrix;
using fem::ElementVector;
using fem::NodeCoords;

namespace
{
NodeCoords cell_coords(const mesh::Mesh& m, int c)
{
  NodeCoords X;
  for (int a = 0; a < 8; ++a)
    X.row(a) = m.nodes.row(m.cells[c][a]);
  return X;
}

NodeCoords apply_map(const NodeCoords& X, const Eigen::Matrix3d& grad, const Eigen::Vector3d& t)
{
  NodeCoords u;
  for (int a = 0; a < 8; ++a)
    u.row(a) = (grad * X.row(a).transpose() + t).transpose();
  return u;
}

ElementVector internal_force(const NodeCoords& X, const NodeCoords& u, const fem::Material& mat)
{
  ElementVector f;
  fem::hex8_element(X, u, mat, fem::Kinematics::total_lagrangian, fem::StiffnessKind::none, f, nullptr, 0);
  return f;
}

Eigen::Matrix3d rotation(double angle, Eigen::Vector3d axis)
{
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}
} // namespace

// Reference: partition of unity, sum_a N_a = 1 and sum_a grad N_a = 0 at any point.
TEST(Hex8, ShapeFunctionsPartitionOfUnity)
{
  const Eigen::Vector3d xi(0.3, -0.7, 0.1);
  EXPECT_NEAR(fem::hex8_shape(xi).sum(), 1.0, 1e-15);
  EXPECT_LT(fem::hex8_reference_gradients(xi).colwise().sum().norm(), 1e-15);
}

// Reference: a rigid rotation has E = 0, hence S = 0 and f_int = 0 exactly in TL
// (ALGORITHMS.md 7, check 2). Scale: the force of a 1% uniaxial stretch.
TEST(Hex8, RigidRotationGivesZeroInternalForce)
{
  const auto m = test::distorted_patch();
  const fem::Material mat{2e11, 0.3};
  for (int c = 0; c < m.n_cells(); ++c)
  {
    const NodeCoords X = cell_coords(m, c);
    const Eigen::Matrix3d R = rotation(M_PI / 2, Eigen::Vector3d(1, 2, 3));
    const NodeCoords u = apply_map(X, R - Eigen::Matrix3d::Identity(), Eigen::Vector3d(1, -2, 3));
    Eigen::Matrix3d stretch = Eigen::Matrix3d::Zero();
    stretch(0, 0) = 0.01;
    const double scale = internal_force(X, apply_map(X, stretch, Eigen::Vector3d::Zero()), mat).norm();
    EXPECT_LT(internal_force(X, u, mat).norm() / scale, 1e-10) << "cell " << c;
  }
}

// Reference: closed-form St Venant–Kirchhoff uniaxial stress. Stretch lambda = 1.5 in x,
// lateral stretch from S22 = S33 = 0: E22 = -nu E11, i.e. lambda_t = sqrt(1 - nu (lambda^2 - 1)).
// Then S11 = E_Y E11 and the first Piola–Kirchhoff traction on the x = 1 face is
// P11 = lambda S11 per unit reference area; lateral faces carry no force.
TEST(Hex8, UniaxialStretchMatchesClosedFormStVenantKirchhoff)
{
  const auto m = test::unit_cube();
  const fem::Material mat{2e11, 0.3};
  const double lambda = 1.5;
  const double E11 = 0.5 * (lambda * lambda - 1);
  const double lambda_t = std::sqrt(1 - mat.poisson * (lambda * lambda - 1));
  const NodeCoords X = cell_coords(m, 0);
  const Eigen::Matrix3d grad = Eigen::Vector3d(lambda - 1, lambda_t - 1, lambda_t - 1).asDiagonal();
  const ElementVector f = internal_force(X, apply_map(X, grad, Eigen::Vector3d::Zero()), mat);
  const double P11 = lambda * mat.young * E11; // times unit area
  for (int a = 0; a < 8; ++a)
  {
    // Constant traction on a unit square face: each node carries a quarter.
    const double expected_x = (X(a, 0) > 0.5 ? 0.25 : -0.25) * P11;
    EXPECT_NEAR(f(3 * a), expected_x, 1e-10 * P11) << "node " << a;
    EXPECT_NEAR(f(3 * a + 1), 0.0, 1e-10 * P11) << "node " << a;
    EXPECT_NEAR(f(3 * a + 2), 0.0, 1e-10 * P11) << "node " << a;
  }
  // Cauchy stress: sigma11 = P11 * lambda / det F = lambda^2 S11 / (lambda lambda_t^2).
  const auto sigma = fem::hex8_cauchy_stress(X, apply_map(X, grad, Eigen::Vector3d::Zero()), mat,
                                             fem::Kinematics::total_lagrangian, 0);
  EXPECT_NEAR(sigma(0), lambda * mat.young * E11 / (lambda_t * lambda_t), 1e-10 * P11);
  EXPECT_NEAR(sigma(1), 0.0, 1e-10 * P11);
}

// Reference: central finite differences of f_int (ALGORITHMS.md 7, check 3) at a strongly
// deformed state: rotation by 40 degrees, 20% stretch and a random perturbation.
TEST(Hex8, ConsistentTangentMatchesFiniteDifference)
{
  const auto m = test::distorted_patch();
  const fem::Material mat{2e11, 0.3};
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> dist(-1, 1);
  for (int c : {0, 5})
  {
    const NodeCoords X = cell_coords(m, c);
    const Eigen::Matrix3d grad =
        rotation(40 * M_PI / 180, Eigen::Vector3d(0.2, 1, 0.5)) * Eigen::Vector3d(1.2, 0.9, 1.05).asDiagonal() -
        Eigen::Matrix3d::Identity();
    NodeCoords u = apply_map(X, grad, Eigen::Vector3d::Zero());
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i)
        u(a, i) += 0.02 * dist(gen);
    ElementVector f;
    ElementMatrix K;
    fem::hex8_element(X, u, mat, fem::Kinematics::total_lagrangian, fem::StiffnessKind::tangent, f, &K, c);
    ElementMatrix K_fd;
    const double h = 1e-6 * u.norm();
    for (int j = 0; j < 24; ++j)
    {
      NodeCoords up = u, um = u;
      up(j / 3, j % 3) += h;
      um(j / 3, j % 3) -= h;
      K_fd.col(j) = (internal_force(X, up, mat) - internal_force(X, um, mat)) / (2 * h);
    }
    EXPECT_LT((K - K_fd).norm() / K.norm(), 1e-6) << "cell " << c;
    EXPECT_LT((K - K.transpose()).norm() / K.norm(), 1e-13) << "tangent must be symmetric";
  }
}

// Reference: the kernel of K_M(u) is spanned by the rigid modes of the current coordinates
// x = X + u (ALGORITHMS.md 2, "Which stiffness in TL"), while K_T is not.
TEST(Hex8, MaterialStiffnessKernelIsRigidModesOfCurrentConfiguration)
{
  const auto m = test::distorted_patch();
  const fem::Material mat{2e11, 0.3};
  const NodeCoords X = cell_coords(m, 3);
  const Eigen::Matrix3d grad = rotation(0.7, Eigen::Vector3d(1, 1, 0)) * Eigen::Vector3d(1.1, 0.95, 1.0).asDiagonal() -
      Eigen::Matrix3d::Identity();
  const NodeCoords u = apply_map(X, grad, Eigen::Vector3d::Zero());
  ElementVector f;
  ElementMatrix K_M, K_T;
  fem::hex8_element(X, u, mat, fem::Kinematics::total_lagrangian, fem::StiffnessKind::material, f, &K_M, 3);
  fem::hex8_element(X, u, mat, fem::Kinematics::total_lagrangian, fem::StiffnessKind::tangent, f, &K_T, 3);
  Eigen::Matrix<double, 24, 6> R = Eigen::Matrix<double, 24, 6>::Zero();
  for (int a = 0; a < 8; ++a)
  {
    const Eigen::Vector3d x = (X.row(a) + u.row(a)).transpose();
    R.block<3, 3>(3 * a, 0).setIdentity();
    R.block<3, 3>(3 * a, 3) << 0, x(2), -x(1), -x(2), 0, x(0), x(1), -x(0), 0;
  }
  EXPECT_LT((K_M * R).norm() / (K_M.norm() * R.norm()), 1e-12);
  EXPECT_GT((K_T * R.rightCols<3>()).norm() / (K_T.norm() * R.norm()), 1e-6);
}

// Reference: at u = 0 the TL element reduces to the small-strain element (same K, f = K u
// for the linear element).
TEST(Hex8, LinearElementIsTotalLagrangianAtZero)
{
  const auto m = test::distorted_patch();
  const fem::Material mat{1e9, 0.25};
  const NodeCoords X = cell_coords(m, 6);
  ElementVector f;
  ElementMatrix K_lin, K_tl;
  const NodeCoords zero = NodeCoords::Zero();
  fem::hex8_element(X, zero, mat, fem::Kinematics::linear, fem::StiffnessKind::tangent, f, &K_lin, 6);
  fem::hex8_element(X, zero, mat, fem::Kinematics::total_lagrangian, fem::StiffnessKind::tangent, f, &K_tl, 6);
  EXPECT_LT((K_lin - K_tl).norm() / K_lin.norm(), 1e-14);
  NodeCoords u = NodeCoords::Random() * 1e-3;
  fem::hex8_element(X, u, mat, fem::Kinematics::linear, fem::StiffnessKind::none, f, nullptr, 6);
  const Eigen::Matrix<double, 3, 8> u_nodes = u.transpose(); // node-major, as element DOFs
  Eigen::Map<const Eigen::Matrix<double, 24, 1>> u_vec(u_nodes.data());
  EXPECT_LT((f - K_lin * u_vec).norm() / f.norm(), 1e-12);
}

// Failure path: an inverted element is reported, not integrated.
TEST(Hex8, InvertedElementIsRejected)
{
  auto m = test::unit_cube();
  NodeCoords X = cell_coords(m, 0);
  X.row(6) = Eigen::RowVector3d(-1, -1, -1); // pull a corner through the cell
  ElementVector f;
  EXPECT_THROW(fem::hex8_element(X, NodeCoords::Zero(), fem::Material{}, fem::Kinematics::linear,
                                 fem::StiffnessKind::none, f, nullptr, 42),
               feticon::Error);
}

// Failure path: a deformation that turns the element inside out (det F < 0) stops the TL
// element with a message naming the element, instead of producing a meaningless force.
TEST(Hex8, ElementInvertedByTheDeformationIsRejected)
{
  const auto m = test::unit_cube();
  const NodeCoords X = cell_coords(m, 0);
  const Eigen::Matrix3d mirror = Eigen::Vector3d(-2, 0, 0).asDiagonal(); // x -> -x
  ElementVector f;
  try
  {
    fem::hex8_element(X, apply_map(X, mirror, Eigen::Vector3d::Zero()), fem::Material{},
                      fem::Kinematics::total_lagrangian, fem::StiffnessKind::none, f, nullptr, 7);
    FAIL() << "no error for det F < 0";
  }
  catch (const feticon::Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("element 7 is inverted in the deformed"), std::string::npos);
  }
}
