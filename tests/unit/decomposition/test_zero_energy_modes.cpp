/// zero_energy_modes (decomposition/rigid_body_modes.hpp): the kernel of a subdomain's K taken
/// from the matrix where the rigid-body modes are not all of it. Reference: the 8-node
/// serendipity quadrilateral with 2 x 2 (reduced) Gauss integration has exactly one zero-energy
/// mode besides the three in-plane rigid motions, which full 3 x 3 integration removes (Cook,
/// Malkus, Plesha and Witt, Concepts and Applications of Finite Element Analysis, 4th ed.,
/// section 6.8); the hex8 with full integration has none besides its six rigid motions. And
/// GeneralizedInverse refuses such a K with the rigid motions alone as its kernel, where the
/// Cholesky factorization may pass on a pivot at round-off.

#include "decomposition/generalized_inverse.hpp"
#include "decomposition/rigid_body_modes.hpp"
#include "fem/cell_element.hpp"
#include "mesh/cell_type.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

namespace feticon
{
namespace
{
/// The stiffness of one cell of `kind` on its reference nodes (scaled by 2 and skewed a little,
/// so that nothing is special about the geometry), restricted to the DOFs `components` of each
/// node, lower triangle.
Eigen::MatrixX3d one_cell_nodes(mesh::CellKind kind)
{
  const auto& ref = mesh::cell_type(kind).reference_nodes;
  Eigen::MatrixX3d X(static_cast<Eigen::Index>(ref.size()), 3);
  for (size_t a = 0; a < ref.size(); ++a)
    X.row(static_cast<Eigen::Index>(a)) << 2 * ref[a][0] + 0.3 * ref[a][1], 2 * ref[a][1], 2 * ref[a][2];
  return X;
}

la::SparseMatrix one_cell_stiffness(mesh::CellKind kind, fem::Integration integration, int components)
{
  const Eigen::MatrixX3d X = one_cell_nodes(kind);
  const Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(X.rows(), 3);
  const mesh::Planar planar{components == 2 ? mesh::PlanarKind::plane_strain : mesh::PlanarKind::none, 1};
  Eigen::VectorXd f;
  Eigen::MatrixXd K;
  fem::cell_element(kind, X, u, fem::Material{2e11, 0.3}, fem::Kinematics::linear, fem::StiffnessKind::material,
                    integration, f, &K, 0, nullptr, nullptr, planar);
  const Eigen::Index n = X.rows() * components;
  la::Matrix active(n, n);
  for (Eigen::Index a = 0; a < X.rows(); ++a)
    for (Eigen::Index b = 0; b < X.rows(); ++b)
      for (int i = 0; i < components; ++i)
        for (int j = 0; j < components; ++j)
          active(components * a + i, components * b + j) = K(3 * a + i, 3 * b + j);
  return la::Matrix(active.triangularView<Eigen::Lower>()).sparseView();
}

/// The cell's rigid-body modes on its `components` DOFs a node (rigid_body_modes: orthonormal).
la::Matrix one_cell_rigid_modes(mesh::CellKind kind, int components)
{
  const Eigen::MatrixX3d X = one_cell_nodes(kind);
  std::vector<int32_t> full_of_active;
  for (Eigen::Index a = 0; a < X.rows(); ++a)
    for (int i = 0; i < components; ++i)
      full_of_active.push_back(static_cast<int32_t>(3 * a + i));
  return decomposition::rigid_body_modes(X, full_of_active);
}

TEST(ZeroEnergyModes, ReducedQuad8HasOneBesidesTheRigidMotions)
{
  const la::SparseMatrix K = one_cell_stiffness(mesh::CellKind::quad8, fem::Integration::reduced, 2);
  const la::Matrix R = one_cell_rigid_modes(mesh::CellKind::quad8, 2);
  const auto modes = decomposition::zero_energy_modes(K, R);
  ASSERT_TRUE(modes.has_value());
  ASSERT_EQ(modes->cols(), 4);
  EXPECT_EQ(modes->leftCols(3), R); // the rigid motions first, as given
  const la::Matrix full = la::Matrix(K).selfadjointView<Eigen::Lower>();
  EXPECT_LT((full * *modes).norm(), 1e-9 * full.norm());
  EXPECT_LT((modes->transpose() * *modes - la::Matrix::Identity(4, 4)).norm(), 1e-12);
}

// The eigenvectors of the 4-dimensional kernel turn arbitrarily with the round-off of K; the
// basis returned does not (up to the sign of its last column): K perturbed by 1e-14 of its
// largest entry gives the same modes to 1e-6 (an eigenvector basis differs by O(1)).
TEST(ZeroEnergyModes, TheBasisDoesNotTurnWithTheRoundOffOfK)
{
  const la::SparseMatrix K = one_cell_stiffness(mesh::CellKind::quad8, fem::Integration::reduced, 2);
  const la::Matrix R = one_cell_rigid_modes(mesh::CellKind::quad8, 2);
  la::Matrix noise = la::Matrix::Zero(K.rows(), K.cols());
  for (la::Index j = 0; j < K.cols(); ++j)
    for (la::Index i = j; i < K.rows(); ++i)
      noise(i, j) = std::sin(1.0 + 7.0 * static_cast<double>(i) + 3.0 * static_cast<double>(j));
  const double scale = la::Matrix(K).cwiseAbs().maxCoeff();
  const la::SparseMatrix perturbed = (la::Matrix(K) + 1e-14 * scale * noise).sparseView();
  const auto a = decomposition::zero_energy_modes(K, R);
  const auto b = decomposition::zero_energy_modes(perturbed, R);
  ASSERT_TRUE(a && b);
  ASSERT_EQ(a->cols(), b->cols());
  const la::Index last = a->cols() - 1;
  const double sign = a->col(last).dot(b->col(last)) < 0 ? -1.0 : 1.0;
  EXPECT_LT((a->col(last) - sign * b->col(last)).norm(), 1e-6);
}

TEST(ZeroEnergyModes, NoneWhereTheRigidMotionsAreTheKernel)
{
  EXPECT_FALSE(decomposition::zero_energy_modes(one_cell_stiffness(mesh::CellKind::quad8, fem::Integration::full, 2),
                                                one_cell_rigid_modes(mesh::CellKind::quad8, 2)));
  EXPECT_FALSE(decomposition::zero_energy_modes(one_cell_stiffness(mesh::CellKind::hex8, fem::Integration::full, 3),
                                                one_cell_rigid_modes(mesh::CellKind::hex8, 3)));
}

// With the rigid motions as its kernel, the reduced quad8's K less three fixing DOFs still has
// the hourglass mode: refused in one line, whether or not its Cholesky factorization passed.
TEST(ZeroEnergyModes, GeneralizedInverseRefusesAKernelLargerThanItsModes)
{
  const la::SparseMatrix K_lower = one_cell_stiffness(mesh::CellKind::quad8, fem::Integration::reduced, 2);
  const la::SparseMatrix K =
      la::SparseMatrix(la::Matrix(K_lower).selfadjointView<Eigen::Lower>().toDenseMatrix().sparseView());
  const la::Matrix R = one_cell_rigid_modes(mesh::CellKind::quad8, 2);
  std::vector<int32_t> candidates(static_cast<size_t>(K.rows()));
  std::iota(candidates.begin(), candidates.end(), 0);
  decomposition::GeneralizedInverse K_plus;
  EXPECT_THROW(K_plus.setup(K, R, candidates, decomposition::GeneralizedInverseMethod::fixing_dofs, "one cell"), Error);
  const auto modes = decomposition::zero_energy_modes(K_lower, R);
  ASSERT_TRUE(modes.has_value());
  EXPECT_NO_THROW(
      K_plus.setup(K, *modes, candidates, decomposition::GeneralizedInverseMethod::fixing_dofs, "one cell"));
}

TEST(ZeroEnergyModes, NoneForAnIndefiniteOrTooLargeMatrix)
{
  la::SparseMatrix indefinite(2, 2);
  indefinite.insert(0, 0) = 1;
  indefinite.insert(1, 1) = -1;
  EXPECT_FALSE(decomposition::zero_energy_modes(indefinite, la::Matrix(2, 0)));
  la::SparseMatrix zero(decomposition::max_dense_kernel_dofs + 1, decomposition::max_dense_kernel_dofs + 1);
  EXPECT_FALSE(decomposition::zero_energy_modes(zero, la::Matrix(zero.rows(), 0)));
}
} // namespace
} // namespace feticon
