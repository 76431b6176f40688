#include "dual/feti_operators.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"

#include <algorithm>
#include <map>
#include <tuple>

namespace feticon::dual
{
namespace
{
std::vector<std::vector<double>> pack(const std::vector<std::vector<int64_t>>& indices,
                                      const la::Vector& values)
{
  std::vector<std::vector<double>> out(indices.size());
  for (size_t k = 0; k < indices.size(); ++k)
    for (const int64_t i : indices[k])
      out[k].push_back(values(i));
  return out;
}

std::vector<size_t> sizes_of(const std::vector<std::vector<int64_t>>& lists)
{
  std::vector<size_t> out;
  for (const auto& l : lists)
    out.push_back(l.size());
  return out;
}
} // namespace

FetiOperators::FetiOperators(const decomposition::SubdomainSystem& system,
                             const decomposition::ConstraintRows& rows)
    : _system(system), _comm(system.decomposition().comm())
{
  const auto& decomp = system.decomposition();
  const int me = _comm.rank();
  const int32_t first = decomp.first_owned();
  const int32_t n_local = decomp.end_owned() - first;
  const int64_t n_kept = rows.n_rows();

  // Who touches and who owns every kept row; owned rows take slots 0.., ghosts follow.
  _touch.resize(n_kept);
  std::vector<int64_t> ghosts;
  for (int64_t i = 0; i < n_kept; ++i)
  {
    for (const auto& e : rows.row(i))
      _touch[i].push_back(e.subdomain);
    std::sort(_touch[i].begin(), _touch[i].end());
    _touch[i].erase(std::unique(_touch[i].begin(), _touch[i].end()), _touch[i].end());
    FETICON_ASSERT(!_touch[i].empty(), "constraint row without entries");
    (decomp.owns(_touch[i].front()) ? _owned : ghosts).push_back(i);
  }
  _slot.assign(n_kept, -1);
  for (int64_t i = 0; i < n_kept; ++i)
    _kept_id.push_back(rows.id(i));
  std::vector<std::vector<la::Index>> blocks;
  std::vector<int32_t> block_subdomain;
  for (size_t k = 0; k < _owned.size(); ++k)
    _slot[_owned[k]] = static_cast<int64_t>(k);
  for (size_t k = 0; k < ghosts.size(); ++k)
    _slot[ghosts[k]] = static_cast<int64_t>(_owned.size() + k);
  _n_dual_global = _comm.sum(n_dual());

  // Blocks of the dual space: the rows owned by each owned subdomain.
  {
    std::map<int32_t, std::vector<la::Index>> by_owner;
    for (size_t k = 0; k < _owned.size(); ++k)
      by_owner[_touch[_owned[k]].front()].push_back(static_cast<la::Index>(k));
    for (auto& [s, list] : by_owner)
      blocks.push_back(std::move(list));
    std::vector<int64_t> owned_ids;
    for (la::Index i = 0; i < n_dual(); ++i)
      owned_ids.push_back(row_id(i));
    _space = std::make_unique<par::BlockSpace>(_comm, std::move(blocks), std::move(owned_ids));
  }

  // B_s and B_s R_s of the owned subdomains; rows of s in increasing id.
  _sub_rows.resize(n_local);
  _sub_slots.resize(n_local);
  _B.resize(n_local);
  _BR.resize(n_local);
  std::vector<std::vector<la::Triplet>> triplets(n_local);
  std::map<std::pair<int64_t, int32_t>, int64_t> position; // (kept row, s) -> local row of s
  for (int64_t i = 0; i < n_kept; ++i)
    for (const int32_t s : _touch[i])
      if (decomp.owns(s))
      {
        position[{i, s}] = static_cast<int64_t>(_sub_rows[s - first].size());
        _sub_rows[s - first].push_back(i);
        _sub_slots[s - first].push_back(_slot[i]);
      }
  for (int64_t i = 0; i < n_kept; ++i)
    for (const auto& e : rows.row(i))
      if (decomp.owns(e.subdomain))
        triplets[e.subdomain - first].emplace_back(
            static_cast<la::Index>(position.at({i, e.subdomain})), e.dof, e.value);
  _contribution_start.assign(1, 0);
  for (int32_t l = 0; l < n_local; ++l)
  {
    const int32_t s = first + l;
    _B[l].resize(static_cast<la::Index>(_sub_rows[l].size()), decomp.subdomain(s).n_dofs());
    _B[l].setFromTriplets(triplets[l].begin(), triplets[l].end());
    _BR[l] = _B[l] * system.operators(s).R;
    _contribution_start.push_back(_contribution_start.back() +
                                  static_cast<int64_t>(_sub_rows[l].size()));
  }

  // Ghost exchange and contribution exchange, derived on both sides from the rows' entries
  // in increasing (row id, subdomain) order.
  std::map<int, size_t> neighbour;
  auto index_of = [&](int rank)
  {
    const auto [it, added] = neighbour.emplace(rank, neighbour.size());
    return it->second;
  };
  for (int64_t i = 0; i < n_kept; ++i)
    for (const int32_t s : _touch[i])
      if (decomp.owner_rank(s) != me)
        index_of(decomp.owner_rank(s));
  // Renumber neighbours in rank order (map iteration order).
  {
    size_t k = 0;
    for (auto& [rank, index] : neighbour)
      index = k++;
  }
  const size_t n_nb = neighbour.size();
  for (auto* ex : {&_ghosts, &_to_owner})
  {
    ex->send.assign(n_nb, {});
    ex->recv.assign(n_nb, {});
    ex->ranks.clear();
    for (const auto& [rank, index] : neighbour)
      ex->ranks.push_back(rank);
  }
  _share_send.assign(n_nb, {});
  _share_recv_size.assign(n_nb, 0);
  std::vector<std::vector<std::tuple<int64_t, int32_t, int64_t>>> to_owner(n_nb);
  for (int64_t i = 0; i < n_kept; ++i)
  {
    const int owner = decomp.owner_rank(_touch[i].front());
    std::vector<int> others; // other ranks touching row i
    for (const int32_t s : _touch[i])
    {
      const int r = decomp.owner_rank(s);
      if (r != me && std::find(others.begin(), others.end(), r) == others.end())
        others.push_back(r);
    }
    if (owner == me)
      for (const int r : others)
        _ghosts.send[neighbour.at(r)].push_back(_slot[i]);
    else
      _ghosts.recv[neighbour.at(owner)].push_back(_slot[i]);
    for (const int32_t s : _touch[i])
    {
      const int r = decomp.owner_rank(s);
      if (r == me)
      {
        if (owner != me)
          to_owner[neighbour.at(owner)].emplace_back(
              rows.id(i), s, _contribution_start[s - first] + position.at({i, s}));
        for (const int q : others)
          _share_send[neighbour.at(q)].emplace_back(i, s);
      }
      else
        _share_recv_size[neighbour.at(r)] += system.kernel_dim(s);
    }
  }
  for (size_t k = 0; k < n_nb; ++k)
  {
    std::sort(to_owner[k].begin(), to_owner[k].end());
    for (const auto& [id, s, pos] : to_owner[k])
      _to_owner.send[k].push_back(pos);
  }
  // Per owned row its contributions in increasing subdomain order: local positions, or the
  // next value received from the subdomain's rank.
  std::vector<int64_t> recv_count(n_nb, 0);
  _sum_start.assign(1, 0);
  std::vector<std::pair<int, int64_t>> sources; // (neighbour or -1, position)
  for (const int64_t i : _owned)
  {
    for (const int32_t s : _touch[i])
    {
      const int r = decomp.owner_rank(s);
      if (r == me)
        sources.emplace_back(-1, _contribution_start[s - first] + position.at({i, s}));
      else
      {
        const size_t k = neighbour.at(r);
        sources.emplace_back(static_cast<int>(k), recv_count[k]++);
      }
    }
    _sum_start.push_back(static_cast<int64_t>(sources.size()));
  }
  std::vector<int64_t> recv_base(n_nb + 1, _contribution_start.back());
  for (size_t k = 0; k < n_nb; ++k)
  {
    recv_base[k + 1] = recv_base[k] + recv_count[k];
    _to_owner.recv[k].resize(recv_count[k]); // only the sizes are used
  }
  for (const auto& [k, pos] : sources)
    _sum_source.push_back(k < 0 ? pos : recv_base[k] + pos);
  _n_contributions = recv_base[n_nb];
}

la::Vector FetiOperators::owned(const la::Vector& per_row) const
{
  la::Vector out(n_dual());
  for (size_t k = 0; k < _owned.size(); ++k)
    out(static_cast<la::Index>(k)) = per_row(_owned[k]);
  return out;
}

la::Vector FetiOperators::extended(const la::Vector& lambda, const std::vector<char>* mask) const
{
  FETICON_ASSERT(lambda.size() == n_dual(), "dual vector size");
  la::Vector ext(static_cast<la::Index>(_slot.size()));
  ext.head(n_dual()) = lambda;
  if (mask)
    for (la::Index i = 0; i < n_dual(); ++i)
      if (!(*mask)[i])
        ext(i) = 0.0;
  const auto received =
      _comm.exchange(_ghosts.ranks, pack(_ghosts.send, ext), sizes_of(_ghosts.recv));
  for (size_t k = 0; k < received.size(); ++k)
    for (size_t j = 0; j < received[k].size(); ++j)
      ext(_ghosts.recv[k][j]) = received[k][j];
  return ext;
}

la::Vector FetiOperators::rows_of(int32_t s, const la::Vector& ext) const
{
  const auto& slots = _sub_slots[s - _system.decomposition().first_owned()];
  la::Vector local(static_cast<la::Index>(slots.size()));
  for (size_t j = 0; j < slots.size(); ++j)
    local(static_cast<la::Index>(j)) = ext(slots[j]);
  return local;
}

template <class LocalOperator>
la::Vector FetiOperators::sum_contributions(LocalOperator&& local_op) const
{
  const auto& decomp = _system.decomposition();
  la::Vector contributions(_n_contributions);
  parallel_for(decomp.first_owned(), decomp.end_owned(), decomp.n_primal(), [&](int32_t s)
  {
    const int32_t l = s - decomp.first_owned();
    if (!_sub_rows[l].empty())
      contributions.segment(_contribution_start[l], static_cast<la::Index>(_sub_rows[l].size())) =
          local_op(s);
  });
  const auto received = _comm.exchange(_to_owner.ranks, pack(_to_owner.send, contributions),
                                       sizes_of(_to_owner.recv));
  la::Index next = _contribution_start.back();
  for (const auto& buffer : received)
    for (const double v : buffer)
      contributions(next++) = v;
  la::Vector y(n_dual());
  for (la::Index i = 0; i < n_dual(); ++i)
  {
    double sum = 0.0;
    for (int64_t k = _sum_start[i]; k < _sum_start[i + 1]; ++k)
      sum += contributions(_sum_source[k]);
    y(i) = sum;
  }
  return y;
}

template <class LocalOperator>
la::Vector FetiOperators::sum_over_subdomains(const std::vector<la::SparseMatrix>& blocks, const la::Vector& lambda,
                                              LocalOperator&& local_op) const
{
  const la::Vector ext = extended(lambda);
  const int32_t first = _system.decomposition().first_owned();
  return sum_contributions([&](int32_t s)
                           {
                             const la::SparseMatrix& B = blocks[s - first];
                             return la::Vector(B * local_op(s, la::Vector(B.transpose() * rows_of(s, ext))));
                           });
}

la::Vector FetiOperators::apply_B(const la::Vector& u) const
{
  const auto& decomp = _system.decomposition();
  FETICON_ASSERT(u.size() == decomp.n_primal(), "stacked vector size");
  return sum_contributions([&](int32_t s)
                           { return la::Vector(_B[s - decomp.first_owned()] * decomp.segment(u, s)); });
}

la::Vector FetiOperators::apply_Bt(const la::Vector& lambda) const
{
  const auto& decomp = _system.decomposition();
  const la::Vector ext = extended(lambda);
  la::Vector u(decomp.n_primal());
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
    decomp.segment(u, s) = _B[s - decomp.first_owned()].transpose() * rows_of(s, ext);
  return u;
}

la::Vector FetiOperators::apply_K_plus(const la::Vector& f) const
{
  const auto& decomp = _system.decomposition();
  la::Vector u(decomp.n_primal());
  parallel_for(decomp.first_owned(), decomp.end_owned(), decomp.n_primal(), [&](int32_t s)
               { decomp.segment(u, s) = _system.operators(s).K_plus.apply(la::Vector(decomp.segment(f, s))); });
  return u;
}

la::Vector FetiOperators::apply_R(const la::Vector& alpha) const
{
  const auto& decomp = _system.decomposition();
  la::Vector u(decomp.n_primal());
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
    decomp.segment(u, s) =
        _system.operators(s).R * alpha.segment(_system.kernel_offset(s), _system.kernel_dim(s));
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
  return gather_coarse(_comm, local);
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
    std::vector<la::Triplet> triplets;
    for (int j = 0; j < B.outerSize(); ++j)
      for (la::SparseMatrix::InnerIterator it(B, j); it; ++it)
      {
        FETICON_CHECK(position[it.col()] >= 0, "explicit dual operators: a constraint row of subdomain "
                                                   << s << " touches DOF " << it.col()
                                                   << ", which is not on its boundary");
        triplets.emplace_back(it.row(), position[it.col()], it.value());
      }
    la::SparseMatrix Bb(B.rows(), static_cast<la::Index>(boundary.size()));
    Bb.setFromTriplets(triplets.begin(), triplets.end());
    _B_boundary.push_back(std::move(Bb));
  }
  _explicit = &ops;
}

