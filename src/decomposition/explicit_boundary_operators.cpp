#include "decomposition/explicit_boundary_operators.hpp"

#include "common/parallel.hpp"
#include "la/symmetric_product.hpp"

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
    local.blocks.resize(nb, nb);
    // Blocks of columns, so that the right-hand sides take n x la::solve_block doubles, not n x |b_s|.
    for (la::Index j = 0; j < nb; j += la::solve_block)
    {
      const la::Index width = std::min(la::solve_block, nb - j);
      la::Matrix columns = la::Matrix::Zero(n, width);
      for (la::Index k = 0; k < width; ++k)
        columns(local.boundary[j + k], k) = 1;
      const la::Matrix X = system.operators(s).K_plus.apply(columns);
      for (la::Index k = 0; k < width; ++k)
        for (la::Index r = j + k; r < nb; ++r)
          local.blocks(r, j + k) = X(local.boundary[r], k);
    }
    const la::Matrix S = schur.dense(s);
    for (la::Index c = 1; c < nb; ++c)
      for (la::Index r = 0; r < c; ++r)
        local.blocks(r, c) = S(r, c);
    local.schur_minus_K_plus = S.diagonal() - local.blocks.diagonal();
  });
}

la::Vector ExplicitBoundaryOperators::apply_K_plus(int32_t s, const la::Vector& v) const
{
  la::Vector y;
  la::symmetric_product(local(s).blocks, la::Triangle::lower, v, y);
  return y;
}

la::Vector ExplicitBoundaryOperators::apply_schur(int32_t s, const la::Vector& v) const
{
  la::Vector y;
  la::symmetric_product(local(s).blocks, la::Triangle::upper, v, y);
  y += local(s).schur_minus_K_plus.cwiseProduct(v);
  return y;
}

int64_t ExplicitBoundaryOperators::bytes() const
{
  int64_t total = 0;
  for (const Local& local : _local)
    total += static_cast<int64_t>(sizeof(double)) * (local.blocks.size() + local.schur_minus_K_plus.size());
  return total;
}

int64_t explicit_operator_bytes(const SubdomainSystem& system, const SchurComplements& schur)
{
  const Decomposition& decomp = system.decomposition();
  int64_t total = 0;
  for (int32_t s = decomp.first_owned(); s < decomp.end_owned(); ++s)
  {
    const auto nb = static_cast<int64_t>(schur.boundary(s).size());
    total += (nb * nb + nb) * static_cast<int64_t>(sizeof(double));
  }
  return total;
}
} // namespace feticon::decomposition
