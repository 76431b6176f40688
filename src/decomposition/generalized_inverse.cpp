#include "decomposition/generalized_inverse.hpp"

#include "common/error.hpp"
#include "la/submatrix.hpp"

#include <algorithm>

namespace feticon::decomposition
{
namespace
{
/// Below it a factor's reciprocal condition estimate (la::CholmodFactor) calls K singular.
constexpr double singular_reciprocal_condition = 1e-12;
} // namespace

std::vector<int32_t> choose_fixing_nodes(const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& coords)
{
  const la::Index n = coords.rows();
  FETICON_CHECK(n >= 3, "a subdomain needs at least 3 nodes, it has " << n);
  const Eigen::RowVector3d centroid = coords.colwise().mean();
  la::Index a = 0, b = 0, c = 0;
  (coords.rowwise() - centroid).rowwise().squaredNorm().maxCoeff(&a);
  (coords.rowwise() - coords.row(a)).rowwise().squaredNorm().maxCoeff(&b);
  double best = -1;
  for (la::Index k = 0; k < n; ++k)
  {
    const double area = (coords.row(k) - coords.row(a)).cross(coords.row(b) - coords.row(a)).norm();
    if (area > best)
    {
      best = area;
      c = k;
    }
  }
  return {static_cast<int32_t>(a), static_cast<int32_t>(b), static_cast<int32_t>(c)};
}

void GeneralizedInverse::setup(const la::SparseMatrix& K, const la::Matrix& R,
                               const std::vector<int32_t>& fixing_candidates, GeneralizedInverseMethod method,
                               const std::string& what, la::FactorPrecision precision)
{
  _method = method;
  _n = K.rows();
  const la::Index k = R.cols();
  FETICON_CHECK(static_cast<la::Index>(fixing_candidates.size()) >= k,
                what << ": " << fixing_candidates.size() << " fixing DOFs cannot remove a kernel of "
                     << "dimension " << k);
  // Rows of R at the candidate DOFs; a column-pivoted QR of its transpose picks the k
  // candidates whose k x k block of R is best conditioned.
  la::Matrix R_fix(static_cast<la::Index>(fixing_candidates.size()), k);
  for (size_t i = 0; i < fixing_candidates.size(); ++i)
    R_fix.row(static_cast<la::Index>(i)) = R.row(fixing_candidates[i]);

  _fixing.clear();
  _regularization.resize(0, 0);
  if (method == GeneralizedInverseMethod::fixing_dofs)
  {
    std::vector<int32_t> position(_n, 0);
    if (k > 0)
    {
      Eigen::ColPivHouseholderQR<la::Matrix> qr(R_fix.transpose());
      la::Matrix block(k, k);
      for (la::Index j = 0; j < k; ++j)
      {
        const int32_t dof = fixing_candidates[qr.colsPermutation().indices()(j)];
        position[dof] = -1;
        _fixing.push_back(dof);
        block.row(j) = R.row(dof);
      }
      Eigen::JacobiSVD<la::Matrix> svd(block);
      const auto& sv = svd.singularValues();
      FETICON_CHECK(sv(k - 1) > 1e-8 * sv(0),
                    what << ": fixing nodes do not determine the "
                         << "rigid-body modes (degenerate subdomain?)");
    }
    _kept.clear();
    for (la::Index i = 0; i < _n; ++i)
      if (position[i] >= 0)
      {
        position[i] = static_cast<int32_t>(_kept.size());
        _kept.push_back(static_cast<int32_t>(i));
      }
    _factor.factorize(la::principal_submatrix(K, position, static_cast<int32_t>(_kept.size())), what.c_str(),
                      precision);
    // K without the fixing DOFs is positive definite where the kernel is R's; where K has
    // another zero-energy mode its Cholesky factorization may still pass on a pivot at round-off
    // (CalculiX's plate: one CPS8R cell a body, reciprocal condition 5.5e-15), and K+ is then
    // garbage (displacements of 1e8 m). The smallest reciprocal condition of a subdomain of the
    // test decks and examples is 3.4e-6 (bolt): below 1e-12 K is singular, as a failed
    // factorization says (SubdomainSystem then takes the kernel from K itself).
    FETICON_CHECK(_factor.reciprocal_condition() > singular_reciprocal_condition,
                  what << ": the stiffness without its fixing DOFs is singular to round-off (reciprocal condition "
                       << _factor.reciprocal_condition()
                       << "): a zero-energy mode besides the rigid-body motions, or stiffnesses 1e12 apart");
    return;
  }

  // Regularization: K + rho C C' with C = R on the fixing DOFs.
  double rho = 0;
  for (la::Index i = 0; i < _n; ++i)
    rho = std::max(rho, K.coeff(i, i));
  _fixing = fixing_candidates;
  _regularization = rho * R_fix * R_fix.transpose();
  std::vector<la::Triplet> triplets;
  for (size_t i = 0; i < fixing_candidates.size(); ++i)
    for (size_t j = 0; j < fixing_candidates.size(); ++j)
      triplets.emplace_back(fixing_candidates[i], fixing_candidates[j],
                            _regularization(static_cast<la::Index>(i), static_cast<la::Index>(j)));
  la::SparseMatrix C(_n, _n);
  C.setFromTriplets(triplets.begin(), triplets.end());
  _factor.factorize(K + C, what.c_str(), precision);
}

la::Vector GeneralizedInverse::apply(const la::Vector& b) const
{
  FETICON_ASSERT(b.size() == _n, "K+ applied to a vector of the wrong size");
  if (_method == GeneralizedInverseMethod::regularization)
    return _factor.solve(b);
  la::Vector b_kept(static_cast<la::Index>(_kept.size()));
  for (size_t i = 0; i < _kept.size(); ++i)
    b_kept(static_cast<la::Index>(i)) = b(_kept[i]);
  const la::Vector x_kept = _factor.solve(b_kept);
  la::Vector x = la::Vector::Zero(_n);
  for (size_t i = 0; i < _kept.size(); ++i)
    x(_kept[i]) = x_kept(static_cast<la::Index>(i));
  return x;
}

la::Matrix GeneralizedInverse::apply(const la::Matrix& B) const
{
  FETICON_ASSERT(B.rows() == _n, "K+ applied to a matrix of the wrong size");
  if (_method == GeneralizedInverseMethod::regularization)
    return _factor.solve(B);
  // All columns in one supernodal solve (BLAS 3), rows of the fixing DOFs left zero.
  la::Matrix B_kept(static_cast<la::Index>(_kept.size()), B.cols());
  for (size_t i = 0; i < _kept.size(); ++i)
    B_kept.row(static_cast<la::Index>(i)) = B.row(_kept[i]);
  const la::Matrix X_kept = _factor.solve(B_kept);
  la::Matrix X = la::Matrix::Zero(_n, B.cols());
  for (size_t i = 0; i < _kept.size(); ++i)
    X.row(_kept[i]) = X_kept.row(static_cast<la::Index>(i));
  return X;
}
} // namespace feticon::decomposition
