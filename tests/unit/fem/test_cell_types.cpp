/// The cell types of issue 38 (mesh/cell_type.hpp, fem/reference_element.hpp,
/// fem/cell_element.hpp), each on its own. References: the Kronecker and partition-of-unity
/// properties of nodal shape functions, central finite differences for their gradients,
/// closed-form integrals of monomials over the reference cells (unit tetrahedron:
/// a! b! c! / (a + b + c + 3)!), the rigid-body modes (K r = 0, exactly six zero eigenvalues),
/// a linear displacement reproducing its constant strain at every quadrature point (the
/// element-level patch test), and the hex8 element of hex8_element.hpp for the generic one.

#include "common/error.hpp"
#include "fem/cell_element.hpp"
#include "fem/hex8_element.hpp"
#include "mesh/cell_type.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace feticon
{
namespace
{
using mesh::CellKind;

std::string name(CellKind kind) { return std::string(mesh::cell_type(kind).name); }

Eigen::Vector3d reference_node(CellKind kind, int a)
{
  const auto& p = mesh::cell_type(kind).reference_nodes[a];
  return {p[0], p[1], p[2]};
}

/// A point inside the reference cell.
Eigen::Vector3d inside(CellKind kind, std::mt19937& rng)
{
  std::uniform_real_distribution<double> d(0.05, 0.3);
  if (kind == CellKind::tet4 || kind == CellKind::tet10)
    return {d(rng), d(rng), d(rng)};
  if (kind == CellKind::wedge6)
    return {d(rng), d(rng), 2 * d(rng) - 0.3};
  return {3 * d(rng) - 0.5, 3 * d(rng) - 0.5, 3 * d(rng) - 0.5};
}

double reference_volume(CellKind kind)
{
  return kind == CellKind::tet4 || kind == CellKind::tet10 ? 1.0 / 6 : kind == CellKind::wedge6 ? 1.0 : 8.0;
}

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }
double interval_moment(int p) { return p % 2 ? 0.0 : 2.0 / (p + 1); } // int_-1^1 x^p

/// int x^a y^b z^c over the reference cell, in closed form.
double monomial_integral(CellKind kind, int a, int b, int c)
{
  if (kind == CellKind::tet4 || kind == CellKind::tet10)
    return factorial(a) * factorial(b) * factorial(c) / factorial(a + b + c + 3);
  if (kind == CellKind::wedge6) // triangle: a! b! / (a + b + 2)!
    return factorial(a) * factorial(b) / factorial(a + b + 2) * interval_moment(c);
  return interval_moment(a) * interval_moment(b) * interval_moment(c);
}

/// Whether the full rule of `kind` must integrate x^a y^b z^c exactly: the degree its
/// stiffness needs on an undistorted cell.
bool exact_for(CellKind kind, int a, int b, int c)
{
  switch (kind)
  {
  case CellKind::hex8:
    return a <= 3 && b <= 3 && c <= 3;
  case CellKind::hex20:
    return a <= 5 && b <= 5 && c <= 5;
  case CellKind::tet4:
    return a + b + c <= 1;
  case CellKind::tet10:
    return a + b + c <= 2;
  case CellKind::wedge6:
    return a + b <= 2 && c <= 3;
  default: // 2D cells: test_planar_elements.cpp
    return false;
  }
}

class CellTypes : public ::testing::TestWithParam<CellKind>
{
};

TEST_P(CellTypes, TableIsConsistentAndFacesPointOut)
{
  const mesh::CellType& type = mesh::cell_type(GetParam());
  ASSERT_EQ(static_cast<int>(type.reference_nodes.size()), type.n_nodes);
  EXPECT_EQ(mesh::cell_type_of_gmsh_type(type.gmsh_type), &type);
  EXPECT_EQ(mesh::cell_type_of_calculix_name(type.calculix_names.front()), &type);
  EXPECT_EQ(static_cast<int>(type.gmsh_to_local.size()), type.n_nodes);
  EXPECT_EQ(static_cast<int>(type.vtk_to_local.size()), type.n_nodes);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int a = 0; a < type.n_corners; ++a)
    centre += reference_node(type.kind, a) / type.n_corners;
  for (const mesh::CellFace& face : type.faces)
  {
    ASSERT_EQ(static_cast<int>(face.nodes.size()), mesh::face_nodes(face.kind));
    const int corners = mesh::face_corners(face.kind);
    const Eigen::Vector3d x0 = reference_node(type.kind, face.nodes[0]);
    const Eigen::Vector3d normal =
        (reference_node(type.kind, face.nodes[1]) - x0).cross(reference_node(type.kind, face.nodes[corners - 1]) - x0);
    EXPECT_GT(normal.dot(x0 - centre), 0) << "face " << &face - type.faces.data();
    // A quadratic face's edge nodes lie midway along its own edges, in order.
    for (int k = corners; k < static_cast<int>(face.nodes.size()); ++k)
    {
      const Eigen::Vector3d mid = 0.5 *
          (reference_node(type.kind, face.nodes[k - corners]) +
           reference_node(type.kind, face.nodes[(k - corners + 1) % corners]));
      EXPECT_LT((reference_node(type.kind, face.nodes[k]) - mid).norm(), 1e-15);
    }
  }
}