la::Vector FetiOperators::apply_F(const la::Vector& lambda) const
{
  if (_explicit)
    return sum_over_subdomains(_B_boundary, lambda, [this](int32_t s, const la::Vector& v)
                               { return _explicit->apply_K_plus(s, v); });
  return sum_over_subdomains(_B, lambda, [this](int32_t s, const la::Vector& v)
                             { return _system.operators(s).K_plus.apply(v); });
}

la::Vector FetiOperators::apply_lumped(const la::Vector& lambda) const
{
  return sum_over_subdomains(_B, lambda, [this](int32_t s, const la::Vector& v)
                             { return la::Vector(_system.operators(s).K * v); });
}

la::Vector FetiOperators::apply_dirichlet(const la::Vector& lambda,
                                          const decomposition::SchurComplements& schur) const
{
  if (_explicit)
    return sum_over_subdomains(_B_boundary, lambda, [this](int32_t s, const la::Vector& v)
                               { return _explicit->apply_schur(s, v); });
  return sum_over_subdomains(_B, lambda, [&schur](int32_t s, const la::Vector& v) { return schur.apply(s, v); });
}

la::Vector FetiOperators::apply_G(const la::Vector& lambda, const std::vector<char>* mask) const
{
  const auto& decomp = _system.decomposition();
  const la::Vector ext = extended(lambda, mask);
  std::vector<double> local;
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
  {
    const la::Vector a = _BR[s - decomp.first_owned()].transpose() * rows_of(s, ext);
    local.insert(local.end(), a.data(), a.data() + a.size());
  }
  return gather_coarse(_comm, local);
}

