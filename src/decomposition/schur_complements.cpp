#include "decomposition/schur_complements.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "la/submatrix.hpp"

#include <string>

namespace feticon::decomposition
{
SchurComplements::SchurComplements(const SubdomainSystem& system, const std::vector<char>& boundary_dof,
                                   bool factorize_interior)
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
                           what.c_str());
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
