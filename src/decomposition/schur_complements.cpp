#include "decomposition/schur_complements.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "la/submatrix.hpp"

#include <algorithm>
#include <limits>
#include <string>

namespace feticon::decomposition
{
namespace
{
/// The interior DOFs of `sub` whose node is within `layers` cell layers of a node with a
/// boundary DOF (layer 1: sharing a cell with one).
std::vector<int32_t> band_of_interior(const Subdomain& sub, const std::vector<int32_t>& boundary,
                                      const std::vector<int32_t>& interior, int layers)
{
  constexpr int far = std::numeric_limits<int>::max() / 2;
  std::vector<int> layer(static_cast<size_t>(sub.domain.n_nodes()), far);
  for (const int32_t dof : boundary)
    layer[sub.full_of_active[dof] / 3] = 0;
  for (int sweep = 0; sweep < layers; ++sweep)
  {
    std::vector<int> next = layer;
    for (size_t c = 0; c < sub.domain.cell_nodes.size(); ++c)
    {
      int lowest = far;
      for (const int32_t n : sub.domain.cell_nodes[c])
        lowest = std::min(lowest, layer[n]);
      for (const int32_t n : sub.domain.cell_nodes[c])
        next[n] = std::min(next[n], lowest + 1);
    }
    layer = std::move(next);
  }
  std::vector<int32_t> band;
  for (const int32_t dof : interior)
    if (layer[sub.full_of_active[dof] / 3] <= layers)
      band.push_back(dof);
  return band;
}
} // namespace

SchurComplements::SchurComplements(const SubdomainSystem& system, const std::vector<char>& boundary_dof,
                                   bool factorize_interior, int interior_layers)
    : _system(system)
{
  const Decomposition& decomp = system.decomposition();
  _local.resize(decomp.end_owned() - decomp.first_owned());
  parallel_for(decomp.first_owned(), decomp.end_owned(), setup_work, [&](int32_t s) {
    const Subdomain& sub = decomp.subdomain(s);
    Local& local = _local[s - decomp.first_owned()];
    for (int32_t dof = 0; dof < sub.n_dofs(); ++dof)
    {
      const int32_t full = sub.full_of_active[dof];
      const int32_t node = sub.domain.local_to_global[full / 3];
      const bool on_boundary = boundary_dof[3 * static_cast<size_t>(node) + full % 3] || decomp.copies(node).size() > 1;
      (on_boundary ? local.boundary : local.interior).push_back(dof);
    }
    if (interior_layers > 0)
      local.interior = band_of_interior(sub, local.boundary, local.interior, interior_layers);
  });
  if (factorize_interior)
    this->factorize_interior();
}

void SchurComplements::factorize_interior()
{
  if (_factorized)
    return;
  const Decomposition& decomp = _system.decomposition();
  parallel_for(decomp.first_owned(), decomp.end_owned(), setup_work, [&](int32_t s) {
    Local& local = _local[s - decomp.first_owned()];
    const la::SparseMatrix& K = _system.operators(s).K;
    local.K_bb = la::symmetric_block(K, local.boundary, local.boundary);
    local.K_ib = la::symmetric_block(K, local.interior, local.boundary);
    if (!local.interior.empty())
    {
      std::vector<int32_t> position(K.rows(), -1);
      for (size_t k = 0; k < local.interior.size(); ++k)
        position[local.interior[k]] = static_cast<int32_t>(k);
      const std::string what = "the interior stiffness K_ii of subdomain " + std::to_string(s);
      // Interior DOFs in increasing order: the lower triangle of K_ii, which CHOLMOD reads.
      local.K_ii.factorize(la::principal_submatrix(K, position, static_cast<int32_t>(local.interior.size())),
                           what.c_str(), _system.factor_precision());
    }
  });
  _factorized = true;
}

la::Vector SchurComplements::apply(int32_t s, const la::Vector& v) const
{
  FETICON_ASSERT(_factorized, "SchurComplements::apply without the K_ii factors");
  const Local& local = this->local(s);
  la::Vector v_b(local.boundary.size());
  for (size_t k = 0; k < local.boundary.size(); ++k)
    v_b(k) = v(local.boundary[k]);
  la::Vector y_b = local.K_bb * v_b;
  if (!local.interior.empty())
    y_b -= local.K_ib.transpose() * local.K_ii.solve(la::Vector(local.K_ib * v_b));
  la::Vector y = la::Vector::Zero(v.size());
  for (size_t k = 0; k < local.boundary.size(); ++k)
    y(local.boundary[k]) = y_b(k);
  return y;
}
} // namespace feticon::decomposition
