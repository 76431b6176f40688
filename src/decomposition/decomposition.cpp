#include "decomposition/decomposition.hpp"

#include "common/error.hpp"

namespace feticon::decomposition
{
Decomposition::Decomposition(const mesh::HexMesh& mesh, const Partition& partition,
                             std::array<bool, 3> eliminated)
    : _mesh(mesh), _partition(partition), _eliminated(eliminated)
{
  FETICON_CHECK(static_cast<int32_t>(partition.cell_subdomain.size()) == mesh.n_cells(),
                "partition has " << partition.cell_subdomain.size() << " cells, the mesh "
                                 << mesh.n_cells());
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
}

Eigen::VectorBlock<la::Vector> Decomposition::segment(la::Vector& stacked, int32_t s) const
{
  return stacked.segment(_offsets[s], _offsets[s + 1] - _offsets[s]);
}

Eigen::VectorBlock<const la::Vector> Decomposition::segment(const la::Vector& stacked,
                                                            int32_t s) const
{
  return stacked.segment(_offsets[s], _offsets[s + 1] - _offsets[s]);
}

la::Vector Decomposition::scatter_copy(const la::Vector& global) const
{
  FETICON_ASSERT(global.size() == 3 * _mesh.n_nodes(), "global vector size");
  la::Vector stacked(n_primal());
  for (const Subdomain& sub : _subdomains)
    for (int32_t k = 0; k < sub.n_dofs(); ++k)
    {
      const int32_t full = sub.full_of_active[k];
      stacked(_offsets[sub.id] + k) = global(3 * sub.domain.local_to_global[full / 3] + full % 3);
    }
  return stacked;
}

la::Vector Decomposition::scatter_split(const la::Vector& global) const
{
  la::Vector stacked = scatter_copy(global);
  for (const Subdomain& sub : _subdomains)
    for (int32_t k = 0; k < sub.n_dofs(); ++k)
    {
      const int32_t node = sub.domain.local_to_global[sub.full_of_active[k] / 3];
      stacked(_offsets[sub.id] + k) /= static_cast<double>(_copies[node].size());
    }
  return stacked;
}

la::Vector Decomposition::gather_sum(const la::Vector& stacked) const
{
  FETICON_ASSERT(stacked.size() == n_primal(), "stacked vector size");
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
