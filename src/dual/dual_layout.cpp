#include "dual/dual_layout.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"

#include <algorithm>
#include <map>
#include <tuple>

namespace feticon::dual
{
namespace
{
std::vector<std::vector<double>> pack(const std::vector<std::vector<int64_t>>& indices, const la::Vector& values)
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

DualLayout::DualLayout(const decomposition::Decomposition& decomp, const decomposition::ConstraintRows& rows)
    : _decomp(decomp), _comm(decomp.comm())
{
  assign_rows(rows);
  make_space();
  list_subdomain_rows();
  // Ghost exchange and contribution exchange, derived on both sides from the rows' entries
  // in increasing (row id, subdomain) order; neighbours numbered in rank order.
  const std::map<int, size_t> neighbour = number_neighbours();
  list_exchanges(rows, neighbour);
  list_sum_sources(neighbour);
}

void DualLayout::assign_rows(const decomposition::ConstraintRows& rows)
{
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
    (_decomp.owns(_touch[i].front()) ? _owned : ghosts).push_back(i);
  }
  _slot.assign(n_kept, -1);
  for (int64_t i = 0; i < n_kept; ++i)
    _kept_id.push_back(rows.id(i));
  for (size_t k = 0; k < _owned.size(); ++k)
    _slot[_owned[k]] = static_cast<int64_t>(k);
  for (size_t k = 0; k < ghosts.size(); ++k)
    _slot[ghosts[k]] = static_cast<int64_t>(_owned.size() + k);
  _n_dual_global = _comm.sum(n_dual());
}

void DualLayout::make_space()
{
  // Blocks of the dual space: the rows owned by each owned subdomain.
  std::map<int32_t, std::vector<la::Index>> by_owner;
  for (size_t k = 0; k < _owned.size(); ++k)
    by_owner[_touch[_owned[k]].front()].push_back(static_cast<la::Index>(k));
  std::vector<std::vector<la::Index>> blocks;
  for (auto& [s, list] : by_owner)
    blocks.push_back(std::move(list));
  std::vector<int64_t> owned_ids;
  for (la::Index i = 0; i < n_dual(); ++i)
    owned_ids.push_back(row_id(i));
  _space = std::make_unique<par::BlockSpace>(_comm, std::move(blocks), std::move(owned_ids));
}

void DualLayout::list_subdomain_rows()
{
  const int32_t first = _decomp.first_owned();
  const int32_t n_local = _decomp.end_owned() - first;
  const int64_t n_kept = this->n_kept();

  // The rows of every owned subdomain in increasing index, and where each subdomain's
  // contributions start.
  _sub_rows.resize(n_local);
  _sub_slots.resize(n_local);
  for (int64_t i = 0; i < n_kept; ++i)
    for (const int32_t s : _touch[i])
      if (_decomp.owns(s))
      {
        _sub_rows[s - first].push_back(i);
        _sub_slots[s - first].push_back(_slot[i]);
      }
  _contribution_start.assign(1, 0);
  for (int32_t l = 0; l < n_local; ++l)
    _contribution_start.push_back(_contribution_start.back() + static_cast<int64_t>(_sub_rows[l].size()));
}

int64_t DualLayout::position(int64_t i, int32_t s) const
{
  const auto& list = _sub_rows[s - _decomp.first_owned()];
  return static_cast<int64_t>(std::lower_bound(list.begin(), list.end(), i) - list.begin());
}

std::map<int, size_t> DualLayout::number_neighbours()
{
  const int me = _comm.rank();
  std::map<int, size_t> neighbour;
  for (int64_t i = 0; i < n_kept(); ++i)
    for (const int32_t s : _touch[i])
      if (_decomp.owner_rank(s) != me)
        neighbour.emplace(_decomp.owner_rank(s), 0);
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
  return neighbour;
}

void DualLayout::list_exchanges(const decomposition::ConstraintRows& rows, const std::map<int, size_t>& neighbour)
{
  const int me = _comm.rank();
  const int32_t first = _decomp.first_owned();
  const size_t n_nb = neighbour.size();
  std::vector<std::vector<std::tuple<int64_t, int32_t, int64_t>>> to_owner(n_nb);
  for (int64_t i = 0; i < n_kept(); ++i)
  {
    const int owner = _decomp.owner_rank(_touch[i].front());
    std::vector<int> others; // other ranks touching row i
    for (const int32_t s : _touch[i])
    {
      const int r = _decomp.owner_rank(s);
      if (r != me && std::find(others.begin(), others.end(), r) == others.end())
        others.push_back(r);
    }
    if (owner == me)
      for (const int r : others)
        _ghosts.send[neighbour.at(r)].push_back(_slot[i]);
    else
      _ghosts.recv[neighbour.at(owner)].push_back(_slot[i]);
    if (owner != me)
      for (const int32_t s : _touch[i])
        if (_decomp.owner_rank(s) == me)
          to_owner[neighbour.at(owner)].emplace_back(rows.id(i), s, _contribution_start[s - first] + position(i, s));
  }
  for (size_t k = 0; k < n_nb; ++k)
  {
    std::sort(to_owner[k].begin(), to_owner[k].end());
    for (const auto& [id, s, pos] : to_owner[k])
      _to_owner.send[k].push_back(pos);
  }
}

void DualLayout::list_sum_sources(const std::map<int, size_t>& neighbour)
{
  const int me = _comm.rank();
  const int32_t first = _decomp.first_owned();
  const size_t n_nb = neighbour.size();
  // Per owned row its contributions in increasing subdomain order: local positions, or the
  // next value received from the subdomain's rank.
  std::vector<int64_t> recv_count(n_nb, 0);
  _sum_start.assign(1, 0);
  std::vector<std::pair<int, int64_t>> sources; // (neighbour or -1, position)
  for (const int64_t i : _owned)
  {
    for (const int32_t s : _touch[i])
    {
      const int r = _decomp.owner_rank(s);
      if (r == me)
        sources.emplace_back(-1, _contribution_start[s - first] + position(i, s));
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

la::Vector DualLayout::owned(const la::Vector& per_row) const
{
  la::Vector out(n_dual());
  for (size_t k = 0; k < _owned.size(); ++k)
    out(static_cast<la::Index>(k)) = per_row(_owned[k]);
  return out;
}

la::Vector DualLayout::extended(const la::Vector& lambda, const std::vector<char>* mask) const
{
  FETICON_ASSERT(lambda.size() == n_dual(), "dual vector size");
  la::Vector ext(static_cast<la::Index>(_slot.size()));
  ext.head(n_dual()) = lambda;
  if (mask)
    for (la::Index i = 0; i < n_dual(); ++i)
      if (!(*mask)[i])
        ext(i) = 0.0;
  const auto received = _comm.exchange(_ghosts.ranks, pack(_ghosts.send, ext), sizes_of(_ghosts.recv));
  for (size_t k = 0; k < received.size(); ++k)
    for (size_t j = 0; j < received[k].size(); ++j)
      ext(_ghosts.recv[k][j]) = received[k][j];
  return ext;
}

la::Vector DualLayout::rows_of(int32_t s, const la::Vector& ext) const
{
  const auto& slots = _sub_slots[s - _decomp.first_owned()];
  la::Vector local(static_cast<la::Index>(slots.size()));
  for (size_t j = 0; j < slots.size(); ++j)
    local(static_cast<la::Index>(j)) = ext(slots[j]);
  return local;
}

la::Vector DualLayout::sum_contributions(const std::function<la::Vector(int32_t)>& local, int64_t work) const
{
  la::Vector contributions(_n_contributions);
  parallel_for(_decomp.first_owned(), _decomp.end_owned(), work, [&](int32_t s) {
    const int32_t l = s - _decomp.first_owned();
    if (!_sub_rows[l].empty())
      contributions.segment(_contribution_start[l], static_cast<la::Index>(_sub_rows[l].size())) = local(s);
  });
  const auto received = _comm.exchange(_to_owner.ranks, pack(_to_owner.send, contributions), sizes_of(_to_owner.recv));
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
} // namespace feticon::dual
