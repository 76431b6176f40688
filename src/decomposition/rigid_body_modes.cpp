#include "decomposition/rigid_body_modes.hpp"

#include "common/error.hpp"

namespace feticon::decomposition
{
la::Matrix rigid_body_modes(const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& coords,
                            const std::vector<int32_t>& full_of_active, bool axisymmetric)
{
  const la::Index n_nodes = coords.rows();
  FETICON_CHECK(n_nodes > 0, "rigid_body_modes: no nodes");
  const Eigen::RowVector3d centroid = coords.colwise().mean();
  la::Matrix full(3 * n_nodes, 6);
  for (la::Index n = 0; n < n_nodes; ++n)
  {
    const Eigen::RowVector3d p = coords.row(n) - centroid;
    full.block<3, 6>(3 * n, 0) << 1, 0, 0, 0, p(2), -p(1), //
        0, 1, 0, -p(2), 0, p(0),                           //
        0, 0, 1, p(1), -p(0), 0;
  }
  // Modes must vanish on eliminated DOFs: restrict to the null space of those rows.
  std::vector<char> active(3 * n_nodes, 0);
  for (int32_t f : full_of_active)
    active[f] = 1;
  std::vector<la::Index> eliminated_rows;
  for (la::Index f = 0; f < 3 * n_nodes; ++f)
    if (!active[f] || (axisymmetric && f % 3 == 0))
      eliminated_rows.push_back(f);
  la::Matrix basis = la::Matrix::Identity(6, 6);
  if (!eliminated_rows.empty())
  {
    la::Matrix R_elim(static_cast<la::Index>(eliminated_rows.size()), 6);
    for (size_t k = 0; k < eliminated_rows.size(); ++k)
      R_elim.row(static_cast<la::Index>(k)) = full.row(eliminated_rows[k]);
    Eigen::JacobiSVD<la::Matrix> svd(R_elim, Eigen::ComputeFullV);
    const double tol = 1e-10 * std::max(svd.singularValues()(0), 1.0);
    la::Index rank = 0;
    while (rank < svd.singularValues().size() && svd.singularValues()(rank) > tol)
      ++rank;
    basis = svd.matrixV().rightCols(6 - rank);
  }
  la::Matrix R(static_cast<la::Index>(full_of_active.size()), basis.cols());
  for (size_t k = 0; k < full_of_active.size(); ++k)
    R.row(static_cast<la::Index>(k)) = full.row(full_of_active[k]) * basis;
  if (R.cols() == 0)
    return R;
  // Orthonormal columns: the thin Q of a Householder QR.
  Eigen::HouseholderQR<la::Matrix> qr(R);
  return qr.householderQ() * la::Matrix::Identity(R.rows(), R.cols());
}

std::optional<la::Matrix> zero_energy_modes(const la::SparseMatrix& K_lower, const la::Matrix& rigid)
{
  const la::Index n = K_lower.rows();
  if (n == 0 || n > max_dense_kernel_dofs)
    return std::nullopt;
  const la::Matrix K = la::Matrix(K_lower).selfadjointView<Eigen::Lower>();
  const Eigen::SelfAdjointEigenSolver<la::Matrix> eigen(K);
  const la::Vector& values = eigen.eigenvalues(); // increasing
  const double tolerance = 1e-10 * values.cwiseAbs().maxCoeff();
  if (values(0) < -tolerance)
    return std::nullopt;
  const auto k = static_cast<la::Index>((values.array() <= tolerance).count());
  const la::Index extra = k - rigid.cols();
  if (extra <= 0)
    return std::nullopt;
  // The eigenvectors are one orthonormal basis of the kernel, turned anyhow by the round-off of
  // K (0.79 apart under noise of 1e-14: test_zero_energy_modes.cpp), and with them the coarse
  // problem and the pivot test of G G' (dual/projector.cpp). The kernel in a basis of its own:
  // the rigid motions as every subdomain has them, then the part W = (I - R R') V beyond them
  // (rank `extra`), written as W W_P^+ on the `extra` DOFs P that a pivoted QR of W' picks (by
  // norms that no turn of V changes, and so is the basis: the identity on P), orthonormalized.
  const la::Matrix V = eigen.eigenvectors().leftCols(k);
  const la::Matrix W = V - rigid * (rigid.transpose() * V);
  const Eigen::ColPivHouseholderQR<la::Matrix> pivots(W.transpose());
  la::Matrix W_P(extra, k);
  for (la::Index j = 0; j < extra; ++j)
    W_P.row(j) = W.row(pivots.colsPermutation().indices()(j));
  const la::Matrix E = W * W_P.completeOrthogonalDecomposition().pseudoInverse();
  const la::Matrix E_orthonormal = E.householderQr().householderQ() * la::Matrix::Identity(n, extra);
  la::Matrix kernel(n, k);
  kernel << rigid, E_orthonormal;
  return kernel;
}
} // namespace feticon::decomposition