TEST_P(CellTypes, ShapeFunctionsAreNodalPartitionOfUnityWithConsistentGradients)
{
  const CellKind kind = GetParam();
  const int n = mesh::cell_type(kind).n_nodes;
  for (int b = 0; b < n; ++b)
  {
    const Eigen::VectorXd N = fem::shape_values(kind, reference_node(kind, b));
    for (int a = 0; a < n; ++a)
      EXPECT_NEAR(N(a), a == b ? 1.0 : 0.0, 1e-14) << "N_" << a << " at node " << b;
  }
  std::mt19937 rng(7);
  for (int trial = 0; trial < 5; ++trial)
  {
    const Eigen::Vector3d xi = inside(kind, rng);
    EXPECT_NEAR(fem::shape_values(kind, xi).sum(), 1.0, 1e-14);
    const Eigen::MatrixX3d dN = fem::shape_gradients(kind, xi);
    EXPECT_LT(dN.colwise().sum().norm(), 1e-13);
    const double h = 1e-6;
    for (int j = 0; j < 3; ++j)
    {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(j);
      const Eigen::VectorXd fd = (fem::shape_values(kind, xi + e) - fem::shape_values(kind, xi - e)) / (2 * h);
      EXPECT_LT((fd - dN.col(j)).cwiseAbs().maxCoeff(), 1e-8) << "d/dxi_" << j;
    }
  }
}

TEST_P(CellTypes, QuadratureIntegratesTheNeededMonomials)
{
  const CellKind kind = GetParam();
  const fem::QuadratureRule& rule = fem::quadrature(kind);
  double volume = 0;
  for (double w : rule.weights)
    volume += w;
  EXPECT_NEAR(volume, reference_volume(kind), 1e-14);
  for (int a = 0; a <= 5; ++a)
    for (int b = 0; b <= 5; ++b)
      for (int c = 0; c <= 5; ++c)
      {
        if (!exact_for(kind, a, b, c))
          continue;
        double sum = 0;
        for (size_t q = 0; q < rule.points.size(); ++q)
          sum += rule.weights[q] * std::pow(rule.points[q].x(), a) * std::pow(rule.points[q].y(), b) *
              std::pow(rule.points[q].z(), c);
        EXPECT_NEAR(sum, monomial_integral(kind, a, b, c), 1e-13) << "x^" << a << " y^" << b << " z^" << c;
      }
}

/// The reference nodes mapped by x = M xi + c: a general straight-edged cell of positive
/// orientation, its edge nodes at the midpoints.
Eigen::MatrixX3d affine_cell(CellKind kind)
{
  Eigen::Matrix3d M;
  M << 1.0, 0.2, -0.1, 0.15, 0.8, 0.1, -0.05, 0.1, 1.2;
  const Eigen::Vector3d c(0.3, -0.2, 0.5);
  Eigen::MatrixX3d X(mesh::cell_type(kind).n_nodes, 3);
  for (int a = 0; a < X.rows(); ++a)
    X.row(a) = (M * reference_node(kind, a) + c).transpose();
  return X;
}

Eigen::MatrixXd rigid_modes(const Eigen::MatrixX3d& X)
{
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(3 * X.rows(), 6);
  for (Eigen::Index a = 0; a < X.rows(); ++a)
  {
    R.block<3, 3>(3 * a, 0).setIdentity();
    const Eigen::Vector3d x = X.row(a).transpose();
    for (int j = 0; j < 3; ++j)
      R.block<3, 1>(3 * a, 3 + j) = Eigen::Vector3d::Unit(j).cross(x);
  }
  return R;
}

TEST_P(CellTypes, StiffnessIsSymmetricWithExactlyTheRigidModesInItsKernel)
{
  const CellKind kind = GetParam();
  const Eigen::MatrixX3d X = affine_cell(kind);
  const Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(X.rows(), 3);
  Eigen::VectorXd f;
  Eigen::MatrixXd K;
  fem::cell_element(kind, X, u, fem::Material{2e11, 0.3}, fem::Kinematics::linear, fem::StiffnessKind::material,
                    fem::Integration::full, f, &K, 0);
  EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
  EXPECT_LT((K * rigid_modes(X)).norm(), 1e-11 * K.norm());
  const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
  int zero = 0;
  for (double lambda : eigenvalues)
    zero += std::abs(lambda) < 1e-10 * eigenvalues.maxCoeff();
  EXPECT_EQ(zero, 6) << "full integration: no zero-energy mode besides the rigid ones";
}

