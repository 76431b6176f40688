#include "decomposition/decomposition.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>

namespace feticon::decomposition
{
Decomposition::Decomposition(const mesh::Mesh& mesh, const Partition& partition, std::array<bool, 3> eliminated,
                             par::Communicator comm)
    : _mesh(mesh), _partition(partition), _eliminated(eliminated), _comm(comm)
{
  FETICON_CHECK(static_cast<int32_t>(partition.cell_subdomain.size()) == mesh.n_cells(),
                "partition has " << partition.cell_subdomain.size() << " cells, the mesh " << mesh.n_cells());
  std::vector<std::vector<int32_t>> cells(partition.n_subdomains);
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    cells[partition.cell_subdomain[c]].push_back(c);
  _copies.resize(mesh.n_nodes());
  _offsets.assign(1, 0);
  for (int32_t s = 0; s < partition.n_subdomains; ++s)
  {
    FETICON_CHECK(!cells[s].empty(), "subdomain " << s << " has no cells");
    Subdomain sub;
    sub.id = s;
    sub.body = mesh.cell_body[cells[s].front()];
    for (int32_t c : cells[s])
      FETICON_CHECK(mesh.cell_body[c] == sub.body,
                    "subdomain " << s << " spans two bodies; partition each body separately");
    sub.domain = fem::make_domain(mesh, std::move(cells[s]));
    sub.active_of_full.assign(sub.domain.n_dofs(), -1);
    for (int32_t n = 0; n < sub.domain.n_nodes(); ++n)
    {
      for (int i = 0; i < 3; ++i)
        if (!eliminated[i])
        {
          sub.active_of_full[3 * n + i] = static_cast<int32_t>(sub.full_of_active.size());
          sub.full_of_active.push_back(3 * n + i);
        }
      _copies[sub.domain.local_to_global[n]].push_back({s, n});
    }
    _offsets.push_back(_offsets.back() + sub.n_dofs());
    _subdomains.push_back(std::move(sub));
  }
  // Contiguous ranges balanced by DOFs (factorization and solves scale with them): rank r
  // ends its range at the subdomain whose cumulative DOFs come closest to (r + 1) / size.
  const int n_ranks = _comm.size();
  FETICON_CHECK(n_ranks <= partition.n_subdomains,
                n_ranks << " ranks but only " << partition.n_subdomains
                        << " subdomains: use at least one subdomain per rank");
  _rank_first.assign(n_ranks + 1, 0);
  _rank_first[n_ranks] = partition.n_subdomains;
  const double total = static_cast<double>(_offsets.back());
  for (int r = 1; r < n_ranks; ++r)
  {
    const double target = total * r / n_ranks;
    int32_t end = std::max(_rank_first[r - 1] + 1, int32_t{1});
    while (end < partition.n_subdomains - (n_ranks - r) &&
           std::abs(static_cast<double>(_offsets[end + 1]) - target) <
               std::abs(static_cast<double>(_offsets[end]) - target))
      ++end;
    _rank_first[r] = end;
  }
}

int Decomposition::owner_rank(int32_t s) const
{
  return static_cast<int>(std::upper_bound(_rank_first.begin(), _rank_first.end(), s) - _rank_first.begin()) - 1;
}

la::Vector Decomposition::gather_stacked(const la::Vector& stacked) const
{
  FETICON_ASSERT(stacked.size() == n_primal(), "owned stacked vector size");
  const std::vector<double> all =
      _comm.all_gather(std::vector<double>(stacked.data(), stacked.data() + stacked.size()));
  return Eigen::Map<const la::Vector>(all.data(), static_cast<la::Index>(all.size()));
}

Eigen::VectorBlock<la::Vector> Decomposition::segment(la::Vector& stacked, int32_t s) const
{
  FETICON_ASSERT(owns(s), "segment of a subdomain owned by another rank");
  return stacked.segment(offset(s), _offsets[s + 1] - _offsets[s]);
}

Eigen::VectorBlock<const la::Vector> Decomposition::segment(const la::Vector& stacked, int32_t s) const
{
  FETICON_ASSERT(owns(s), "segment of a subdomain owned by another rank");
  return stacked.segment(offset(s), _offsets[s + 1] - _offsets[s]);
}

la::Vector Decomposition::owned_slice(const la::Vector& global_stacked) const
{
  FETICON_ASSERT(global_stacked.size() == n_primal_global(), "global stacked vector size");
  return global_stacked.segment(_offsets[first_owned()], n_primal());
}

la::Vector Decomposition::scatter_copy(const la::Vector& global) const
{
  FETICON_ASSERT(global.size() == 3 * _mesh.n_nodes(), "global vector size");
  la::Vector stacked(n_primal());
  for (int32_t s = first_owned(); s < end_owned(); ++s)
  {
    const Subdomain& sub = _subdomains[s];
    for (int32_t k = 0; k < sub.n_dofs(); ++k)
    {
      const int32_t full = sub.full_of_active[k];
      stacked(offset(s) + k) = global(3 * sub.domain.local_to_global[full / 3] + full % 3);
    }
  }
  return stacked;
}

la::Vector Decomposition::scatter_split(const la::Vector& global) const
{
  la::Vector stacked = scatter_copy(global);
  for (int32_t s = first_owned(); s < end_owned(); ++s)
  {
    const Subdomain& sub = _subdomains[s];
    for (int32_t k = 0; k < sub.n_dofs(); ++k)
    {
      const int32_t node = sub.domain.local_to_global[sub.full_of_active[k] / 3];
      stacked(offset(s) + k) /= static_cast<double>(_copies[node].size());
    }
  }
  return stacked;
}

la::Vector Decomposition::gather_sum(const la::Vector& stacked) const
{
  FETICON_ASSERT(stacked.size() == n_primal_global(), "global stacked vector size");
  la::Vector global = la::Vector::Zero(3 * _mesh.n_nodes());
  for (const Subdomain& sub : _subdomains)
    for (int32_t k = 0; k < sub.n_dofs(); ++k)
    {
      const int32_t full = sub.full_of_active[k];
      global(3 * sub.domain.local_to_global[full / 3] + full % 3) += stacked(_offsets[sub.id] + k);
    }
  return global;
}

la::Vector Decomposition::gather_mean(const la::Vector& stacked) const
{
  la::Vector global = gather_sum(stacked);
  for (int32_t node = 0; node < _mesh.n_nodes(); ++node)
    if (!_copies[node].empty())
      global.segment<3>(3 * node) /= static_cast<double>(_copies[node].size());
  return global;
}
} // namespace feticon::decomposition
