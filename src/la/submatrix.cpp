#include "la/submatrix.hpp"

#include "common/error.hpp"

namespace feticon::la
{
SparseMatrix principal_submatrix(const SparseMatrix& A, const std::vector<int32_t>& position, int32_t n_kept,
                                 Entries keep)
{
  FETICON_ASSERT(static_cast<Index>(position.size()) == A.rows() && A.rows() == A.cols(),
                 "position map does not match the matrix");
  std::vector<Triplet> triplets;
  triplets.reserve(A.nonZeros());
  for (int col = 0; col < A.outerSize(); ++col)
    if (position[col] >= 0)
      for (SparseMatrix::InnerIterator it(A, col); it; ++it)
        if (position[it.row()] >= 0 && (keep == Entries::all || position[it.row()] >= position[col]))
          triplets.emplace_back(position[it.row()], position[col], it.value());
  SparseMatrix out(n_kept, n_kept);
  out.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}

SparseMatrix symmetric_block(const SparseMatrix& lower, const std::vector<int32_t>& rows,
                             const std::vector<int32_t>& cols)
{
  FETICON_ASSERT(lower.rows() == lower.cols(), "symmetric_block of a non-square matrix");
  std::vector<int32_t> row_position(lower.rows(), -1), col_position(lower.cols(), -1);
  for (size_t k = 0; k < rows.size(); ++k)
    row_position[rows[k]] = static_cast<int32_t>(k);
  for (size_t k = 0; k < cols.size(); ++k)
    col_position[cols[k]] = static_cast<int32_t>(k);
  std::vector<Triplet> triplets;
  for (int j = 0; j < lower.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(lower, j); it; ++it)
    {
      const int i = static_cast<int>(it.row());
      FETICON_ASSERT(i >= j, "symmetric_block: an entry above the diagonal");
      if (row_position[i] >= 0 && col_position[j] >= 0)
        triplets.emplace_back(row_position[i], col_position[j], it.value());
      if (i != j && row_position[j] >= 0 && col_position[i] >= 0) // its mirror (j, i)
        triplets.emplace_back(row_position[j], col_position[i], it.value());
    }
  SparseMatrix out(static_cast<Index>(rows.size()), static_cast<Index>(cols.size()));
  out.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}
} // namespace feticon::la
