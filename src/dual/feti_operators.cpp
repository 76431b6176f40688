#include "dual/feti_operators.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <map>

namespace feticon::dual
{
FetiOperators::FetiOperators(const decomposition::SubdomainSystem& system,
                             const decomposition::ConstraintRows& rows)
    : _system(system), _n_dual(rows.n_rows())
{
  const auto& decomp = system.decomposition();
  const int32_t n_sub = decomp.n_subdomains();
  // Local row numbering per subdomain.
  std::vector<std::map<int64_t, int32_t>> local_row(n_sub);
  for (int64_t r = 0; r < rows.n_rows(); ++r)
    for (const auto& e : rows.row(r))
      local_row[e.subdomain].emplace(r, 0);
  _rows.resize(n_sub);
  _B.resize(n_sub);
  std::vector<std::vector<la::Triplet>> triplets(n_sub);
  for (int32_t s = 0; s < n_sub; ++s)
  {
    int32_t k = 0;
    for (auto& [r, local] : local_row[s])
    {
      local = k++;
      _rows[s].push_back(r);
    }
  }
  for (int64_t r = 0; r < rows.n_rows(); ++r)
    for (const auto& e : rows.row(r))
      triplets[e.subdomain].emplace_back(local_row[e.subdomain].at(r), e.dof, e.value);

  std::vector<la::Triplet> g_triplets;
  for (int32_t s = 0; s < n_sub; ++s)
  {
    const int32_t n_s = decomp.subdomain(s).n_dofs();
    _B[s].resize(static_cast<la::Index>(_rows[s].size()), n_s);
    _B[s].setFromTriplets(triplets[s].begin(), triplets[s].end());
    // G_s = (B_s R_s)': kernel rows of s against the multipliers touching s.
    const la::Matrix BR = _B[s] * system.operators(s).R;
    for (la::Index j = 0; j < BR.rows(); ++j)
      for (la::Index a = 0; a < BR.cols(); ++a)
        if (BR(j, a) != 0.0)
          g_triplets.emplace_back(static_cast<int>(system.kernel_offset(s) + a),
                                  static_cast<int>(_rows[s][j]), BR(j, a));
  }
  _G.resize(system.n_kernel(), _n_dual);
  _G.setFromTriplets(g_triplets.begin(), g_triplets.end());
}

la::Vector FetiOperators::apply_B(const la::Vector& u) const
{
  la::Vector lambda = la::Vector::Zero(_n_dual);
  const auto& decomp = _system.decomposition();
  for (int32_t s = 0; s < decomp.n_subdomains(); ++s)
  {
    const la::Vector local = _B[s] * decomp.segment(u, s);
    for (size_t j = 0; j < _rows[s].size(); ++j)
      lambda(_rows[s][j]) += local(static_cast<la::Index>(j));
  }
  return lambda;
}

la::Vector FetiOperators::apply_Bt(const la::Vector& lambda) const
{
  FETICON_ASSERT(lambda.size() == _n_dual, "dual vector size");
  const auto& decomp = _system.decomposition();
  la::Vector u(decomp.n_primal());
  for (int32_t s = 0; s < decomp.n_subdomains(); ++s)
  {
    la::Vector local(static_cast<la::Index>(_rows[s].size()));
    for (size_t j = 0; j < _rows[s].size(); ++j)
      local(static_cast<la::Index>(j)) = lambda(_rows[s][j]);
    decomp.segment(u, s) = _B[s].transpose() * local;
  }
  return u;
}

la::Vector FetiOperators::apply_K_plus(const la::Vector& f) const
{
  const auto& decomp = _system.decomposition();
  la::Vector u(decomp.n_primal());
  for (int32_t s = 0; s < decomp.n_subdomains(); ++s)
    decomp.segment(u, s) = _system.operators(s).K_plus.apply(la::Vector(decomp.segment(f, s)));
  return u;
}

la::Vector FetiOperators::apply_R(const la::Vector& alpha) const
{
  const auto& decomp = _system.decomposition();
  la::Vector u(decomp.n_primal());
  for (int32_t s = 0; s < decomp.n_subdomains(); ++s)
    decomp.segment(u, s) =
        _system.operators(s).R * alpha.segment(_system.kernel_offset(s), _system.kernel_dim(s));
  return u;
}

la::Vector FetiOperators::apply_Rt(const la::Vector& u) const
{
  const auto& decomp = _system.decomposition();
  la::Vector alpha(_system.n_kernel());
  for (int32_t s = 0; s < decomp.n_subdomains(); ++s)
    alpha.segment(_system.kernel_offset(s), _system.kernel_dim(s)) =
        _system.operators(s).R.transpose() * decomp.segment(u, s);
  return alpha;
}

template <class LocalOperator>
la::Vector FetiOperators::sum_over_subdomains(const la::Vector& lambda, LocalOperator&& local_op) const
{
  FETICON_ASSERT(lambda.size() == _n_dual, "dual vector size");
  la::Vector y = la::Vector::Zero(_n_dual);
  for (int32_t s = 0; s < _system.n_subdomains(); ++s)
  {
    if (_rows[s].empty())
      continue;
    la::Vector local(static_cast<la::Index>(_rows[s].size()));
    for (size_t j = 0; j < _rows[s].size(); ++j)
      local(static_cast<la::Index>(j)) = lambda(_rows[s][j]);
    const la::Vector out = _B[s] * local_op(s, la::Vector(_B[s].transpose() * local));
    for (size_t j = 0; j < _rows[s].size(); ++j)
      y(_rows[s][j]) += out(static_cast<la::Index>(j));
  }
  return y;
}

la::Vector FetiOperators::apply_F(const la::Vector& lambda) const
{
  return sum_over_subdomains(lambda, [this](int32_t s, const la::Vector& v)
                             { return _system.operators(s).K_plus.apply(v); });
}

la::Vector FetiOperators::apply_lumped(const la::Vector& lambda) const
{
  return sum_over_subdomains(lambda, [this](int32_t s, const la::Vector& v)
                             { return la::Vector(_system.operators(s).K * v); });
}

la::SparseMatrix FetiOperators::G_columns(const std::vector<char>& keep) const
{
  FETICON_ASSERT(static_cast<int64_t>(keep.size()) == _n_dual, "mask size");
  std::vector<la::Triplet> triplets;
  for (int col = 0; col < _G.outerSize(); ++col)
    if (keep[col])
      for (la::SparseMatrix::InnerIterator it(_G, col); it; ++it)
        triplets.emplace_back(static_cast<int>(it.row()), col, it.value());
  la::SparseMatrix out(_G.rows(), _G.cols());
  out.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}
} // namespace feticon::dual
