#include "decomposition/explicit_boundary_operators.hpp"

#include "common/parallel.hpp"

#include <algorithm>

namespace feticon::decomposition
{
ExplicitBoundaryOperators::ExplicitBoundaryOperators(const SubdomainSystem& system,
                                                     const SchurComplements& schur)
{
  const Decomposition& decomp = system.decomposition();
  _first = decomp.first_owned();
  _local.resize(decomp.end_owned() - decomp.first_owned());
  parallel_for(decomp.first_owned(), decomp.end_owned(), setup_work, [&](int32_t s)
  {
    Local& local = _local[s - _first];
    local.boundary = schur.boundary(s);
    const la::Index n = system.operators(s).K.rows();
    const la::Index nb = static_cast<la::Index>(local.boundary.size());
    local.K_plus.resize(nb, nb);
    // Blocks of columns, so that the right-hand sides take n x la::solve_block doubles, not n x |b_s|.
    for (la::Index j = 0; j < nb; j += la::solve_block)
    {
      const la::Index width = std::min(la::solve_block, nb - j);
      la::Matrix columns = la::Matrix::Zero(n, width);
      for (la::Index k = 0; k < width; ++k)
        columns(local.boundary[j + k], k) = 1;
      const la::Matrix X = system.operators(s).K_plus.apply(columns);
      for (la::Index k = 0; k < nb; ++k)
        local.K_plus.block(k, j, 1, width) = X.row(local.boundary[k]);
    }
    local.schur = schur.dense(s);
  });
}

int64_t ExplicitBoundaryOperators::bytes() const
{
  int64_t total = 0;
  for (const Local& local : _local)
    total += static_cast<int64_t>(sizeof(double)) * (local.K_plus.size() + local.schur.size());
  return total;
}

int64_t explicit_operator_bytes(const SubdomainSystem& system, const SchurComplements& schur)
{
  const Decomposition& decomp = system.decomposition();
  int64_t total = 0;
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
  {
    const auto nb = static_cast<int64_t>(schur.boundary(s).size());
    total += 2 * nb * nb * static_cast<int64_t>(sizeof(double));
  }
  return total;
}
} // namespace feticon::decomposition
