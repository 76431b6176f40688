#include "la/nodal_ordering.hpp"

#include "common/error.hpp"

#include <metis.h>

#include <algorithm>

namespace feticon::la
{
namespace
{
/// Consecutive columns of A with the same rows form one vertex (the DOFs of a node: three,
/// or fewer where a generalized inverse fixed some). Fills `first` (the first column of each
/// vertex, and A.cols() at the end) and the vertex graph (CSR, no self-loops) of A, a
/// symmetric pattern stored whole.
void node_graph(const SparseMatrix& A, std::vector<idx_t>& first, std::vector<idx_t>& xadj, std::vector<idx_t>& adjncy)
{
  const Index n = A.cols();
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  std::vector<idx_t> vertex(static_cast<size_t>(n));
  first.assign(1, 0);
  for (Index j = 1; j < n; ++j)
    if (!std::equal(inner + outer[j - 1], inner + outer[j], inner + outer[j], inner + outer[j + 1]))
      first.push_back(static_cast<idx_t>(j));
  first.push_back(static_cast<idx_t>(n));
  const auto vertices = static_cast<idx_t>(first.size() - 1);
  for (idx_t v = 0; v < vertices; ++v)
    std::fill(vertex.begin() + first[v], vertex.begin() + first[v + 1], v);
  xadj.assign(1, 0);
  adjncy.clear();
  adjncy.reserve(static_cast<size_t>(A.nonZeros() / 9));
  for (idx_t v = 0; v < vertices; ++v)
  {
    idx_t previous = -1;
    for (int k = outer[first[v]]; k < outer[first[v] + 1]; ++k)
    {
      const idx_t w = vertex[static_cast<size_t>(inner[k])];
      if (w != v && w != previous)
        adjncy.push_back(w);
      previous = w;
    }
    xadj.push_back(static_cast<idx_t>(adjncy.size()));
  }
}
} // namespace

std::optional<std::vector<int>> nodal_nested_dissection(const SparseMatrix& A, Index min_dofs)
{
  if (A.rows() < min_dofs || A.rows() != A.cols())
    return std::nullopt;
  // The pattern CHOLMOD factorizes: A's lower triangle, mirrored.
  const SparseMatrix symmetric = A.selfadjointView<Eigen::Lower>();
  std::vector<idx_t> first, xadj, adjncy;
  node_graph(symmetric, first, xadj, adjncy);
  if (static_cast<double>(A.rows()) < 2.5 * static_cast<double>(first.size() - 1))
    return std::nullopt;
  auto vertices = static_cast<idx_t>(first.size() - 1);
  std::vector<idx_t> perm(static_cast<size_t>(vertices)), iperm(static_cast<size_t>(vertices));
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  const int status = METIS_NodeND(&vertices, xadj.data(), adjncy.data(), nullptr, options, perm.data(), iperm.data());
  FETICON_CHECK(status == METIS_OK,
                "METIS could not order a matrix of " << A.rows() << " DOFs (status " << status << ")");
  // METIS's perm[k] is the vertex eliminated k-th; its DOFs follow one another.
  std::vector<int> dofs;
  dofs.reserve(static_cast<size_t>(A.rows()));
  for (const idx_t v : perm)
    for (idx_t j = first[v]; j < first[v + 1]; ++j)
      dofs.push_back(static_cast<int>(j));
  return dofs;
}
} // namespace feticon::la
