#include "dual/feti_operators.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "la/submatrix.hpp"

#include <algorithm>
#include <map>
#include <tuple>

namespace feticon::dual
{
FetiOperators::FetiOperators(const decomposition::SubdomainSystem& system, const decomposition::ConstraintRows& rows)
    : _system(system), _layout(system.decomposition(), rows),
      // A substitution costs its factor's nonzeros: counted in DOFs, the 3D subdomains (about
      // five times the nonzeros per DOF of plane strain) would run serially where threads pay
      // (docs/measurements.md).
      _implicit_work(system.factor_nonzeros() / factor_nonzeros_per_work_unit)
{
  const auto& decomp = system.decomposition();
  const int me = decomp.comm().rank();
  const int32_t first = decomp.first_owned();
  const int32_t n_local = decomp.end_owned() - first;

  // B_s and B_s R_s of the owned subdomains; rows of s in increasing id.
  _B.resize(n_local);
  _BR.resize(n_local);
  std::vector<std::vector<la::Triplet>> triplets(n_local);
  for (int64_t i = 0; i < rows.n_rows(); ++i)
    for (const auto& e : rows.row(i))
      if (decomp.owns(e.subdomain))
      {
        const auto& list = _layout.rows_of_subdomain(e.subdomain);
        const auto local_row = std::lower_bound(list.begin(), list.end(), i) - list.begin();
        triplets[e.subdomain - first].emplace_back(static_cast<la::Index>(local_row), e.dof, e.value);
      }
  for (int32_t l = 0; l < n_local; ++l)
  {
    const int32_t s = first + l;
    _B[l].resize(static_cast<la::Index>(_layout.rows_of_subdomain(s).size()), decomp.subdomain(s).n_dofs());
    _B[l].setFromTriplets(triplets[l].begin(), triplets[l].end());
    _BR[l] = _B[l] * system.operators(s).R;
  }

  // G G' shares: every row's B_s R_s rows go to the other ranks touching the row.
  const std::vector<int>& ranks = _layout.neighbour_ranks();
  auto neighbour = [&](int rank) {
    return static_cast<size_t>(std::lower_bound(ranks.begin(), ranks.end(), rank) - ranks.begin());
  };
  _share_send.assign(ranks.size(), {});
  _share_recv_size.assign(ranks.size(), 0);
  for (int64_t i = 0; i < _layout.n_kept(); ++i)
  {
    std::vector<int> others; // other ranks touching row i
    for (const int32_t s : _layout.touching(i))
    {
      const int r = decomp.owner_rank(s);
      if (r != me && std::find(others.begin(), others.end(), r) == others.end())
        others.push_back(r);
    }
    for (const int32_t s : _layout.touching(i))
    {
      const int r = decomp.owner_rank(s);
      if (r == me)
        for (const int q : others)
          _share_send[neighbour(q)].emplace_back(i, s);
      else
        _share_recv_size[neighbour(r)] += system.kernel_dim(s);
    }
  }
}

template <class LocalOperator>
la::Vector FetiOperators::sum_over_subdomains(const std::vector<la::SparseMatrix>& blocks, const la::Vector& lambda,
                                              int64_t work, LocalOperator&& local_op) const
{
  const la::Vector ext = _layout.extended(lambda);
  const int32_t first = _system.decomposition().first_owned();
  return _layout.sum_contributions(
      [&](int32_t s) {
    const la::SparseMatrix& B = blocks[s - first];
    return la::Vector(B * local_op(s, la::Vector(B.transpose() * _layout.rows_of(s, ext))));
      },
      work);
}

la::Vector FetiOperators::apply_B(const la::Vector& u) const
{
  const auto& decomp = _system.decomposition();
  FETICON_ASSERT(u.size() == decomp.n_primal(), "stacked vector size");
  // A few entries per row: cheaper than waking the threads.
  return _layout.sum_contributions(
      [&](int32_t s) { return la::Vector(_B[s - decomp.first_owned()] * decomp.segment(u, s)); }, 0);
}

la::Vector FetiOperators::apply_Bt(const la::Vector& lambda) const
{
  const auto& decomp = _system.decomposition();
  const la::Vector ext = _layout.extended(lambda);
  la::Vector u(decomp.n_primal());
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
    decomp.segment(u, s) = _B[s - decomp.first_owned()].transpose() * _layout.rows_of(s, ext);
  return u;
}

la::Vector FetiOperators::apply_K_plus(const la::Vector& f) const
{
  const auto& decomp = _system.decomposition();
  la::Vector u(decomp.n_primal());
  parallel_for(decomp.first_owned(), decomp.end_owned(), _implicit_work, [&](int32_t s) {
    decomp.segment(u, s) = _system.operators(s).K_plus.apply(la::Vector(decomp.segment(f, s)));
  });
  return u;
}

la::Vector FetiOperators::apply_K_plus_refined(const la::Vector& f) const
{
  if (_system.factor_precision() != la::FactorPrecision::single_precision)
    return apply_K_plus(f);
  const auto& decomp = _system.decomposition();
  la::Vector u(decomp.n_primal());
  parallel_for(decomp.first_owned(), decomp.end_owned(), _implicit_work, [&](int32_t s) {
    const decomposition::SubdomainOperators& op = _system.operators(s);
    const la::Vector f_s = decomp.segment(f, s);
    la::Vector u_s = op.K_plus.apply(f_s);
    la::Vector r = f_s - op.K.selfadjointView<Eigen::Lower>() * u_s;
    // K K+ r = r holds for r in the range of K only; the kernel part of f_s (the dual's
    // feasibility error) was answered by the first substitution already.
    if (op.R.cols() > 0)
      r -= op.R * (op.R.transpose() * r);
    u_s += op.K_plus.apply(r);
    decomp.segment(u, s) = u_s;
  });
  return u;
}

la::Vector FetiOperators::apply_R(const la::Vector& alpha) const
{
  const auto& decomp = _system.decomposition();
  la::Vector u(decomp.n_primal());
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
    decomp.segment(u, s) = _system.operators(s).R * alpha.segment(_system.kernel_offset(s), _system.kernel_dim(s));
  return u;
}

namespace
{
/// The replicated coarse vector from the owned subdomains' blocks (contiguous, rank order).
la::Vector gather_coarse(const par::Communicator& comm, const std::vector<double>& owned_blocks)
{
  const std::vector<double> all = comm.all_gather(owned_blocks);
  return Eigen::Map<const la::Vector>(all.data(), static_cast<la::Index>(all.size()));
}
} // namespace

la::Vector FetiOperators::apply_Rt(const la::Vector& u) const
{
  const auto& decomp = _system.decomposition();
  std::vector<double> local;
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
  {
    const la::Vector a = _system.operators(s).R.transpose() * decomp.segment(u, s);
    local.insert(local.end(), a.data(), a.data() + a.size());
  }
  return gather_coarse(comm(), local);
}

la::Vector FetiOperators::net_force_weights() const
{
  const auto& decomp = _system.decomposition();
  std::vector<double> local;
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
  {
    const la::Matrix& R = _system.operators(s).R;
    for (la::Index j = 0; j < R.cols(); ++j)
      local.push_back(1.0 / R.col(j).cwiseAbs().maxCoeff());
  }
  return gather_coarse(comm(), local);
}

namespace
{
/// B's columns j with position[j] >= 0, column j becoming position[j]; every entry of B must
/// be in one of them.
la::SparseMatrix restrict_columns(const la::SparseMatrix& B, const std::vector<int32_t>& position, la::Index n_kept,
                                  int32_t subdomain, const char* caller)
{
  std::vector<la::Triplet> triplets;
  for (int j = 0; j < B.outerSize(); ++j)
    for (la::SparseMatrix::InnerIterator it(B, j); it; ++it)
    {
      FETICON_CHECK(position[it.col()] >= 0,
                    caller << ": a constraint row of subdomain " << subdomain << " touches DOF " << it.col()
                           << ", which is not on its boundary");
      triplets.emplace_back(it.row(), position[it.col()], it.value());
    }
  la::SparseMatrix restricted(B.rows(), n_kept);
  restricted.setFromTriplets(triplets.begin(), triplets.end());
  return restricted;
}
} // namespace

void FetiOperators::use_lumped_blocks()
{
  const auto& decomp = _system.decomposition();
  _B_touched.clear();
  _K_touched.clear();
  int64_t entries = 0;
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
  {
    const la::SparseMatrix& B = _B[s - decomp.first_owned()];
    std::vector<int32_t> position(B.cols(), -1);
    for (int j = 0; j < B.outerSize(); ++j)
      for (la::SparseMatrix::InnerIterator it(B, j); it; ++it)
        position[it.col()] = 0;
    int32_t n_touched = 0;
    for (int32_t& p : position) // increasing with the DOF: K's lower triangle stays lower
      if (p == 0)
        p = n_touched++;
    _B_touched.push_back(restrict_columns(B, position, n_touched, s, "lumped preconditioner"));
    _K_touched.push_back(la::principal_submatrix(_system.operators(s).K, position, n_touched));
    entries += _K_touched.back().nonZeros();
  }
  // A product reads each stored entry twice (the symmetric view); counted like the blocks.
  _lumped_work = entries / 25;
}

void FetiOperators::use_explicit(const decomposition::ExplicitBoundaryOperators& ops)
{
  const auto& decomp = _system.decomposition();
  _B_boundary.clear();
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
  {
    const la::SparseMatrix& B = _B[s - decomp.first_owned()];
    const std::vector<int32_t>& boundary = ops.boundary(s);
    std::vector<int32_t> position(B.cols(), -1);
    for (size_t k = 0; k < boundary.size(); ++k)
      position[boundary[k]] = static_cast<int32_t>(k);
    _B_boundary.push_back(
        restrict_columns(B, position, static_cast<la::Index>(boundary.size()), s, "explicit dual operators"));
  }
  _explicit = &ops;
  // A product reads each block once; the threads pay from about 25 * min_parallel_work block
  // entries on (docs/measurements.md). Counted as the subdomains' DOFs, as the substitutions
  // are, these products would thread the sparse products with B and G with them, which are
  // cheaper than waking the threads.
  constexpr int64_t block_entries_per_work_unit = 25;
  int64_t entries = 0;
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
    entries += static_cast<int64_t>(ops.boundary(s).size()) * static_cast<int64_t>(ops.boundary(s).size());
  _explicit_work = entries / block_entries_per_work_unit;
}

la::Vector FetiOperators::apply_F(const la::Vector& lambda) const
{
  if (_explicit)
    return sum_over_subdomains(_B_boundary, lambda, _explicit_work,
                               [this](int32_t s, const la::Vector& v) { return _explicit->apply_K_plus(s, v); });
  return sum_over_subdomains(_B, lambda, _implicit_work,
                             [this](int32_t s, const la::Vector& v) { return _system.operators(s).K_plus.apply(v); });
}

la::Vector FetiOperators::apply_lumped(const la::Vector& lambda) const
{
  if (!_K_touched.empty())
    return sum_over_subdomains(_B_touched, lambda, _lumped_work, [this](int32_t s, const la::Vector& v) {
      return la::Vector(_K_touched[s - _system.decomposition().first_owned()].selfadjointView<Eigen::Lower>() * v);
    });
  return sum_over_subdomains(_B, lambda, n_primal(), [this](int32_t s, const la::Vector& v) {
    return la::Vector(_system.operators(s).K.selfadjointView<Eigen::Lower>() * v);
  });
}

la::Vector FetiOperators::apply_dirichlet(const la::Vector& lambda, const decomposition::SchurComplements& schur) const
{
  if (_explicit)
    return sum_over_subdomains(_B_boundary, lambda, _explicit_work,
                               [this](int32_t s, const la::Vector& v) { return _explicit->apply_schur(s, v); });
  return sum_over_subdomains(_B, lambda, _implicit_work,
                             [&schur](int32_t s, const la::Vector& v) { return schur.apply(s, v); });
}

la::Vector FetiOperators::apply_G(const la::Vector& lambda, const std::vector<char>* mask) const
{
  const auto& decomp = _system.decomposition();
  const la::Vector ext = _layout.extended(lambda, mask);
  std::vector<double> local;
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
  {
    const la::Vector a = _BR[s - decomp.first_owned()].transpose() * _layout.rows_of(s, ext);
    local.insert(local.end(), a.data(), a.data() + a.size());
  }
  return gather_coarse(comm(), local);
}

la::Vector FetiOperators::apply_Gt(const la::Vector& alpha, const std::vector<char>* mask) const
{
  const auto& decomp = _system.decomposition();
  la::Vector y = _layout.sum_contributions(
      [&](int32_t s) {
    return la::Vector(_BR[s - decomp.first_owned()] * alpha.segment(_system.kernel_offset(s), _system.kernel_dim(s)));
      },
      0); // a few columns per subdomain: cheaper than waking the threads
  if (mask)
    for (la::Index i = 0; i < n_dual(); ++i)
      if (!(*mask)[i])
        y(i) = 0.0;
  return y;
}

la::SparseMatrix FetiOperators::coarse_matrix(const std::vector<char>* mask) const
{
  const auto& decomp = _system.decomposition();
  const int32_t first = decomp.first_owned();
  // Mask of every kept row (ghosts from their owners).
  la::Vector ones = la::Vector::Ones(n_dual());
  const la::Vector kept_mask = _layout.extended(ones, mask);
  // B_t R_t rows of remote subdomains t for the rows this rank shares with them.
  std::vector<std::vector<double>> send(_share_send.size());
  for (size_t k = 0; k < _share_send.size(); ++k)
    for (const auto& [i, s] : _share_send[k])
    {
      const int32_t l = s - first;
      const auto& sub_rows = _layout.rows_of_subdomain(s);
      const auto it = std::lower_bound(sub_rows.begin(), sub_rows.end(), i);
      const la::Index j = static_cast<la::Index>(it - sub_rows.begin());
      for (la::Index a = 0; a < _BR[l].cols(); ++a)
        send[k].push_back(_BR[l](j, a));
    }
  const std::vector<int>& ranks = _layout.neighbour_ranks();
  const auto received = comm().exchange(ranks, send, _share_recv_size);
  // (kept row, remote subdomain) -> its received row, in the order the sender packed.
  std::map<std::pair<int64_t, int32_t>, const double*> remote;
  {
    std::vector<size_t> cursor(received.size(), 0);
    for (int64_t i = 0; i < _layout.n_kept(); ++i)
      for (const int32_t t : _layout.touching(i))
      {
        const int r = decomp.owner_rank(t);
        if (r == comm().rank())
          continue;
        const size_t k = static_cast<size_t>(std::lower_bound(ranks.begin(), ranks.end(), r) - ranks.begin());
        remote[{i, t}] = received[k].data() + cursor[k];
        cursor[k] += static_cast<size_t>(_system.kernel_dim(t));
      }
  }
  // Block (s, t) of the owned subdomain s: sum over the rows s and t share, in id order.
  std::vector<int64_t> indices;
  std::vector<double> values;
  for (int32_t s = first; s < decomp.end_owned(); ++s)
  {
    const int32_t l = s - first;
    const auto& sub_rows = _layout.rows_of_subdomain(s);
    std::map<int32_t, la::Matrix> blocks;
    for (size_t j = 0; j < sub_rows.size(); ++j)
    {
      const int64_t i = sub_rows[j];
      if (kept_mask(_layout.slot(i)) == 0.0)
        continue;
      for (const int32_t t : _layout.touching(i))
      {
        const int32_t kt = _system.kernel_dim(t);
        la::Vector g_t(kt);
        if (decomp.owns(t))
        {
          const auto& t_rows = _layout.rows_of_subdomain(t);
          const auto it = std::lower_bound(t_rows.begin(), t_rows.end(), i);
          g_t = _BR[t - first].row(it - t_rows.begin()).transpose();
        }
        else
          g_t = Eigen::Map<const la::Vector>(remote.at({i, t}), kt);
        auto [it, added] = blocks.try_emplace(t, la::Matrix::Zero(_BR[l].cols(), kt));
        it->second += _BR[l].row(static_cast<la::Index>(j)).transpose() * g_t.transpose();
      }
    }
    for (const auto& [t, block] : blocks)
      for (la::Index a = 0; a < block.rows(); ++a)
        for (la::Index b = 0; b < block.cols(); ++b)
          if (block(a, b) != 0.0)
          {
            indices.push_back(_system.kernel_offset(s) + a);
            indices.push_back(_system.kernel_offset(t) + b);
            values.push_back(block(a, b));
          }
  }
  const std::vector<int64_t> all_indices = comm().all_gather(indices);
  const std::vector<double> all_values = comm().all_gather(values);
  std::vector<la::Triplet> triplets;
  triplets.reserve(all_values.size());
  for (size_t k = 0; k < all_values.size(); ++k)
    triplets.emplace_back(static_cast<int>(all_indices[2 * k]), static_cast<int>(all_indices[2 * k + 1]),
                          all_values[k]);
  la::SparseMatrix GGt(n_kernel(), n_kernel());
  GGt.setFromTriplets(triplets.begin(), triplets.end());
  return GGt;
}

std::vector<FetiOperators::GramEntry> FetiOperators::gram_entries(const std::function<bool(int64_t)>& selected) const
{
  std::vector<GramEntry> out;
  const int32_t first = _system.decomposition().first_owned();
  for (size_t l = 0; l < _B.size(); ++l)
  {
    const auto& sub_rows = _layout.rows_of_subdomain(first + static_cast<int32_t>(l));
    const la::SparseMatrix BBt = _B[l] * la::SparseMatrix(_B[l].transpose());
    for (int k = 0; k < BBt.outerSize(); ++k)
      for (la::SparseMatrix::InnerIterator it(BBt, k); it; ++it)
      {
        const int64_t row = _layout.kept_id(sub_rows[it.row()]);
        const int64_t col = _layout.kept_id(sub_rows[it.col()]);
        if (it.value() != 0.0 && (selected(row) || selected(col)))
          out.push_back({row, col, first + static_cast<int32_t>(l), it.value()});
      }
  }
  return out;
}
} // namespace feticon::dual