la::Vector FetiOperators::apply_Gt(const la::Vector& alpha, const std::vector<char>* mask) const
{
  const auto& decomp = _system.decomposition();
  la::Vector y = sum_contributions(
      [&](int32_t s)
      {
        return la::Vector(_BR[s - decomp.first_owned()] *
                          alpha.segment(_system.kernel_offset(s), _system.kernel_dim(s)));
      });
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
  const la::Vector kept_mask = extended(ones, mask);
  // B_t R_t rows of remote subdomains t for the rows this rank shares with them.
  std::vector<std::vector<double>> send(_share_send.size());
  for (size_t k = 0; k < _share_send.size(); ++k)
    for (const auto& [i, s] : _share_send[k])
    {
      const int32_t l = s - first;
      const auto it = std::lower_bound(_sub_rows[l].begin(), _sub_rows[l].end(), i);
      const la::Index j = static_cast<la::Index>(it - _sub_rows[l].begin());
      for (la::Index a = 0; a < _BR[l].cols(); ++a)
        send[k].push_back(_BR[l](j, a));
    }
  const auto received = _comm.exchange(_to_owner.ranks, send, _share_recv_size);
  // (kept row, remote subdomain) -> its received row, in the order the sender packed.
  std::map<std::pair<int64_t, int32_t>, const double*> remote;
  {
    std::vector<size_t> cursor(received.size(), 0);
    for (int64_t i = 0; i < static_cast<int64_t>(_touch.size()); ++i)
      for (const int32_t t : _touch[i])
      {
        const int r = decomp.owner_rank(t);
        if (r == _comm.rank())
          continue;
        const size_t k = static_cast<size_t>(
            std::lower_bound(_to_owner.ranks.begin(), _to_owner.ranks.end(), r) - _to_owner.ranks.begin());
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
    std::map<int32_t, la::Matrix> blocks;
    for (size_t j = 0; j < _sub_rows[l].size(); ++j)
    {
      const int64_t i = _sub_rows[l][j];
      if (kept_mask(_slot[i]) == 0.0)
        continue;
      for (const int32_t t : _touch[i])
      {
        const int32_t kt = _system.kernel_dim(t);
        la::Vector g_t(kt);
        if (decomp.owns(t))
        {
          const int32_t lt = t - first;
          const auto it = std::lower_bound(_sub_rows[lt].begin(), _sub_rows[lt].end(), i);
          g_t = _BR[lt].row(it - _sub_rows[lt].begin()).transpose();
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
  const std::vector<int64_t> all_indices = _comm.all_gather(indices);
  const std::vector<double> all_values = _comm.all_gather(values);
  std::vector<la::Triplet> triplets;
  triplets.reserve(all_values.size());
  for (size_t k = 0; k < all_values.size(); ++k)
    triplets.emplace_back(static_cast<int>(all_indices[2 * k]), static_cast<int>(all_indices[2 * k + 1]),
                          all_values[k]);
  la::SparseMatrix GGt(n_kernel(), n_kernel());
  GGt.setFromTriplets(triplets.begin(), triplets.end());
  return GGt;
}

std::vector<FetiOperators::GramEntry> FetiOperators::gram_entries(
    const std::function<bool(int64_t)>& selected) const
{
  std::vector<GramEntry> out;
  const int32_t first = _system.decomposition().first_owned();
  for (size_t l = 0; l < _B.size(); ++l)
  {
    const la::SparseMatrix BBt = _B[l] * la::SparseMatrix(_B[l].transpose());
    for (int k = 0; k < BBt.outerSize(); ++k)
      for (la::SparseMatrix::InnerIterator it(BBt, k); it; ++it)
      {
        const int64_t row = _kept_id[_sub_rows[l][it.row()]];
        const int64_t col = _kept_id[_sub_rows[l][it.col()]];
        if (it.value() != 0.0 && (selected(row) || selected(col)))
          out.push_back({row, col, first + static_cast<int32_t>(l), it.value()});
      }
  }
  return out;
}
} // namespace feticon::dual
