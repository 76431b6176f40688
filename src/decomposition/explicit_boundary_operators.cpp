#include "decomposition/explicit_boundary_operators.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "la/schur_complement.hpp"
#include "la/symmetric_product.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace feticon::decomposition
{
la::Matrix eliminate_fixing_dofs(const la::Matrix& S_ext, la::Index nb, const std::string& what)
{
  const la::Index ng = S_ext.rows() - nb;
  la::Matrix S = S_ext.topLeftCorner(nb, nb);
  if (ng == 0)
    return S;
  // S'_gg is positive definite for a subdomain fixed by these DOFs; a status other than
  // success is a singular or non-finite subdomain, named here (the implicit path throws too).
  const Eigen::LLT<la::Matrix> S_gg(S_ext.bottomRightCorner(ng, ng));
  FETICON_CHECK(S_gg.info() == Eigen::Success && S_gg.matrixLLT().allFinite(),
                "the Schur complement S'_gg of the fixing DOFs of "
                    << what << " is not positive definite (a singular or non-finite subdomain)");
  S -= S_ext.topRightCorner(nb, ng) * S_gg.solve(S_ext.bottomLeftCorner(ng, nb));
  return S;
}

namespace
{
/// The dense blocks of one subdomain, unscaled: (K_s+)_bb in the lower triangle and the
/// diagonal of `blocks`, S_s in its strict upper triangle; returns diag(S_s).
la::Vector form_blocks(const la::SparseMatrix& K, const GeneralizedInverse& K_plus,
                       const std::vector<int32_t>& boundary, la::Matrix& blocks, const std::string& what)
{
  const la::Index nb = static_cast<la::Index>(boundary.size());
  // b' = b followed by the fixing DOFs outside b; where[dof] = its index in b' (or -1).
  std::vector<int32_t> extended = boundary;
  std::vector<la::Index> where(K.rows(), -1);
  for (la::Index k = 0; k < nb; ++k)
    where[boundary[k]] = k;
  for (int32_t dof : K_plus.fixing_dofs())
    if (where[dof] < 0)
    {
      where[dof] = static_cast<la::Index>(extended.size());
      extended.push_back(dof);
    }
  const la::Matrix S_ext = la::schur_complement(K, extended, what.c_str());

  la::Matrix K_plus_bb = la::Matrix::Zero(nb, nb);
  const std::string inverse_of = "the boundary Schur complement of " + what;
  if (K_plus.method() == GeneralizedInverseMethod::fixing_dofs)
  {
    // K_rr's Schur complement on r = b' minus f is S' without the fixing rows; all of r lies in b.
    std::vector<char> fixed(extended.size(), 0);
    for (int32_t dof : K_plus.fixing_dofs())
      fixed[where[dof]] = 1;
    std::vector<la::Index> r;
    for (la::Index k = 0; k < nb; ++k)
      if (!fixed[k])
        r.push_back(k);
    la::Matrix M = S_ext(r, r);
    la::invert_spd(M, inverse_of.c_str());
    K_plus_bb(r, r) = M;
  }
  else
  {
    la::Matrix M = S_ext;
    const auto& dofs = K_plus.fixing_dofs();
    for (size_t i = 0; i < dofs.size(); ++i)
      for (size_t j = 0; j < dofs.size(); ++j)
        M(where[dofs[i]], where[dofs[j]]) +=
            K_plus.regularization()(static_cast<la::Index>(i), static_cast<la::Index>(j));
    la::invert_spd(M, inverse_of.c_str());
    K_plus_bb = M.topLeftCorner(nb, nb);
  }

  const la::Matrix S = eliminate_fixing_dofs(S_ext, nb, what);
  blocks = K_plus_bb.triangularView<Eigen::Lower>();
  blocks.triangularView<Eigen::StrictlyUpper>() = S;
  return S.diagonal();
}
} // namespace

ExplicitBoundaryOperators::ExplicitBoundaryOperators(const SubdomainSystem& system, const SchurComplements& schur,
                                                     ExplicitBoundaryOperators* reuse)
{
  const Decomposition& decomp = system.decomposition();
  _first = decomp.first_owned();
  _local.resize(decomp.end_owned() - decomp.first_owned());
  std::vector<char> form(_local.size(), 1);
  if (reuse && reuse->_first == _first && reuse->_local.size() == _local.size())
    for (size_t k = 0; k < _local.size(); ++k)
      if (reuse->_local[k].boundary == schur.boundary(_first + static_cast<int32_t>(k)))
      {
        _local[k] = std::move(reuse->_local[k]);
        form[k] = 0;
      }
  _formed = static_cast<int32_t>(std::count(form.begin(), form.end(), 1));
  parallel_for(decomp.first_owned(), decomp.end_owned(), setup_work, [&](int32_t s) {
    if (!form[s - _first])
      return;
    Local& local = _local[s - _first];
    local.boundary = schur.boundary(s);
    if (local.boundary.empty()) // no dual row touches it (a body alone in its subdomain, no contact)
    {
      local.blocks.resize(0, 0);
      local.schur_minus_K_plus.resize(0);
      local.sigma = 1;
      return;
    }
    const la::Vector schur_diagonal = form_blocks(system.operators(s).K, system.operators(s).K_plus, local.boundary,
                                                  local.blocks, "subdomain " + std::to_string(s));
    const la::Vector K_plus_diagonal = local.blocks.diagonal();
    const double K_plus_mean = K_plus_diagonal.mean(), schur_mean = schur_diagonal.mean();
    local.sigma = K_plus_mean > 0 && schur_mean > 0 ? std::sqrt(schur_mean / K_plus_mean) : 1.0;
    local.blocks.triangularView<Eigen::Lower>() *= local.sigma;
    local.blocks.triangularView<Eigen::StrictlyUpper>() /= local.sigma;
    local.schur_minus_K_plus = schur_diagonal / local.sigma - local.sigma * K_plus_diagonal;
  });
}

la::Vector ExplicitBoundaryOperators::apply_K_plus(int32_t s, const la::Vector& v) const
{
  la::Vector y;
  la::symmetric_product(local(s).blocks, la::Triangle::lower, v, y);
  return y / local(s).sigma;
}

la::Vector ExplicitBoundaryOperators::apply_schur(int32_t s, const la::Vector& v) const
{
  la::Vector y;
  la::symmetric_product(local(s).blocks, la::Triangle::upper, v, y);
  y += local(s).schur_minus_K_plus.cwiseProduct(v);
  return local(s).sigma * y;
}

int64_t ExplicitBoundaryOperators::bytes() const
{
  int64_t total = 0;
  for (const Local& local : _local)
    total += static_cast<int64_t>(sizeof(double)) * (local.blocks.size() + local.schur_minus_K_plus.size());
  return total;
}

int64_t explicit_operator_bytes(const SubdomainSystem& system, const SchurComplements& schur)
{
  const Decomposition& decomp = system.decomposition();
  int64_t total = 0;
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
  {
    const auto nb = static_cast<int64_t>(schur.boundary(s).size());
    total += (nb * nb + nb) * static_cast<int64_t>(sizeof(double));
  }
  return total;
}
} // namespace feticon::decomposition
