#include "decomposition/schur_complements.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "la/submatrix.hpp"

#include <string>

namespace feticon::decomposition
{
namespace
{
/// Rows `rows` and columns `cols` of A (both increasing index lists).
la::SparseMatrix block(const la::SparseMatrix& A, const std::vector<int32_t>& rows,
                       const std::vector<int32_t>& cols)
{
  std::vector<int32_t> row_position(A.rows(), -1), col_position(A.cols(), -1);
  for (size_t k = 0; k < rows.size(); ++k)
    row_position[rows[k]] = static_cast<int32_t>(k);
  for (size_t k = 0; k < cols.size(); ++k)
    col_position[cols[k]] = static_cast<int32_t>(k);
  std::vector<la::Triplet> triplets;
  for (int j = 0; j < A.outerSize(); ++j)
    if (col_position[j] >= 0)
      for (la::SparseMatrix::InnerIterator it(A, j); it; ++it)
        if (row_position[it.row()] >= 0)
          triplets.emplace_back(row_position[it.row()], col_position[j], it.value());
  la::SparseMatrix out(static_cast<la::Index>(rows.size()), static_cast<la::Index>(cols.size()));
  out.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}
} // namespace

SchurComplements::SchurComplements(const SubdomainSystem& system, const std::vector<char>& boundary_node,
                                   bool factorize_interior)
    : _system(system)
{
  const Decomposition& decomp = system.decomposition();
  _local.resize(decomp.end_owned() - decomp.first_owned());
  parallel_for(decomp.first_owned(), decomp.end_owned(), setup_work, [&](int32_t s)
  {
    const Subdomain& sub = decomp.subdomain(s);
    Local& local = _local[s - decomp.first_owned()];
    for (int32_t dof = 0; dof < sub.n_dofs(); ++dof)
    {
      const int32_t node = sub.domain.local_to_global[sub.full_of_active[dof] / 3];
      const bool on_boundary = boundary_node[node] || decomp.copies(node).size() > 1;
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
  parallel_for(decomp.first_owned(), decomp.end_owned(), setup_work, [&](int32_t s)
  {
    Local& local = _local[s - decomp.first_owned()];
    const la::SparseMatrix& K = _system.operators(s).K;
    local.K_bb = block(K, local.boundary, local.boundary);
    local.K_ib = block(K, local.interior, local.boundary);
    if (!local.interior.empty())
    {
      std::vector<int32_t> position(K.rows(), -1);
      for (size_t k = 0; k < local.interior.size(); ++k)
        position[local.interior[k]] = static_cast<int32_t>(k);
      const std::string what = "the interior stiffness K_ii of subdomain " + std::to_string(s);
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