TEST_P(CellTypes, LinearDisplacementGivesItsConstantStrainInBothFormulations)
{
  const CellKind kind = GetParam();
  const Eigen::MatrixX3d X = affine_cell(kind);
  Eigen::Matrix3d A;
  A << 1e-3, 2e-3, -1e-3, 0.5e-3, -2e-3, 1e-3, 3e-3, 0.2e-3, 1.5e-3;
  const Eigen::MatrixX3d u = X * A.transpose(); // u = A X
  const Eigen::Matrix3d eps = 0.5 * (A + A.transpose());
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + A;
  const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
  for (const fem::Kinematics kinematics : {fem::Kinematics::linear, fem::Kinematics::total_lagrangian})
  {
    const Eigen::Matrix3d& expected = kinematics == fem::Kinematics::linear ? eps : E;
    Eigen::Matrix<double, 6, 1> voigt;
    voigt << expected(0, 0), expected(1, 1), expected(2, 2), 2 * expected(0, 1), 2 * expected(1, 2), 2 * expected(2, 0);
    for (const auto& strain : fem::cell_point_strains(kind, X, u, kinematics, fem::Integration::full, 0))
      EXPECT_LT((strain - voigt).norm(), 1e-15 + 1e-12 * voigt.norm());
  }
}

TEST_P(CellTypes, RigidRotationHasNoInternalForceWithLargeDisplacements)
{
  const CellKind kind = GetParam();
  const Eigen::MatrixX3d X = affine_cell(kind);
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::MatrixX3d u = X * (Q - Eigen::Matrix3d::Identity()).transpose();
  Eigen::VectorXd f;
  Eigen::MatrixXd K;
  fem::cell_element(kind, X, u, fem::Material{2e11, 0.3}, fem::Kinematics::total_lagrangian,
                    fem::StiffnessKind::tangent, fem::Integration::full, f, &K, 0);
  EXPECT_LT(f.norm(), 1e-12 * K.norm() * X.norm());
  // The rigid modes of the current configuration x = X + u span K_T's kernel (S = 0 there).
  EXPECT_LT((K * rigid_modes(X + u)).norm(), 1e-11 * K.norm());
}

// The 3D cells; the 2D ones are test_planar_elements.cpp's.
INSTANTIATE_TEST_SUITE_P(AllTypes, CellTypes, ::testing::ValuesIn(mesh::solid_cell_kinds),
                         [](const auto& info) { return name(info.param); });

TEST(CellElement, GenericHex8EqualsTheHex8Element)
{
  // A distorted hexahedron (corners moved off the affine image) under a non-affine displacement.
  Eigen::MatrixX3d X = affine_cell(CellKind::hex8);
  X(6, 0) += 0.1;
  X(3, 2) -= 0.08;
  Eigen::MatrixX3d u(8, 3);
  for (int a = 0; a < 8; ++a)
    u.row(a) << 1e-2 * std::sin(a), 2e-2 * std::cos(3.0 * a), -1e-2 * a * a / 49.0;
  fem::NodeCoords X8 = X, u8 = u;
  for (const fem::Kinematics kinematics : {fem::Kinematics::linear, fem::Kinematics::total_lagrangian})
  {
    fem::ElementVector f8;
    fem::ElementMatrix K8;
    fem::hex8_element(X8, u8, fem::Material{2e11, 0.3}, kinematics, fem::StiffnessKind::tangent, f8, &K8, 0);
    Eigen::VectorXd f;
    Eigen::MatrixXd K;
    fem::cell_element(CellKind::hex8, X, u, fem::Material{2e11, 0.3}, kinematics, fem::StiffnessKind::tangent,
                      fem::Integration::full, f, &K, 0);
    EXPECT_LT((f - f8).norm(), 1e-12 * f8.norm());
    EXPECT_LT((K - K8).norm(), 1e-12 * K8.norm());
  }
}

TEST(CellElement, InvertedCellIsNamed)
{
  Eigen::MatrixX3d X = affine_cell(CellKind::tet4);
  X.row(3).swap(X.row(2)); // two nodes swapped: negative orientation
  Eigen::VectorXd f;
  Eigen::MatrixXd K;
  EXPECT_THROW(fem::cell_element(CellKind::tet4, X, Eigen::MatrixX3d::Zero(4, 3), fem::Material{2e11, 0.3},
                                 fem::Kinematics::linear, fem::StiffnessKind::material, fem::Integration::full, f, &K,
                                 42),
               Error);
}
} // namespace
} // namespace feticon
