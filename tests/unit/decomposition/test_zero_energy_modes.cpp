/// zero_energy_modes (decomposition/rigid_body_modes.hpp): the kernel of a subdomain's K taken
/// from the matrix where the rigid-body modes are not all of it. Reference: the 8-node
/// serendipity quadrilateral with 2 x 2 (reduced) Gauss integration has exactly one zero-energy
/// mode besides the three in-plane rigid motions, which full 3 x 3 integration removes (Cook,
/// Malkus, Plesha and Witt, Concepts and Applications of Finite Element Analysis, 4th ed.,
/// section 6.8); the hex8 with full integration has none besides its six rigid motions.

#include "decomposition/rigid_body_modes.hpp"
#include "fem/cell_element.hpp"
#include "mesh/cell_type.hpp"

#include <gtest/gtest.h>

namespace feticon
{
namespace
{
/// The stiffness of one cell of `kind` on its reference nodes (scaled by 2 and skewed a little,
/// so that nothing is special about the geometry), restricted to the DOFs `components` of each
/// node, lower triangle.
la::SparseMatrix one_cell_stiffness(mesh::CellKind kind, fem::Integration integration, int components)
{
  const auto& ref = mesh::cell_type(kind).reference_nodes;
  Eigen::MatrixX3d X(static_cast<Eigen::Index>(ref.size()), 3);
  for (size_t a = 0; a < ref.size(); ++a)
    X.row(static_cast<Eigen::Index>(a)) << 2 * ref[a][0] + 0.3 * ref[a][1], 2 * ref[a][1], 2 * ref[a][2];
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

TEST(ZeroEnergyModes, ReducedQuad8HasOneBesidesTheRigidMotions)
{
  const la::SparseMatrix K = one_cell_stiffness(mesh::CellKind::quad8, fem::Integration::reduced, 2);
  const auto modes = decomposition::zero_energy_modes(K, 3);
  ASSERT_TRUE(modes.has_value());
  ASSERT_EQ(modes->cols(), 4);
  const la::Matrix full = la::Matrix(K).selfadjointView<Eigen::Lower>();
  EXPECT_LT((full * *modes).norm(), 1e-9 * full.norm());
  EXPECT_LT((modes->transpose() * *modes - la::Matrix::Identity(4, 4)).norm(), 1e-12);
}

TEST(ZeroEnergyModes, NoneWhereTheRigidMotionsAreTheKernel)
{
  EXPECT_FALSE(
      decomposition::zero_energy_modes(one_cell_stiffness(mesh::CellKind::quad8, fem::Integration::full, 2), 3));
  EXPECT_FALSE(
      decomposition::zero_energy_modes(one_cell_stiffness(mesh::CellKind::hex8, fem::Integration::full, 3), 6));
}

TEST(ZeroEnergyModes, NoneForAnIndefiniteOrTooLargeMatrix)
{
  la::SparseMatrix indefinite(2, 2);
  indefinite.insert(0, 0) = 1;
  indefinite.insert(1, 1) = -1;
  EXPECT_FALSE(decomposition::zero_energy_modes(indefinite, 0));
  la::SparseMatrix zero(decomposition::max_dense_kernel_dofs + 1, decomposition::max_dense_kernel_dofs + 1);
  EXPECT_FALSE(decomposition::zero_energy_modes(zero, 0));
}
} // namespace
} // namespace feticon
